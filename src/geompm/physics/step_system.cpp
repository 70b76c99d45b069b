#include "geompm/physics/step_system.hpp"

#include <algorithm>

#include "geompm/core/agreement.hpp"

namespace geompm {

StepSystem::StepSystem(const GridSystem& grid)
    : dofs_(grid.active_nodes()), communicator_(grid.communicator()) {
  dofs_.add_nodal_field("displacement", FieldKind::Displacement, grid.dim());
  if (grid.mixed()) dofs_.add_nodal_field("pressure", FieldKind::Pressure, 1);
}

void StepSystem::build_pattern() {
  dofs_.number_free();
  SparsityBuilder pattern(dofs_);
  for (const auto& c : contributions_) c->declare_couplings(pattern);
  SparseMatrix built = pattern.build();
  tangent_.swap(built);  // Eigen's assignment would copy every entry
  for (const auto& c : contributions_) c->attach(tangent_);
}

bool StepSystem::evaluate(const Vector& du, SystemForces& forces, bool with_tangent) {
  forces.reset(dofs_.size());
  if (with_tangent) std::fill(tangent_.valuePtr(), tangent_.valuePtr() + tangent_.nonZeros(), 0.0);
  const bool distributed = communicator_.distributed();
  const auto add_all = [&] {
    inject_test_fault(communicator_, "step");
    for (const auto& c : contributions_) {
      if (distributed && communicator_.rank() != 0 && !c->sums_own_points()) continue;
      if (!c->add(du, forces, with_tangent ? &tangent_ : nullptr)) return false;
    }
    return true;
  };
  if (!distributed) return add_all();
  // Whether every process's points were admissible, or what went wrong on one (a stress update
  // that threw, a non-finite value): one reduction, so that no process is left waiting at the
  // sums below for one that has stopped.
  if (!together_all(communicator_, add_all)) return false;
  // Every process's share of the forces, summed; the tangent stays this process's share, which
  // the distributed linear solver assembles.
  for (Vector* v : {&forces.internal, &forces.inertia, &forces.external})
    communicator_.sum(v->data(), static_cast<std::size_t>(v->size()));
  return true;
}

void StepSystem::report(const Vector& du, Reactions& reactions) {
  for (const auto& c : contributions_) c->report(du, reactions);
  // The point sets' reactions are sums over the points (the same sets on every process).
  if (communicator_.distributed())
    for (auto& [set, force] : reactions.point_sets) communicator_.sum(force.data(), 3);
}

void StepSystem::commit() {
  for (const auto& c : contributions_) c->commit();
}

}  // namespace geompm

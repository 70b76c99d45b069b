#include "geompm/physics/step_system.hpp"

#include <algorithm>

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
  bool admissible = true;
  for (const auto& c : contributions_) {
    if (distributed && communicator_.rank() != 0 && !c->sums_own_points()) continue;
    if (!c->add(du, forces, with_tangent ? &tangent_ : nullptr)) {
      admissible = false;
      break;
    }
  }
  if (!distributed) return admissible;
  // Every process's share of the forces, summed; the tangent stays this process's share, which
  // the distributed linear solver assembles.
  if (!communicator_.all(admissible)) return false;
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

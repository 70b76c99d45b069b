#include "geompm/physics/step_system.hpp"

#include <algorithm>

namespace geompm {

StepSystem::StepSystem(const GridSystem& grid) : dofs_(grid.active_nodes()) {
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
  for (const auto& c : contributions_)
    if (!c->add(du, forces, with_tangent ? &tangent_ : nullptr)) return false;
  return true;
}

void StepSystem::report(const Vector& du, Reactions& reactions) {
  for (const auto& c : contributions_) c->report(du, reactions);
}

void StepSystem::commit() {
  for (const auto& c : contributions_) c->commit();
}

}  // namespace geompm

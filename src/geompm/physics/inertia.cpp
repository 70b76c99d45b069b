#include "geompm/physics/inertia.hpp"

namespace geompm {

Vector displacement_block(const DofMap& dofs, const Vector& all) {
  const Field& u = dofs.field(dofs.find("displacement"));
  return all.segment(u.offset, std::size_t(u.entities) * u.components);
}

Vector from_displacement_block(const DofMap& dofs, const Vector& nodal) {
  Vector all = Vector::Zero(dofs.size());
  const Field& u = dofs.field(dofs.find("displacement"));
  all.segment(u.offset, std::size_t(u.entities) * u.components) = nodal;
  return all;
}

Inertia::Inertia(const GridSystem& grid, const DofMap& dofs, const Newmark& newmark)
    : dofs_(dofs), newmark_(newmark), declares_diagonal_(grid.communicator().distributed()) {
  const int u = dofs.find("displacement");
  mass_ = Vector::Zero(dofs.size());
  for (Index a = 0; a < static_cast<Index>(grid.active_nodes().size()); ++a)
    for (int i = 0; i < grid.dim(); ++i) mass_(dofs.dof(u, a, i)) = grid.nodal_mass()(a);
  velocity_ = from_displacement_block(dofs, grid.nodal_velocity());
  acceleration_ = from_displacement_block(dofs, grid.nodal_acceleration());
}

void Inertia::declare_couplings(SparsityBuilder& pattern) const {
  // In a serial run the cells' couplings hold every diagonal entry already.
  if (!declares_diagonal_) return;
  const Field& u = dofs_.field(dofs_.find("displacement"));
  for (Index d = u.offset; d < u.offset + u.entities * u.components; ++d) {
    const Index unknown[] = {d};
    pattern.couple_unknowns(unknown);
  }
}

void Inertia::attach(const SparseMatrix& pattern) {
  diagonal_.assign(pattern.cols(), -1);
  for (Index j = 0; j < pattern.cols(); ++j)
    for (int at = pattern.outerIndexPtr()[j]; at < pattern.outerIndexPtr()[j + 1]; ++at)
      if (pattern.innerIndexPtr()[at] == j) diagonal_[j] = at;
}

bool Inertia::add(const Vector& du, SystemForces& forces, SparseMatrix* tangent) {
  forces.inertia +=
      mass_.cwiseProduct(newmark_.inertial_acceleration(du, velocity_, acceleration_));
  if (!tangent) return true;
  double* values = tangent->valuePtr();
  for (Index k = 0; k < dofs_.num_free(); ++k)
    values[diagonal_[k]] += newmark_.mass_factor() * mass_(dofs_.dof_of_free(k));
  return true;
}

void Inertia::start_in_balance(const SystemForces& at_start) {
  // Without it the first step takes a0 = 0 where the loads ask for f / m: under suddenly
  // applied gravity an error of g dt / 2 in every later velocity, which no step corrects.
  // A constrained unknown's out-of-balance force is its support's reaction: it stays at rest.
  for (Index k = 0; k < mass_.size(); ++k)
    acceleration_(k) = mass_(k) > 0.0 && !dofs_.constrained(k)
                           ? (at_start.external(k) - at_start.internal(k)) / mass_(k)
                           : 0.0;
}

double Inertia::momentum_rate() const { return mass_.cwiseProduct(velocity_).norm() / newmark_.dt; }

Vector Inertia::acceleration(const Vector& du) const {
  return newmark_.acceleration(du, velocity_, acceleration_);
}

Vector Inertia::velocity(const Vector& acceleration) const {
  return newmark_.velocity(velocity_, acceleration_, acceleration);
}

}  // namespace geompm

#include "geompm/structures/rigid_structure_term.hpp"

namespace geompm {

RigidStructureTerm::RigidStructureTerm(RigidStructure& structure, const DofMap& dofs,
                                       const Vec3& gravity, const std::vector<double>& load,
                                       std::optional<Newmark> newmark, double dt)
    : structure_(structure), dofs_(dofs), newmark_(newmark), dt_(dt) {
  for (int k = 0; k < structure.components(); ++k) dofs_of_.push_back(structure.dof(dofs, k));
  // Self-weight at the centre of mass (eq. 17.7) and the drive's force and moment.
  applied_ = structure.generalised_force(structure.mass() * gravity) +
             Eigen::Map<const Vector>(load.data(), static_cast<Index>(load.size()));
  if (newmark_) mass_ = structure.mass_matrix();
}

void RigidStructureTerm::declare_couplings(SparsityBuilder& pattern) const {
  pattern.couple_unknowns(dofs_of_);
}

Vector RigidStructureTerm::unknowns(const Vector& du) const {
  Vector q(dofs_of_.size());
  for (std::size_t k = 0; k < dofs_of_.size(); ++k) q(k) = du(dofs_of_[k]);
  return q;
}

bool RigidStructureTerm::add(const Vector& du, SystemForces& forces, SparseMatrix* tangent) {
  for (std::size_t k = 0; k < dofs_of_.size(); ++k) forces.external(dofs_of_[k]) += applied_(k);
  if (!newmark_) return true;
  // Inertia with Newmark's acceleration of the unknowns (eq. 17.9, seed eq. 8), M / (beta dt^2) on
  // the tangent.
  const Vector a = newmark_->inertial_acceleration(unknowns(du), structure_.velocity(),
                                                   structure_.acceleration());
  const Vector inertia = mass_ * a;
  for (std::size_t k = 0; k < dofs_of_.size(); ++k) forces.inertia(dofs_of_[k]) += inertia(k);
  if (tangent)
    for (std::size_t i = 0; i < dofs_of_.size(); ++i)
      for (std::size_t j = 0; j < dofs_of_.size(); ++j)
        if (mass_(i, j) != 0.0)
          add_to_tangent(*tangent, dofs_, dofs_of_[i], dofs_of_[j],
                         newmark_->mass_factor() * mass_(i, j));
  return true;
}

void RigidStructureTerm::report(const Vector& du, Reactions& /*reactions*/) {
  converged_ = du;
  reported_ = true;
}

void RigidStructureTerm::commit() {
  if (!reported_) return;
  const Vector q = unknowns(converged_);
  if (newmark_) {
    Vector a = newmark_->acceleration(q, structure_.velocity(), structure_.acceleration());
    Vector v = newmark_->velocity(structure_.velocity(), structure_.acceleration(), a);
    structure_.set_rates(std::move(v), std::move(a));
  } else {
    structure_.set_rates(q / dt_, Vector::Zero(q.size()));
  }
  structure_.commit(dofs_, converged_);
}

DriveForces drive_forces(const RigidStructure& structure, const StructureDrive& drive,
                         const DofMap& dofs, const Vector& reaction, double t) {
  const std::vector<double> load = drive.load(t);
  Vector q(structure.components());
  for (int k = 0; k < structure.components(); ++k) {
    const Index d = structure.dof(dofs, k);
    q(k) = dofs.constrained(d) ? reaction(d) : load[k];
  }
  // Axisymmetry holds the radial motion and the rotation by symmetry, not by a drive: the net
  // radial force of a body of revolution is zero, whatever its per-radian share at x.
  if (structure.kinematics() == Kinematics::Axisymmetric) q(0) = q(2) = 0.0;
  DriveForces f;
  if (structure.components() == 3) {
    f.force = Vec3(q(0), q(1), 0.0);
    f.moment = Vec3(0.0, 0.0, q(2));
  } else {
    f.force = q.head<3>();
    f.moment = q.tail<3>();
  }
  return f;
}

}  // namespace geompm

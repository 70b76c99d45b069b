// The inertia of the grid's lumped mass in a dynamic step (seed eqs. 8 and 11): M a with the
// step's acceleration from Newmark, and M / (beta dt^2) on the tangent's diagonal.
#pragma once

#include <vector>

#include "geompm/physics/contribution.hpp"
#include "geompm/physics/grid_system.hpp"
#include "geompm/physics/newmark.hpp"

namespace geompm {

class Inertia final : public Contribution {
 public:
  Inertia(const GridSystem& grid, const DofMap& dofs, const Newmark& newmark);
  const char* name() const override { return "inertia"; }
  void declare_couplings(SparsityBuilder& pattern) const override;
  void attach(const SparseMatrix& pattern) override;
  bool add(const Vector& du, SystemForces& forces, SparseMatrix* tangent) override;

  /// |M v0| / dt: the momentum rate of the grid's motion at the start of the step, the force
  /// scale of a body that moves freely without loads.
  double momentum_rate() const;
  /// A dynamic phase that starts from rest (or from a quasi-static phase, whose points carry no
  /// acceleration): the start acceleration is the one in balance with the forces at the start,
  /// M a0 = f_ext - f_int (docs/theory.md §4.7, eq. 4.7e), at every unknown with mass; the forces
  /// are those of the contributions at a zero increment, inertia left out.
  void start_in_balance(const SystemForces& at_start);
  /// The acceleration and velocity at the end of the step (per unknown) for the increment du.
  Vector acceleration(const Vector& du) const;
  Vector velocity(const Vector& acceleration) const;

 private:
  const DofMap& dofs_;
  Newmark newmark_;
  Vector mass_, velocity_, acceleration_;  // per unknown: the displacement field's, else 0
  std::vector<int> diagonal_;              // per free unknown: its diagonal entry
  // Distributed: the diagonal is declared, as this process's cells may not reach every node.
  bool declares_diagonal_ = false;
};

/// The step's unknowns of the displacement field (dim per active node) from a nodal vector, and
/// back: the displacement field's block.
Vector displacement_block(const DofMap& dofs, const Vector& all);
Vector from_displacement_block(const DofMap& dofs, const Vector& nodal);

}  // namespace geompm

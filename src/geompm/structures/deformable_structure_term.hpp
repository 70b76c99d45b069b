// A deformable structure's own terms in a step (docs/theory.md §17.7-17.9): the internal force
// and consistent tangent of its Gauss points with the same finite-strain kinematics and material
// models as the soil's points (physics/point_kernel.hpp; updated Lagrangian on the mesh at the
// start of the step), its self-weight under the phase's gravity and the nodal forces of its drive
// (f_ext), and in a dynamic phase its inertia M a with the consistent mass matrix and the phase's
// Newmark. At the converged step it keeps the Gauss points' states and the nodes' rates and moves
// the mesh. Whatever touches the structure (contact) is a contribution of its own.
#pragma once

#include <optional>

#include "geompm/physics/contribution.hpp"
#include "geompm/physics/newmark.hpp"
#include "geompm/structures/deformable_structure.hpp"
#include "geompm/structures/rigid_structure_term.hpp"
#include "geompm/structures/structure_drive.hpp"

namespace geompm {

class DeformableStructureTerm final : public Contribution {
 public:
  /// `gravity` at the end of the step; `load` the drive's nodal forces there (node-major, as
  /// StructureDrive::nodal_load); `newmark` in a dynamic phase, else the step's length for the
  /// velocity du / dt.
  DeformableStructureTerm(DeformableStructure& structure, const DofMap& dofs, const Vec3& gravity,
                          Vector load, std::optional<Newmark> newmark, double dt);
  const char* name() const override { return "deformable structure"; }
  void declare_couplings(SparsityBuilder& pattern) const override;
  bool add(const Vector& du, SystemForces& forces, SparseMatrix* tangent) override;
  void report(const Vector& du, Reactions& reactions) override;
  void commit() override;

  /// The Gauss points' states at the increment du (every unknown of the step); false where a
  /// point's deformation is inadmissible or its material's update failed.
  bool states_at(const Vector& du, std::vector<GaussPointState>& states) const;

 private:
  // Adds the cells' internal forces (and tangent) at du; fills `states` if given.
  bool add_cells(const Vector& du, SystemForces* forces, SparseMatrix* tangent,
                 std::vector<GaussPointState>* states) const;
  void add_inertia(const Vector& u, SystemForces& forces, SparseMatrix* tangent) const;

  DeformableStructure& structure_;
  const DofMap& dofs_;
  std::vector<Index> cell_dofs_;  // per cell: its nodes' unknowns, node-major
  int cell_size_ = 0;             // unknowns per cell
  Vector applied_;                // self-weight and drive loads, node-major
  std::optional<Newmark> newmark_;
  double dt_;
  // The consistent mass matrix per cell, M_ab = sum_q m_q N_a N_b (eq. 17.14), nodes x nodes.
  std::vector<Eigen::MatrixXd> cell_mass_;
  Vector converged_;
  bool reported_ = false;
};

/// What a deformable structure's drive exerts on it at a converged step (histories): the sum over
/// its nodes of the step's reaction at their prescribed components (f_int + M a - f_ext, eq.
/// 17.5) and the drive's force at their free ones, and its moment about the origin (about z in
/// 2D). In axisymmetry only the axial force (the radial ones of a body of revolution cancel).
DriveForces drive_forces(const DeformableStructure& structure, const StructureDrive& drive,
                         const DofMap& dofs, const Vector& reaction, double t);

}  // namespace geompm

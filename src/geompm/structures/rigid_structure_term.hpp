// A rigid structure's own terms in a step (docs/theory.md §17.5): its self-weight m g at
// the centre of mass and the force and moment its drive applies (f_ext, as generalised forces on
// its unknowns), and in a dynamic phase its inertia M a with the phase's Newmark (M its mass
// matrix, eq. 17.8). At the converged step it moves the structure to its new pose and keeps its
// velocity and acceleration for the next step. Whatever touches the structure (contact) is a
// contribution of its own.
#pragma once

#include <optional>

#include "geompm/physics/contribution.hpp"
#include "geompm/physics/newmark.hpp"
#include "geompm/structures/rigid_structure.hpp"
#include "geompm/structures/structure_drive.hpp"

namespace geompm {

class RigidStructureTerm final : public Contribution {
 public:
  /// `gravity` and `load` (per unknown, StructureDrive::load) at the end of the step; `newmark`
  /// in a dynamic phase, else the step's length for the velocity du / dt.
  RigidStructureTerm(RigidStructure& structure, const DofMap& dofs, const Vec3& gravity,
                     const std::vector<double>& load, std::optional<Newmark> newmark, double dt);
  const char* name() const override { return "rigid structure"; }
  void declare_couplings(SparsityBuilder& pattern) const override;
  bool add(const Vector& du, SystemForces& forces, SparseMatrix* tangent) override;
  void report(const Vector& du, Reactions& reactions) override;
  void commit() override;

  /// The generalised force it applies (self-weight and load), per unknown of the structure.
  const Vector& applied() const { return applied_; }

 private:
  Vector unknowns(const Vector& du) const;

  RigidStructure& structure_;
  const DofMap& dofs_;
  std::vector<Index> dofs_of_;  // its unknowns in the step
  Vector applied_;
  std::optional<Newmark> newmark_;
  double dt_;
  Eigen::MatrixXd mass_;
  Vector converged_;  // du at the converged increment (report), committed by commit()
  bool reported_ = false;
};

/// What a structure's drive exerts on it at a converged step (histories): at its prescribed
/// unknowns the step's reaction there (f_int + M a - f_ext: the force that holds the motion,
/// self-weight included), at its free ones the force or moment applied. As force and moment
/// about the reference point (x, y, z; the moment about z in 2D).
struct DriveForces {
  Vec3 force = Vec3::Zero();
  Vec3 moment = Vec3::Zero();
};
DriveForces drive_forces(const RigidStructure& structure, const StructureDrive& drive,
                         const DofMap& dofs, const Vector& reaction, double t);

}  // namespace geompm

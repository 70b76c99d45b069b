// A rigid structure (docs/theory.md §17): its mesh moves as one rigid body. Its unknowns in a
// step are the translation t of its reference point c and a rotation theta about it (3 in 2D:
// ux, uy, rotation about z; 6 in 3D); within the step the displacement of its point x is linear
// in them, u(x) = t + theta x (x - c) (eq. 17.1, the rotation infinitesimal), and once the step
// has converged the pose is updated exactly, with the rotation matrix exp(theta) (eq. 17.3). In
// axisymmetry it is a body of revolution about the axis and only its axial translation moves.
#pragma once

#include <optional>

#include "geompm/structures/mass_properties.hpp"
#include "geompm/structures/structure.hpp"

namespace geompm {

class RigidStructure final : public Structure {
 public:
  /// `density` per unit volume; the reference point by default its centre of mass.
  RigidStructure(std::string name, StructureMesh mesh, double density,
                 std::optional<Vec3> reference_point = std::nullopt);

  bool rigid() const override { return true; }
  int add_unknowns(DofMap& dofs) const override;
  void displacement_weights(const DofMap& dofs, const Vec3& x, Index cell,
                            std::vector<DofWeight>& out) const override;
  void commit(const DofMap& dofs, const Vector& du) override;
  void start_phase() override;
  void save(ByteWriter& out) const override;
  void load(ByteReader& in) override;

  Kinematics kinematics() const { return mesh().kinematics(); }
  /// Its unknowns: 3 (2D) or 6 (3D).
  int components() const { return components_; }
  /// The step's unknown of component k (its field must be in `dofs`).
  Index dof(const DofMap& dofs, int k) const;

  /// Per unit thickness (plane strain), per radian (axisymmetry) or of the whole body (3D).
  double mass() const { return body_.mass; }
  /// The centre of mass, the reference point and the inertia about the centre of mass, in the
  /// current configuration.
  const Vec3& centre_of_mass() const { return body_.centroid; }
  const Vec3& reference_point() const { return reference_; }
  Mat3 inertia() const { return rotation_ * body_.inertia * rotation_.transpose(); }
  /// The mass matrix of its unknowns (eq. 17.8): m on the translations, m (theta x s) coupling
  /// them with the rotations (s = centre of mass - reference point) and J about the reference
  /// point on the rotations.
  Eigen::MatrixXd mass_matrix() const;
  /// The generalised force of a force F at the centre of mass and of a moment M (eq. 17.7):
  /// F on the translations, M + s x F on the rotations.
  Vector generalised_force(const Vec3& force, const Vec3& moment = Vec3::Zero()) const;

  /// Since the start of the analysis and of the phase: the reference point's displacement, and
  /// the rotation (about x, y, z; the angle about z in 2D, summed; in 3D the rotation vector of
  /// the rotation matrix).
  Vec3 displacement() const { return reference_ - initial_reference_; }
  Vec3 rotation() const;
  Vec3 phase_displacement() const { return reference_ - phase_reference_; }
  Vec3 phase_rotation() const;

  /// Velocity and acceleration of its unknowns at the end of the last step (Newmark's start).
  const Vector& velocity() const { return velocity_; }
  const Vector& acceleration() const { return acceleration_; }
  void set_rates(Vector velocity, Vector acceleration);

 private:
  /// Translation and rotation vector of the unknowns q (3D vectors, z = 0 in 2D).
  void split(const Vector& q, Vec3& translation, Vec3& theta) const;

  int components_ = 3;
  MassProperties body_;  // centroid current; inertia about it in the initial orientation
  Vec3 reference_ = Vec3::Zero(), initial_reference_ = Vec3::Zero(),
       phase_reference_ = Vec3::Zero();
  Mat3 rotation_ = Mat3::Identity(), phase_rotation_ = Mat3::Identity();
  double angle_ = 0.0, phase_angle_ = 0.0;  // about z (2D), summed exactly
  Vector velocity_, acceleration_;
};

/// The rotation matrix of the rotation vector theta (Rodrigues; the identity for theta = 0).
Mat3 rotation_matrix(const Vec3& theta);

}  // namespace geompm

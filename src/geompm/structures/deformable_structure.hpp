// A deformable structure (docs/theory.md §17.7): its mesh is a finite-element body of its own,
// updated Lagrangian. Its unknowns in a step are the displacement increments of its nodes (dim per
// node, the field "structure:<name>"); within the step the displacement of any of its points is
// interpolated by the shape functions of the cell it lies in, u(x) = sum_a N_a(xi(x)) du_a (eq.
// 17.11), which is all contact needs. Each Gauss point carries from step to step what a material
// point carries (F, b_e, the material's internal variables, the stress), and the mesh moves with
// the converged increment: the configuration at the start of the step is the reference of the
// next, never reset.
#pragma once

#include <vector>

#include "geompm/materials/material.hpp"
#include "geompm/structures/structure.hpp"

namespace geompm {

/// What a Gauss point of a deformable structure carries from step to step.
struct GaussPointState {
  Mat3 F = Mat3::Identity();   // deformation gradient since the start of the analysis
  Mat3 be = Mat3::Identity();  // elastic left Cauchy-Green tensor
  InternalVariables internal{};
  Mat3 stress = Mat3::Zero();  // Cauchy stress
};

class DeformableStructure final : public Structure {
 public:
  /// `material` outlives the structure (the model's); `density` per unit volume of the initial
  /// configuration.
  DeformableStructure(std::string name, StructureMesh mesh, const Material& material,
                      double density);

  bool rigid() const override { return false; }
  int add_unknowns(DofMap& dofs) const override;
  void displacement_weights(const DofMap& dofs, const Vec3& x, Index cell,
                            std::vector<DofWeight>& out) const override;
  /// Moves the nodes by the converged increment; the Gauss points' states must have been set for
  /// it first (set_gauss_points, by the structure's term).
  void commit(const DofMap& dofs, const Vector& du) override;
  void start_phase() override;
  void save(ByteWriter& out) const override;
  void load(ByteReader& in) override;

  Kinematics kinematics() const { return mesh().kinematics(); }
  int dim() const { return mesh().dim(); }
  Index num_nodes() const { return static_cast<Index>(mesh().nodes().size()); }
  /// The step's unknown of component i of node a (its field must be in `dofs`).
  Index dof(const DofMap& dofs, Index node, int i) const;
  /// The structure's increment in `du` (every unknown of the step) as one vector, node-major.
  Vector nodal(const DofMap& dofs, const Vector& du) const;

  const Material& material() const { return material_; }
  double density() const { return density_; }
  /// Gauss points per cell (the cell's rule, exact for its mass matrix); point q of cell c is
  /// entry c * gauss_points_per_cell() + q.
  int gauss_points_per_cell() const { return points_per_cell_; }
  const std::vector<GaussPointState>& gauss_points() const { return gauss_; }
  void set_gauss_points(std::vector<GaussPointState> states) { gauss_ = std::move(states); }
  /// Each Gauss point's mass, rho_0 w det J_0 (r_0 in axisymmetry): constant (eq. 17.13).
  const std::vector<double>& gauss_mass() const { return gauss_mass_; }
  /// The total mass (per unit thickness, per radian or of the body).
  double mass() const;
  /// The volume-weighted mean Cauchy stress of each cell in the current configuration.
  std::vector<Mat3> cell_stress() const;

  /// The nodes' displacement since the start of the analysis or of the phase.
  Vec3 displacement(Index node) const { return mesh().nodes()[node] - initial_nodes()[node]; }
  Vec3 phase_displacement(Index node) const { return mesh().nodes()[node] - phase_nodes_[node]; }

  /// Velocity and acceleration of its nodes at the end of the last step (Newmark's start),
  /// node-major like nodal().
  const Vector& velocity() const { return velocity_; }
  const Vector& acceleration() const { return acceleration_; }
  void set_rates(Vector velocity, Vector acceleration);

 private:
  const Material& material_;
  double density_;
  int points_per_cell_ = 0;
  std::vector<GaussPointState> gauss_;
  std::vector<double> gauss_mass_;
  std::vector<Vec3> phase_nodes_;
  Vector velocity_, acceleration_;
};

}  // namespace geompm

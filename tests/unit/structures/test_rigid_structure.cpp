// A rigid structure (structures/rigid_structure, docs/theory.md §17): its unknowns' weights are
// the rigid motion linearised in the rotation (eq. 17.1), the converged pose is the exact one
// (eq. 17.3), its mass matrix and generalised forces are those of the closed forms (eqs. 17.7,
// 17.8), and its own term in a step lets it fall freely under gravity exactly as Newmark's
// trapezoidal rule integrates a constant acceleration, or hang on a spring, with the drive's
// reaction where it is held.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>

#include "geompm/core/byte_archive.hpp"
#include "geompm/dofs/sparsity.hpp"
#include "geompm/structures/rigid_structure.hpp"
#include "geompm/structures/rigid_structure_term.hpp"
#include "geompm/structures/structure_drive.hpp"

namespace geompm {
namespace {

constexpr double pi = std::numbers::pi;

// The rectangle [0, 2] x [0, 1] (2D) or the box [0, 2] x [0, 1] x [0, 3] (3D), one cell.
StructureMesh block(Kinematics k) {
  Mesh m;
  if (k == Kinematics::ThreeD) {
    m.cell_type = CellType::Hex8;
    m.nodes = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 1, 0), Vec3(0, 1, 0),
               Vec3(0, 0, 3), Vec3(2, 0, 3), Vec3(2, 1, 3), Vec3(0, 1, 3)};
    m.connectivity = {0, 1, 2, 3, 4, 5, 6, 7};
  } else {
    m.cell_type = CellType::Quad4;
    m.nodes = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 1, 0), Vec3(0, 1, 0)};
    m.connectivity = {0, 1, 2, 3};
  }
  return StructureMesh(std::move(m), k);
}

TEST(RigidStructure, WeighsItsUnknownsAsTheLinearisedRigidMotionAndMovesExactly) {
  RigidStructure s("block", block(Kinematics::PlaneStrain), 1.0, Vec3(0, 0, 0));
  DofMap dofs;
  s.add_unknowns(dofs);
  ASSERT_EQ(dofs.size(), 3);
  const double theta = 1e-3;
  Vector du(3);
  du << 0.1, -0.2, theta;
  const std::vector<Vec3> before = s.mesh().nodes();
  std::vector<DofWeight> weights;
  std::vector<Vec3> linear;
  for (const Vec3& x : before) {
    s.displacement_weights(dofs, x, 0, weights);
    Vec3 u = Vec3::Zero();
    for (const DofWeight& w : weights) u += w.coefficient * du(w.dof);
    linear.push_back(u);
  }
  s.commit(dofs, du);
  for (std::size_t a = 0; a < before.size(); ++a) {
    // Exactly: x' = t + R x about the reference point at the origin.
    const Vec3 x = before[a];
    const Vec3 exact(0.1 + std::cos(theta) * x.x() - std::sin(theta) * x.y(),
                     -0.2 + std::sin(theta) * x.x() + std::cos(theta) * x.y(), 0);
    EXPECT_NEAR((s.mesh().nodes()[a] - exact).norm(), 0.0, 1e-15);
    // The linearised motion differs by the second-order term theta^2 |x| / 2.
    const double gap = (s.mesh().nodes()[a] - x - linear[a]).norm();
    EXPECT_NEAR(gap, 0.5 * theta * theta * x.norm(), 1e-12);
  }
  EXPECT_NEAR((s.displacement() - Vec3(0.1, -0.2, 0)).norm(), 0, 1e-15);
  EXPECT_DOUBLE_EQ(s.rotation().z(), theta);
  // A quarter turn in one step lands exactly; the rotations add up.
  s.start_phase();
  du << 0, 0, 0.5 * pi;
  s.commit(dofs, du);
  EXPECT_DOUBLE_EQ(s.phase_rotation().z(), 0.5 * pi);
  EXPECT_DOUBLE_EQ(s.rotation().z(), theta + 0.5 * pi);
  EXPECT_TRUE(s.phase_displacement().isZero());
  // The surface turned with it: the bottom facet's normal (0, -1) is now along the turn.
  const Vec3 n = s.mesh().surface().front().normal;
  EXPECT_NEAR(n.norm(), 1.0, 1e-14);
}

TEST(RigidStructure, WeighsItsSixUnknownsIn3DAsTheRotationVector) {
  RigidStructure s("box", block(Kinematics::ThreeD), 1.0, Vec3(1, 0.5, 0));
  DofMap dofs;
  s.add_unknowns(dofs);
  ASSERT_EQ(dofs.size(), 6);
  Vector du(6);
  du << 0.01, -0.02, 0.03, 2e-4, -3e-4, 5e-4;
  const double theta = du.tail<3>().norm();
  const std::vector<Vec3> before = s.mesh().nodes();
  std::vector<Vec3> linear;
  std::vector<DofWeight> weights;
  for (const Vec3& x : before) {
    s.displacement_weights(dofs, x, 0, weights);
    ASSERT_EQ(weights.size(), 6u);
    Vec3 u = Vec3::Zero();
    for (const DofWeight& w : weights) u += w.coefficient * du(w.dof);
    linear.push_back(u);
    // The rotations' weights are e_j x (x - c): u = t + theta x (x - c).
    const Vec3 expected = du.head<3>() + Vec3(du.tail<3>()).cross(x - Vec3(1, 0.5, 0));
    EXPECT_NEAR((u - expected).norm(), 0.0, 1e-16);
  }
  s.commit(dofs, du);
  for (std::size_t a = 0; a < before.size(); ++a) {
    // The exact pose differs from the linearised one by at most theta^2 |x - c| / 2.
    const double gap = (s.mesh().nodes()[a] - before[a] - linear[a]).norm();
    EXPECT_LE(gap, 0.5 * theta * theta * (before[a] - Vec3(1, 0.5, 0)).norm() * (1 + 1e-6));
    EXPECT_GT(gap, 0.0);
  }
  EXPECT_NEAR((s.rotation() - Vec3(du.tail<3>())).norm(), 0.0, 1e-15);
  EXPECT_NEAR((s.displacement() - Vec3(du.head<3>())).norm(), 0.0, 1e-15);
}

TEST(RigidStructure, AxisymmetryMovesOnlyAlongTheAxis) {
  RigidStructure s("disc", block(Kinematics::Axisymmetric), 1.0);
  EXPECT_DOUBLE_EQ(s.reference_point().x(), 0.0);  // on the axis
  DofMap dofs;
  s.add_unknowns(dofs);
  std::vector<DofWeight> weights;
  s.displacement_weights(dofs, Vec3(1.5, 0.5, 0), 0, weights);
  ASSERT_EQ(weights.size(), 1u);
  EXPECT_EQ(weights[0].coefficient, Vec3::UnitY());
  const StructureDrive free(Kinematics::Axisymmetric);
  EXPECT_TRUE(free.prescribed(0));
  EXPECT_FALSE(free.prescribed(1));
  EXPECT_TRUE(free.prescribed(2));
  EXPECT_EQ(free.increment(0, 1)[0], 0.0);
  EXPECT_TRUE(std::isnan(free.increment(0, 1)[1]));
}

TEST(RigidStructure, HasTheMassMatrixAndLoadsOfTheClosedForms) {
  // About a corner: the rectangle's J = m (B^2 + H^2) / 3, coupled to the translations by m s.
  const double rho = 2.0, m = rho * 2.0;
  RigidStructure s("block", block(Kinematics::PlaneStrain), rho, Vec3(0, 0, 0));
  const Eigen::MatrixXd M = s.mass_matrix();
  EXPECT_DOUBLE_EQ(s.mass(), m);
  EXPECT_NEAR(M(2, 2), m * (4.0 + 1.0) / 3.0, 1e-13);
  EXPECT_DOUBLE_EQ(M(0, 2), -m * 0.5);  // -m s_y, s = (1, 0.5)
  EXPECT_DOUBLE_EQ(M(1, 2), m * 1.0);   // m s_x
  EXPECT_TRUE(M.isApprox(M.transpose()));
  // The weight at the centre of mass: its moment about the corner s x F.
  const Vector f = s.generalised_force(Vec3(0, -10, 0));
  EXPECT_DOUBLE_EQ(f(1), -10.0);
  EXPECT_DOUBLE_EQ(f(2), -10.0 * 1.0);

  // 3D box 2 x 1 x 3 about its corner: J_xx = m (b^2 + c^2) / 3, J_xy = -m a b / 4.
  RigidStructure box("box", block(Kinematics::ThreeD), rho, Vec3(0, 0, 0));
  const double mb = rho * 6.0;
  const Eigen::MatrixXd B = box.mass_matrix();
  EXPECT_NEAR(B(3, 3), mb * (1.0 + 9.0) / 3, 1e-12);
  EXPECT_NEAR(B(5, 5), mb * (4.0 + 1.0) / 3, 1e-12);
  EXPECT_NEAR(B(3, 4), -mb * 2.0 * 1.0 / 4, 1e-12);
  EXPECT_NEAR(B(3, 5), -mb * 2.0 * 3.0 / 4, 1e-12);
  // The kinetic energy of a rigid motion, 1/2 m |v_c|^2 + 1/2 omega J_c omega, whatever the
  // reference point.
  Vector v(6);
  v << 0.3, -0.1, 0.2, 0.05, -0.07, 0.11;
  const Vec3 omega = v.tail<3>(), s_c = box.centre_of_mass();
  const Vec3 v_c = v.head<3>() + omega.cross(s_c);
  const double T = 0.5 * mb * v_c.squaredNorm() + 0.5 * omega.dot(box.inertia() * omega);
  EXPECT_NEAR(0.5 * v.dot(B * v), T, 1e-13);
}

// A test spring on the structure's unknowns: what contact will give it.
class Spring final : public Contribution {
 public:
  Spring(const DofMap& map, std::vector<Index> dofs, double k)
      : map_(map), dofs_(std::move(dofs)), k_(k) {}
  const char* name() const override { return "spring"; }
  void declare_couplings(SparsityBuilder& p) const override { p.couple_unknowns(dofs_); }
  bool add(const Vector& du, SystemForces& f, SparseMatrix* tangent) override {
    for (Index d : dofs_) {
      f.internal(d) += k_ * du(d);
      if (tangent) add_to_tangent(*tangent, map_, d, d, k_);
    }
    return true;
  }

 private:
  const DofMap& map_;
  std::vector<Index> dofs_;
  double k_;
};

// One step solved to equilibrium (linear: one Newton correction), as the step solver does: the
// prescribed unknowns set, the free ones solved; returns the reaction f_int + M a - f_ext.
Vector solve_step(DofMap& dofs, std::vector<Contribution*> terms, Vector& du) {
  SparsityBuilder builder(dofs);
  for (Contribution* c : terms) c->declare_couplings(builder);
  SparseMatrix K = builder.build();
  for (Contribution* c : terms) c->attach(K);
  du = dofs.prescribed();
  SystemForces f;
  f.reset(dofs.size());
  for (Contribution* c : terms) c->add(du, f, &K);
  const Vector r = f.external - f.internal - f.inertia;
  Vector rf;
  dofs.restrict_to_free(r, rf);
  const Vector dx = Eigen::MatrixXd(K).lu().solve(rf);
  for (Index k = 0; k < dofs.num_free(); ++k) du(dofs.dof_of_free(k)) += dx(k);
  f.reset(dofs.size());
  for (Contribution* c : terms) c->add(du, f, nullptr);
  return f.internal + f.inertia - f.external;
}

TEST(RigidStructureTerm, FallsFreelyAsNewmarkIntegratesAConstantAcceleration) {
  // Reference point at a corner: the weight's moment about it is balanced by the coupling of
  // the mass matrix, so the block falls without turning.
  RigidStructure s("block", block(Kinematics::PlaneStrain), 2.0, Vec3(0, 0, 0));
  const Vec3 g(0, -9.81, 0);
  const double dt = 0.1;
  const Newmark newmark{0.25, 0.5, dt};
  // Released at rest with its acceleration g (the start Newmark's formulas need to be exact).
  s.set_rates(Vector::Zero(3), Eigen::Vector3d(0, g.y(), 0));
  for (int step = 1; step <= 5; ++step) {
    DofMap dofs;
    s.add_unknowns(dofs);
    dofs.number_free();
    RigidStructureTerm term(s, dofs, g, {0, 0, 0}, newmark, dt);
    Vector du;
    solve_step(dofs, {&term}, du);
    Reactions unused;
    term.report(du, unused);
    term.commit();
    const double t = step * dt;
    EXPECT_NEAR(s.displacement().y(), 0.5 * g.y() * t * t, 1e-12);
    EXPECT_NEAR(s.velocity()(1), g.y() * t, 1e-12);
    EXPECT_NEAR(s.rotation().z(), 0.0, 1e-14);
  }
}

TEST(RigidStructureTerm, HangsOnASpringAndItsDriveHoldsTheRest) {
  // ux held at 0.05 (its increment), the rotation held; uy on a spring k: uy = -m g / k.
  const double rho = 3.0, m = rho * 2.0, k = 100.0;
  RigidStructure s("block", block(Kinematics::PlaneStrain), rho, Vec3(0, 0, 0));
  spec::StructureDrive given;
  given.motion[0] = "0.05 * t";
  given.motion[5] = "0";
  given.load[1] = "-2 * t";  // and pushed down by 2 at t = 1
  const StructureDrive drive(given, Kinematics::PlaneStrain);
  DofMap dofs;
  s.add_unknowns(dofs);
  const std::vector<double> increment = drive.increment(0.0, 1.0);
  for (int c = 0; c < 3; ++c)
    if (!std::isnan(increment[c])) dofs.constrain(s.dof(dofs, c), increment[c]);
  dofs.number_free();
  const Vec3 g(0, -10, 0);
  RigidStructureTerm term(s, dofs, g, drive.load(1.0), std::nullopt, 1.0);
  Spring spring(dofs, {s.dof(dofs, 1)}, k);
  Vector du;
  const Vector reaction = solve_step(dofs, {&term, &spring}, du);
  EXPECT_NEAR(du(s.dof(dofs, 1)), (-m * 10 - 2) / k, 1e-13);
  EXPECT_DOUBLE_EQ(du(s.dof(dofs, 0)), 0.05);
  const DriveForces held = drive_forces(s, drive, dofs, reaction, 1.0);
  EXPECT_NEAR(held.force.x(), 0.0, 1e-12);  // nothing resists the push along x
  EXPECT_DOUBLE_EQ(held.force.y(), -2.0);   // the free component's applied force
  // The rotation is held against the weight's moment about the corner, s x F = -m g s_x.
  EXPECT_NEAR(held.moment.z(), m * 10 * 1.0, 1e-12);
}

TEST(RigidStructure, SavesAndLoadsItsStateBitForBit) {
  RigidStructure moved("box", block(Kinematics::ThreeD), 2.0);
  DofMap dofs;
  moved.add_unknowns(dofs);
  Vector du(6);
  du << 0.1, 0.2, -0.3, 0.01, -0.02, 0.03;
  moved.commit(dofs, du);
  moved.start_phase();
  moved.commit(dofs, 0.5 * du);
  moved.set_rates(du, 2 * du);
  ByteWriter out;
  moved.save(out);
  RigidStructure fresh("box", block(Kinematics::ThreeD), 2.0);
  ByteReader in(out.bytes(), "test");
  fresh.load(in);
  in.expect_end();
  EXPECT_EQ(fresh.mesh().nodes(), moved.mesh().nodes());
  EXPECT_EQ(fresh.displacement(), moved.displacement());
  EXPECT_EQ(fresh.phase_displacement(), moved.phase_displacement());
  EXPECT_EQ(fresh.rotation(), moved.rotation());
  EXPECT_EQ(fresh.phase_rotation(), moved.phase_rotation());
  EXPECT_EQ(fresh.centre_of_mass(), moved.centre_of_mass());
  EXPECT_EQ(fresh.mass_matrix(), moved.mass_matrix());
  EXPECT_EQ(fresh.velocity(), moved.velocity());
  EXPECT_EQ(fresh.acceleration(), moved.acceleration());
  // The 3D phase rotation is the second commit's alone.
  EXPECT_NEAR((moved.phase_rotation() - 0.5 * du.tail<3>()).norm(), 0.0, 1e-15);
}

TEST(StructureDrive, PrescribesIncrementsOfDisplacementOrVelocity) {
  spec::StructureDrive given;
  given.motion[1] = "-0.1 * t^2";
  const StructureDrive by_displacement(given, Kinematics::PlaneStrain);
  const std::vector<double> du = by_displacement.increment(1.0, 2.0);
  EXPECT_TRUE(std::isnan(du[0]));
  EXPECT_DOUBLE_EQ(du[1], -0.1 * 4 + 0.1);
  EXPECT_TRUE(std::isnan(du[2]));
  given.velocity = true;
  given.motion[1] = "2 * t";  // the trapezoidal rule is exact for a linear velocity
  EXPECT_DOUBLE_EQ(StructureDrive(given, Kinematics::PlaneStrain).increment(1.0, 2.0)[1], 3.0);
  // 3D: six components, the rotation about z last.
  spec::StructureDrive turn;
  turn.motion[5] = "t";
  const StructureDrive three(turn, Kinematics::ThreeD);
  EXPECT_EQ(three.components(), 6);
  EXPECT_TRUE(three.prescribed(5));
  EXPECT_FALSE(three.prescribed(3));
}

}  // namespace
}  // namespace geompm

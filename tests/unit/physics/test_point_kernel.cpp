// The tangent of the Lagrangian phase against a finite-difference derivative of the internal
// force (docs/theory.md eq. 3.9): elastic and with initial stress, every element type, plane
// strain, axisymmetry and 3D, both hyperelastic laws.
#include <gtest/gtest.h>

#include <random>

#include "geompm/materials/linear_elastic.hpp"
#include "geompm/materials/neo_hookean.hpp"
#include "geompm/physics/point_kernel.hpp"

namespace geompm {
namespace {

template <class E>
struct KernelCase {
  Eigen::Matrix<double, E::nodes, E::dim> X;  // a distorted cell
  typename E::Local xi;
  PointStartState start;
  Eigen::Matrix<double, E::nodes, E::dim> du;
};

template <class E>
KernelCase<E> make_case(const Material& material, bool prestressed, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  KernelCase<E> c;
  for (int a = 0; a < E::nodes; ++a) {
    const auto node = E::node(a);
    for (int d = 0; d < E::dim; ++d) c.X(a, d) = 2.0 + node(d) + 0.08 * u(rng);  // x > 0 (radius)
  }
  c.xi = E::centroid();
  for (int d = 0; d < E::dim; ++d) c.xi(d) += 0.1 * u(rng);
  c.start.material = &material;
  c.start.position = Vec3::Zero();
  c.start.position.template head<E::dim>() = c.X.transpose() * E::shape(c.xi);
  c.start.volume = 0.7;
  c.start.F = Mat3::Identity();
  c.start.be = Mat3::Identity();
  if (prestressed) {
    // A previous deformation with rotation and stretch: non-zero initial (Cauchy) stress.
    Mat3 A;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) A(i, j) = 0.15 * u(rng);
    if (E::dim == 2) A(0, 2) = A(1, 2) = A(2, 0) = A(2, 1) = 0.0;
    c.start.F = Mat3::Identity() + A;
    c.start.be = c.start.F * c.start.F.transpose();
  }
  c.start.internal = {};
  for (int a = 0; a < E::nodes; ++a)
    for (int d = 0; d < E::dim; ++d) c.du(a, d) = 0.05 * u(rng);
  return c;
}

template <class E>
void check_tangent(const Material& material, bool prestressed, bool axisymmetric) {
  std::mt19937 rng(42);
  for (int trial = 0; trial < 3; ++trial) {
    const auto c = make_case<E>(material, prestressed, rng);
    const auto s = make_stencil<E>(c.X, c.xi);
    PointKernelResult<E> r;
    ASSERT_TRUE(integrate_point(s, c.start, c.du, axisymmetric, true, r));
    constexpr int n = E::nodes * E::dim;
    Eigen::Matrix<double, n, n> fd;
    const double h = 1e-6;
    for (int j = 0; j < n; ++j) {
      auto plus = c.du, minus = c.du;
      plus(j / E::dim, j % E::dim) += h;
      minus(j / E::dim, j % E::dim) -= h;
      PointKernelResult<E> rp, rm;
      ASSERT_TRUE(integrate_point(s, c.start, plus, axisymmetric, false, rp));
      ASSERT_TRUE(integrate_point(s, c.start, minus, axisymmetric, false, rm));
      fd.col(j) = (rp.internal_force - rm.internal_force) / (2 * h);
    }
    const double scale = fd.norm();
    ASSERT_GT(scale, 0.0);
    EXPECT_LT((r.stiffness - fd).norm() / scale, 1e-7)
        << E::nodes << "-node cell, trial " << trial << "\nK=\n"
        << r.stiffness << "\nFD=\n"
        << fd;
  }
}

template <class E>
void check_all_cases() {
  LinearElastic hencky(1000.0, 0.3, 1.0);
  NeoHookean neo(1000.0, 0.3, 1.0);
  for (bool prestressed : {false, true}) {
    check_tangent<E>(hencky, prestressed, false);
    check_tangent<E>(neo, prestressed, false);
    if (E::dim == 2) {
      check_tangent<E>(hencky, prestressed, true);
      check_tangent<E>(neo, prestressed, true);
    }
  }
}

TEST(PointKernelTangent, Tri3) { check_all_cases<Element<CellType::Tri3>>(); }
TEST(PointKernelTangent, Tri6) { check_all_cases<Element<CellType::Tri6>>(); }
TEST(PointKernelTangent, Quad4) { check_all_cases<Element<CellType::Quad4>>(); }
TEST(PointKernelTangent, Tet4) { check_all_cases<Element<CellType::Tet4>>(); }
TEST(PointKernelTangent, Hex8) { check_all_cases<Element<CellType::Hex8>>(); }

// A rigid rotation of a stressed point leaves the stress rotated with it and its magnitude
// unchanged (objectivity of the update).
TEST(PointKernel, RigidRotationRotatesTheStress) {
  using E = Element<CellType::Quad4>;
  LinearElastic material(1000.0, 0.25, 1.0);
  Eigen::Matrix<double, 4, 2> X;
  X << 0, 0, 1, 0, 1, 1, 0, 1;
  PointStartState start{&material, Vec3(0.5, 0.5, 0), 1.0, Mat3::Identity(), Mat3::Identity(), {}};
  start.F(0, 0) = 1.02;
  start.F(1, 1) = 0.97;
  start.be = start.F * start.F.transpose();
  const double angle = 1.1;  // radians: a large rotation in one step
  Eigen::Matrix2d R;
  R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  Eigen::Matrix<double, 4, 2> du;
  for (int a = 0; a < 4; ++a)
    du.row(a) = (R * X.row(a).transpose() - X.row(a).transpose()).transpose();
  const auto s = make_stencil<E>(X, E::Local(0.1, -0.2));
  PointKernelResult<E> rotated, unrotated;
  ASSERT_TRUE(integrate_point(s, start, du, false, false, rotated));
  ASSERT_TRUE(integrate_point(s, start,
                              Eigen::Matrix<double, 4, 2>(Eigen::Matrix<double, 4, 2>::Zero()),
                              false, false, unrotated));
  Mat3 R3 = Mat3::Identity();
  R3.topLeftCorner<2, 2>() = R;
  const Mat3 expected = R3 * unrotated.state.cauchy_stress * R3.transpose();
  EXPECT_LT((rotated.state.cauchy_stress - expected).norm(), 1e-10 * expected.norm());
  EXPECT_NEAR(rotated.volume, unrotated.volume, 1e-12);
}

}  // namespace
}  // namespace geompm

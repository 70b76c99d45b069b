// The pyramid5 cell (docs/theory.md eqs. 19.7-19.9): its traces on the faces (the bilinear
// quadrangle on the base, linear triangles on the sides, so it conforms with hex8 and tet4), the
// apex limit, linear completeness on a distorted pyramid, the quadrature (the volume of any
// straight-sided pyramid, the internal force of a constant stress against the divergence
// theorem, the stiffness and mass matrices of an affine pyramid against a rule of high order),
// and the inverse map.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include "geompm/core/error.hpp"
#include "geompm/mesh/cell_geometry.hpp"
#include "geompm/mesh/element.hpp"
#include "mesh_test_support.hpp"

namespace geompm {
namespace {

using Pyramid = Element<CellType::Pyramid5>;
using Quad = Element<CellType::Quad4>;
using Nodes = NodeCoordinates<CellType::Pyramid5>;

/// A pyramid whose base is a warped quadrangle (not planar, not a parallelogram) and whose apex
/// is off the base's axis.
Nodes distorted_pyramid() {
  Nodes x;
  x.col(0) << 0.0, 0.0, 0.0;
  x.col(1) << 1.3, 0.1, 0.05;
  x.col(2) << 1.1, 1.2, -0.1;
  x.col(3) << -0.2, 0.9, 0.08;
  x.col(4) << 0.7, 0.3, 1.1;
  return x;
}

/// An affine image of the reference pyramid: a parallelogram base, the apex anywhere above it.
Nodes affine_pyramid() {
  Eigen::Matrix3d A;
  A << 0.8, 0.3, 0.2,  //
      -0.1, 0.6, 0.1,  //
      0.05, 0.1, 1.3;
  const Eigen::Vector3d offset(0.4, -0.2, 0.1);
  Nodes x;
  for (int a = 0; a < 5; ++a) x.col(a) = A * Pyramid::node(a) + offset;
  return x;
}

/// The collapsed-hexahedron map (eq. 19.9) with an n-point Gauss-Legendre rule per direction:
/// calls f(xi, weight) with weight = w_u w_v w_w (1 - w)^2. Exact for polynomials in (u, v, w)
/// of degree 2n - 1 per direction, the (1 - w)^2 included.
template <class F>
void high_order_rule(int n, F&& f) {
  // Gauss-Legendre on [-1, 1] by Newton on P_n.
  std::vector<double> x(n), w(n);
  for (int i = 0; i < n; ++i) {
    double t = std::cos(M_PI * (i + 0.75) / (n + 0.5));
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = t;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * t * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      const double dp = n * (t * p1 - p0) / (t * t - 1.0);
      const double step = p1 / dp;
      t -= step;
      if (std::abs(step) < 1e-16) {
        x[i] = t;
        w[i] = 2.0 / ((1.0 - t * t) * dp * dp);
        break;
      }
    }
  }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const double height = 0.5 * (x[k] + 1.0), s = 1.0 - height;
        f(Pyramid::Local(x[i] * s, x[j] * s, height), w[i] * w[j] * 0.5 * w[k] * s * s);
      }
}

TEST(Pyramid5, OnTheBaseItIsTheBilinearQuadrangle) {
  std::mt19937 rng(3);
  for (int k = 0; k < 50; ++k) {
    const Quad::Local st = testing::random_reference_point<CellType::Quad4>(rng);
    const Pyramid::Values n = Pyramid::shape(Pyramid::Local(st[0], st[1], 0.0));
    EXPECT_LT((n.head<4>() - Quad::shape(st)).norm(), 1e-15);
    EXPECT_EQ(n[4], 0.0);
  }
}

TEST(Pyramid5, OnEachTriangularFaceItIsLinear) {
  // The face through base corners a, b = a + 1 and the apex: N_a, N_b, N_apex are the
  // barycentric coordinates of the triangle, the other two vanish.
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int a = 0; a < 4; ++a) {
    const int b = (a + 1) % 4;
    for (int k = 0; k < 50; ++k) {
      double l1 = unit(rng), l2 = unit(rng);
      if (l1 + l2 > 1.0) l1 = 1.0 - l1, l2 = 1.0 - l2;
      const double l0 = 1.0 - l1 - l2;
      const Pyramid::Local xi =
          l0 * Pyramid::node(a) + l1 * Pyramid::node(b) + l2 * Pyramid::node(4);
      const Pyramid::Values n = Pyramid::shape(xi);
      EXPECT_NEAR(n[a], l0, 1e-14) << "face " << a;
      EXPECT_NEAR(n[b], l1, 1e-14) << "face " << a;
      EXPECT_NEAR(n[4], l2, 1e-14) << "face " << a;
      EXPECT_NEAR(n[(a + 2) % 4], 0.0, 1e-14) << "face " << a;
      EXPECT_NEAR(n[(a + 3) % 4], 0.0, 1e-14) << "face " << a;
    }
  }
}

TEST(Pyramid5, ApexTakesTheLimitAlongTheAxis) {
  const Pyramid::Local apex = Pyramid::node(4);
  const Pyramid::Values n = Pyramid::shape(apex);
  for (int a = 0; a < 4; ++a) EXPECT_EQ(n[a], 0.0);
  EXPECT_EQ(n[4], 1.0);
  const Pyramid::Gradients g = Pyramid::shape_gradients(apex);
  EXPECT_TRUE(g.allFinite());
  // Along the axis the gradients are constant; at the apex they are that constant.
  const Pyramid::Gradients near = Pyramid::shape_gradients(Pyramid::Local(0.0, 0.0, 1.0 - 1e-9));
  EXPECT_LT((g - near).norm(), 1e-15);
  for (int a = 0; a < 4; ++a) {
    EXPECT_NEAR(g(a, 0), 0.25 * Pyramid::node(a)[0], 1e-15);
    EXPECT_NEAR(g(a, 2), -0.25, 1e-15);
  }
  // Towards the apex along an edge or a face the values tend to the apex's (continuity), while
  // the gradients stay bounded (|xi|, |eta| <= 1 - zeta in the cell).
  for (int a = 0; a < 4; ++a)
    for (double s : {1e-3, 1e-6, 1e-10}) {
      const Pyramid::Local xi(Pyramid::node(a)[0] * s, 0.5 * Pyramid::node(a)[1] * s, 1.0 - s);
      EXPECT_LT((Pyramid::shape(xi) - n).lpNorm<Eigen::Infinity>(), 2.0 * s);
      EXPECT_LT(Pyramid::shape_gradients(xi).lpNorm<Eigen::Infinity>(), 1.0 + 1e-12);
    }
}

TEST(Pyramid5, ReproducesLinearFieldsOnADistortedPyramid) {
  const Nodes x = distorted_pyramid();
  const Eigen::Matrix3d A =
      (Eigen::Matrix3d() << 0.3, -1.2, 0.7, 0.4, 0.1, -0.5, 2.0, 0.3, -0.8).finished();
  const Eigen::Vector3d c(0.1, -0.5, 0.25);
  const Nodes u = (A * x).colwise() + c;
  std::mt19937 rng(5);
  for (int k = 0; k < 200; ++k) {
    Pyramid::Local xi = testing::random_reference_point<CellType::Pyramid5>(rng);
    if (k == 0) xi = Pyramid::node(4);
    const auto J = jacobian<CellType::Pyramid5>(x, xi);
    const Eigen::Vector3d at = map_to_physical<CellType::Pyramid5>(x, xi);
    EXPECT_LT((u * Pyramid::shape(xi) - (A * at + c)).norm(), 1e-13);
    EXPECT_LT((u * (Pyramid::shape_gradients(xi) * J.inverse()) - A).norm(), 1e-12);
  }
}

TEST(Pyramid5, QuadratureIntegratesTheVolumeOfStraightSidedPyramids) {
  // A trapezoid base in z = 0 and an apex at height 0.9 off its axis: V = A h / 3.
  Nodes trapezoid;
  trapezoid << 0.0, 2.0, 1.5, 0.3, 1.9,  //
      0.0, 0.0, 1.0, 1.0, -0.4,          //
      0.0, 0.0, 0.0, 0.0, 0.9;
  const auto volume = [](const Nodes& x) {
    double v = 0.0;
    for (int q = 0; q < Pyramid::quadrature_size(); ++q)
      v += Pyramid::quadrature_weight(q) *
           jacobian<CellType::Pyramid5>(x, Pyramid::quadrature_point(q)).determinant();
    return v;
  };
  EXPECT_NEAR(volume(trapezoid), 0.5 * (2.0 + 1.2) * 1.0 * 0.9 / 3.0, 1e-15);
  // The warped base: V = (1/3) of the flux of x through the surface (divergence theorem), the
  // triangles' exactly, the bilinear base's with a 3 x 3 Gauss rule (its integrand has degree 2
  // in each direction).
  const Nodes x = distorted_pyramid();
  double flux = 0.0;
  for (int a = 0; a < 4; ++a) {
    const int b = (a + 1) % 4;
    const Eigen::Vector3d centre = (x.col(a) + x.col(b) + x.col(4)) / 3.0;
    flux += centre.dot(0.5 * (x.col(b) - x.col(a)).cross(x.col(4) - x.col(a)));
  }
  const double g[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, w[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const Quad::Local st(g[i], g[j]);
      const Eigen::Matrix<double, 3, 4> base = x.leftCols<4>();
      const Eigen::Matrix<double, 3, 2> d = base * Quad::shape_gradients(st);
      // The base seen from outside is clockwise in the reference numbering: the outward
      // normal is d_eta x d_xi.
      flux += w[i] * w[j] * (base * Quad::shape(st)).dot(d.col(1).cross(d.col(0)));
    }
  EXPECT_NEAR(volume(x), flux / 3.0, 1e-14);
  EXPECT_GT(volume(x), 0.3);
}

TEST(Pyramid5, QuadratureIntegratesTheForcesOfAConstantStress) {
  // f_a = int grad N_a . sigma dV = (surface integral of N_a sigma n) for the warped pyramid:
  // the rule is exact for it (the integrand is polynomial in the collapsed coordinates).
  const Nodes x = distorted_pyramid();
  Eigen::Matrix3d sigma;
  sigma << 2.0, 0.3, -0.4,  //
      0.3, -1.0, 0.6,       //
      -0.4, 0.6, 0.5;
  Eigen::Matrix<double, 3, 5> volume_force = Eigen::Matrix<double, 3, 5>::Zero();
  for (int q = 0; q < Pyramid::quadrature_size(); ++q) {
    const Pyramid::Local xi = Pyramid::quadrature_point(q);
    const auto J = jacobian<CellType::Pyramid5>(x, xi);
    const Pyramid::Gradients dn_dx = Pyramid::shape_gradients(xi) * J.inverse();
    volume_force += Pyramid::quadrature_weight(q) * J.determinant() * sigma * dn_dx.transpose();
  }
  Eigen::Matrix<double, 3, 5> surface_force = Eigen::Matrix<double, 3, 5>::Zero();
  for (int a = 0; a < 4; ++a) {  // triangles: int N dA = A / 3 at each of their corners
    const int b = (a + 1) % 4;
    const Eigen::Vector3d area = 0.5 * (x.col(b) - x.col(a)).cross(x.col(4) - x.col(a));
    for (int node : {a, b, 4}) surface_force.col(node) += sigma * area / 3.0;
  }
  const double g[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, w[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const Quad::Local st(g[i], g[j]);
      const Eigen::Matrix<double, 3, 2> d = x.leftCols<4>() * Quad::shape_gradients(st);
      const Eigen::Vector3d area = w[i] * w[j] * d.col(1).cross(d.col(0));
      const Quad::Values n = Quad::shape(st);
      for (int a = 0; a < 4; ++a) surface_force.col(a) += n[a] * sigma * area;
    }
  EXPECT_LT((volume_force - surface_force).norm(), 1e-14 * sigma.norm());
  EXPECT_GT(volume_force.norm(), 0.1);
}

/// int grad N_a . grad N_b dV and int N_a N_b dV of the cell, with the given rule.
template <class Rule>
std::pair<Eigen::Matrix<double, 5, 5>, Eigen::Matrix<double, 5, 5>> stiffness_and_mass(
    const Nodes& x, Rule&& rule) {
  Eigen::Matrix<double, 5, 5> K = Eigen::Matrix<double, 5, 5>::Zero(), M = K;
  rule([&](const Pyramid::Local& xi, double weight) {
    const auto J = jacobian<CellType::Pyramid5>(x, xi);
    const Pyramid::Gradients G = Pyramid::shape_gradients(xi) * J.inverse();
    const Pyramid::Values n = Pyramid::shape(xi);
    K += weight * J.determinant() * G * G.transpose();
    M += weight * J.determinant() * n * n.transpose();
  });
  return {K, M};
}

TEST(Pyramid5, QuadratureIsExactForTheStiffnessAndMassOfAnAffinePyramid) {
  const auto own = [](auto&& f) {
    for (int q = 0; q < Pyramid::quadrature_size(); ++q)
      f(Pyramid::quadrature_point(q), Pyramid::quadrature_weight(q));
  };
  const auto high = [](auto&& f) { high_order_rule(8, f); };
  const auto [K, M] = stiffness_and_mass(affine_pyramid(), own);
  const auto [K_ref, M_ref] = stiffness_and_mass(affine_pyramid(), high);
  EXPECT_LT((K - K_ref).norm(), 1e-14 * K_ref.norm());
  EXPECT_LT((M - M_ref).norm(), 1e-14 * M_ref.norm());
  // The stiffness annihilates a constant field and the rule is not vacuous: on the warped
  // pyramid (rational integrand) the two rules differ.
  EXPECT_LT((K * Eigen::Matrix<double, 5, 1>::Ones()).norm(), 1e-14 * K.norm());
  const auto [K_warped, M_warped] = stiffness_and_mass(distorted_pyramid(), own);
  const auto [K_warped_ref, M_warped_ref] = stiffness_and_mass(distorted_pyramid(), high);
  EXPECT_GT((K_warped - K_warped_ref).norm(), 1e-6 * K_warped_ref.norm());
  EXPECT_NEAR(M_warped.sum(), M_warped_ref.sum(), 1e-14);  // the volume, exact for both
}

TEST(Pyramid5, InverseMapFindsPointsOfADistortedPyramidAndRejectsOthers) {
  Mesh mesh;
  mesh.cell_type = CellType::Pyramid5;
  const Nodes x = distorted_pyramid();
  for (int a = 0; a < 5; ++a) mesh.nodes.push_back(x.col(a));
  mesh.connectivity = {0, 1, 2, 3, 4};
  ASSERT_NO_THROW(validate_mesh(mesh, "pyramid"));
  std::mt19937 rng(6);
  for (int k = 0; k < 500; ++k) {
    Pyramid::Local xi = testing::random_reference_point<CellType::Pyramid5>(rng);
    if (k < 5) xi = Pyramid::node(k);
    if (k == 5) xi = Pyramid::Local(0.0, 0.0, 0.999);  // beside the apex
    const Vec3 at = map_to_physical(mesh, 0, Vec3(xi[0], xi[1], xi[2]));
    Vec3 found;
    ASSERT_TRUE(cell_contains(mesh, 0, at, found)) << xi.transpose();
    EXPECT_LT((found - Vec3(xi[0], xi[1], xi[2])).norm(), 1e-10) << xi.transpose();
  }
  // Points beyond each face: past the apex, below the base, beside a triangle.
  const Vec3 apex = mesh.nodes[4], centre = map_to_physical(mesh, 0, Vec3(0, 0, 0.25));
  Vec3 found;
  EXPECT_FALSE(cell_contains(mesh, 0, apex + 1e-6 * (apex - centre), found));
  EXPECT_FALSE(cell_contains(
      mesh, 0, map_to_physical(mesh, 0, Vec3(0.1, 0.2, 0.0)) - Vec3(0, 0, 1e-6), found));
  EXPECT_FALSE(cell_contains(mesh, 0, map_to_physical(mesh, 0, Vec3(0.5 + 1e-6, 0.1, 0.5)), found));
  EXPECT_TRUE(cell_contains(mesh, 0, map_to_physical(mesh, 0, Vec3(0.5 - 1e-6, 0.1, 0.5)), found));
}

TEST(Pyramid5, AnInvertedPyramidIsRefusedNamingIt) {
  // The apex below the base (counter-clockwise seen from above): negative Jacobian throughout.
  Mesh mesh;
  mesh.cell_type = CellType::Pyramid5;
  mesh.nodes = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, -0.7}};
  mesh.connectivity = {0, 1, 2, 3, 4};
  try {
    validate_mesh(mesh, "pyramid.msh");
    ADD_FAILURE() << "an inverted pyramid was accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("cell 0 (pyramid5) is inverted"), std::string::npos) << message;
    EXPECT_NE(message.find("(0.5, 0.5, -0.7)"), std::string::npos) << message;
  }
  mesh.nodes[4].z() = 0.7;
  EXPECT_NO_THROW(validate_mesh(mesh, "pyramid.msh"));
  EXPECT_NEAR(cell_measure(mesh, 0), 0.7 / 3.0, 1e-15);
}

}  // namespace
}  // namespace geompm

// The zero level set as facets (docs/theory.md §16.2). A linear phi is cut exactly by every cell
// type (its interpolant is itself on each linear sub-simplex): the facets lie on the line or
// plane, their normals are its normal out of the body, and clipped to a box their area vectors
// sum to the closed form. A circle's polygon ends where the clip lines cut it; on grid lines that
// is where phi's linear interpolant along the edge is 0, off the exact circle by the
// interpolation error, which bounds the resultant's error (below). The level set of a block of
// points (block_of_points.hpp) gives its top surface, once, with the upward normal.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "block_of_points.hpp"
#include "geompm/levelset/zero_level_set.hpp"
#include "geompm/mesh/gmsh_import.hpp"
#include "geompm/mesh/structured_mesh.hpp"

namespace geompm {
namespace {

constexpr double round_off = 1e-12;

std::vector<double> nodal(const Mesh& mesh, const std::function<double(const Vec3&)>& phi) {
  std::vector<double> values;
  for (const Vec3& x : mesh.nodes) values.push_back(phi(x));
  return values;
}

Vec3 area_sum(const std::vector<SurfaceFacet>& facets) {
  Vec3 sum = Vec3::Zero();
  for (const SurfaceFacet& f : facets) sum += f.measure() * f.normal;
  return sum;
}

FacetBox box(std::array<double, 2> x, std::optional<std::array<double, 2>> y = std::nullopt) {
  FacetBox b;
  b.range[0] = x;
  b.range[1] = y;
  return b;
}

class LineIn2D : public ::testing::TestWithParam<CellType> {};

TEST_P(LineIn2D, IsCutExactlyWithTheOutwardNormal) {
  // The body below y = 1.3 + 0.4 x on [0, 4] x [0, 4] (cells of 0.5), phi its signed distance.
  Mesh mesh =
      generate_structured_mesh(testing::block_mesh(GetParam(), {8, 8, 1}, Vec3::Zero(), 0.5));
  const double a = 1.3, b = 0.4, norm = std::sqrt(1 + b * b);
  const auto phi = [&](const Vec3& x) { return (a + b * x.x() - x.y()) / norm; };
  const FacetBox clip = box({0.7, 3.1});
  const auto facets = zero_level_set(mesh, nodal(mesh, phi), {}, &clip);
  ASSERT_FALSE(facets.empty());
  const Vec3 outward = Vec3(-b, 1.0, 0.0) / norm;
  double length = 0.0;
  for (const SurfaceFacet& f : facets) {
    EXPECT_EQ(f.vertices, 2);
    for (int k = 0; k < 2; ++k) {
      EXPECT_NEAR(phi(f.x[k]), 0.0, round_off);
      // The reference coordinates map to the same place.
      EXPECT_NEAR((map_to_physical(mesh, f.cell, f.xi[k]) - f.x[k]).norm(), 0.0, round_off);
    }
    EXPECT_NEAR((f.normal - outward).norm(), 0.0, round_off);
    length += f.measure();
  }
  EXPECT_NEAR(length, 2.4 * norm, round_off);
  // The area vector: the chord (2.4, 0.96) rotated clockwise, (-0.96, 2.4).
  EXPECT_NEAR((area_sum(facets) - Vec3(-2.4 * b, 2.4, 0.0)).norm(), 0.0, round_off);
}

INSTANTIATE_TEST_SUITE_P(CellTypes, LineIn2D,
                         ::testing::Values(CellType::Quad4, CellType::Tri3, CellType::Tri6));

class PlaneIn3D : public ::testing::TestWithParam<CellType> {};

TEST_P(PlaneIn3D, IsCutExactlyWithTheOutwardNormal) {
  // The body below z = 0.9 + 0.3 x - 0.2 y in [0, 2]^3 (cells of 0.5), clipped to
  // x in [0.3, 1.6], y in [0.2, 1.9]: area vector (1.3 x 1.7) (-0.3, 0.2, 1).
  Mesh mesh =
      generate_structured_mesh(testing::block_mesh(GetParam(), {4, 4, 4}, Vec3::Zero(), 0.5));
  const double norm = std::sqrt(1 + 0.09 + 0.04);
  const auto phi = [&](const Vec3& x) { return (0.9 + 0.3 * x.x() - 0.2 * x.y() - x.z()) / norm; };
  const FacetBox clip = box({0.3, 1.6}, std::array<double, 2>{0.2, 1.9});
  const auto facets = zero_level_set(mesh, nodal(mesh, phi), {}, &clip);
  ASSERT_FALSE(facets.empty());
  const Vec3 outward = Vec3(-0.3, 0.2, 1.0) / norm;
  double area = 0.0;
  for (const SurfaceFacet& f : facets) {
    EXPECT_EQ(f.vertices, 3);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(phi(f.x[k]), 0.0, round_off);
    EXPECT_NEAR((f.normal - outward).norm(), 0.0, round_off);
    area += f.measure();
  }
  const double projected = 1.3 * 1.7;
  EXPECT_NEAR(area, projected * norm, round_off);
  EXPECT_NEAR((area_sum(facets) - projected * Vec3(-0.3, 0.2, 1.0)).norm(), 0.0, round_off);
}

INSTANTIATE_TEST_SUITE_P(CellTypes, PlaneIn3D, ::testing::Values(CellType::Hex8, CellType::Tet4));

TEST(ZeroLevelSet, CircularArcEndsOnTheCircleWithinTheEdgeInterpolationError) {
  // The disc |x - (2, 2)| < 1.3 on [0, 4]^2 (quad4 cells of h = 0.25), phi = 1.3 - |x - c|; its
  // upper arc clipped to the grid lines x = 1.25 and 2.75 (and y >= 2). The polygon's area vector
  // is its chord B - A rotated clockwise whatever its shape: (-(y_B - y_A), x_B - x_A), so the x
  // component is exact. A and B are where phi's linear interpolant along the vertical edge they
  // lie on is 0; that interpolant is off phi by at most h^2 / 8 max |phi_yy| on the edge, and
  // phi_yy = -dx^2 / rho^3, phi_y = -dy / rho, so each end is off the circle by at most
  // h^2 / 8 (dx^2 / rho_min^3) / (|dy| / rho) (rho_min = R - h: the edge's nearest place).
  const double h = 0.25, R = 1.3;
  const Vec3 c(2.0, 2.0, 0.0);
  Mesh mesh =
      generate_structured_mesh(testing::block_mesh(CellType::Quad4, {16, 16, 1}, Vec3::Zero(), h));
  const auto phi = [&](const Vec3& x) { return R - (x - c).norm(); };
  const FacetBox clip = box({1.25, 2.75}, std::array<double, 2>{2.0, 4.0});
  const auto facets = zero_level_set(mesh, nodal(mesh, phi), {}, &clip);
  const auto height = [&](double x) {
    return c.y() + std::sqrt(R * R - (x - c.x()) * (x - c.x()));
  };
  const auto end_error = [&](double x) {
    const double dx = x - c.x(), dy = height(x) - c.y();
    return h * h / 8.0 * (dx * dx / std::pow(R - h, 3)) / (dy / R);
  };
  const Vec3 sum = area_sum(facets);
  EXPECT_NEAR(sum.y(), 1.5, round_off);
  const double exact = -(height(2.75) - height(1.25));  // 0 by symmetry: a circle about x = 2
  EXPECT_NEAR(sum.x(), exact, end_error(1.25) + end_error(2.75));
  // Asymmetric ends: x in [1.25, 3.0].
  const FacetBox right = box({1.25, 3.0}, std::array<double, 2>{2.0, 4.0});
  const Vec3 sum_right = area_sum(zero_level_set(mesh, nodal(mesh, phi), {}, &right));
  EXPECT_NEAR(sum_right.y(), 1.75, round_off);
  const double exact_right = -(height(3.0) - height(1.25));
  EXPECT_NEAR(sum_right.x(), exact_right, end_error(1.25) + end_error(3.0));
  EXPECT_GT(std::abs(exact_right), 10 * (end_error(1.25) + end_error(3.0)));  // a real test
  for (const SurfaceFacet& f : facets) EXPECT_GT(f.normal.y(), 0.0);          // out of the disc, up
}

TEST(ZeroLevelSet, PlanesThroughHexahedraPyramidsAndTetrahedraAreCutExactly) {
  // The mixed box [0, 2] x [0, 1]^2 (tests/unit/mesh/data/mixed_box.msh): the plane z = 0.55
  // crosses every kind of cell, x = 1.1 the pyramids and tetrahedra beside the interface. A linear
  // phi is its own interpolant on each cell's sub-tetrahedra: the cut is the box's section.
  const Mesh mesh =
      read_gmsh_mesh(std::string(GEOMPM_SOURCE_DIR) + "/tests/unit/mesh/data/mixed_box.msh", 3);
  struct Plane {
    Vec3 normal;
    double at, area;
  };
  for (const Plane& plane : {Plane{Vec3(0, 0, 1), 0.55, 2.0}, Plane{Vec3(1, 0, 0), 1.1, 1.0}}) {
    const auto phi = [&](const Vec3& x) { return plane.at - plane.normal.dot(x); };
    const auto facets = zero_level_set(mesh, nodal(mesh, phi), {});
    std::set<CellType> cut;
    for (const SurfaceFacet& f : facets) {
      cut.insert(mesh.type_of(f.cell));
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(phi(f.x[k]), 0.0, round_off);
      EXPECT_NEAR((f.normal - plane.normal).norm(), 0.0, round_off);
    }
    EXPECT_NEAR((area_sum(facets) - plane.area * plane.normal).norm(), 0.0, round_off);
    EXPECT_TRUE(cut.count(CellType::Pyramid5)) << "at " << plane.at;
    EXPECT_TRUE(cut.count(CellType::Tet4)) << "at " << plane.at;
  }
}

TEST(ZeroLevelSet, BlockOfPointsHasItsTopOnceWithTheUpwardNormal) {
  for (CellType type : {CellType::Quad4, CellType::Hex8}) {
    const bool three_d = type == CellType::Hex8;
    const int up = three_d ? 2 : 1;
    auto block = testing::fill_block(testing::block_mesh(type, {3, three_d ? 2 : 4, 4}),
                                     three_d ? Kinematics::ThreeD : Kinematics::PlaneStrain,
                                     [&](const Vec3& x) { return x(up) < 2.0 ? 0 : -1; });
    const auto facets = zero_level_set(LevelSet(*block->grid, block->points));
    double measure = 0.0;
    for (const SurfaceFacet& f : facets) {
      for (int k = 0; k < f.vertices; ++k) EXPECT_NEAR(f.x[k](up), 2.0, round_off);
      EXPECT_NEAR(f.normal(up), 1.0, round_off);
      measure += f.measure();
    }
    EXPECT_NEAR(measure, three_d ? 6.0 : 3.0, round_off);  // once, not from both cells
  }
}

TEST(ZeroLevelSet, AxisymmetricQuadratureWeighsWithTheRadius) {
  // The top of a block r in [0, 4] (the mesh's width): the weights sum to int_0^4 r dr = 8 per
  // radian, and the first moment to int r^2 dr = 64 / 3 (Gauss exact to degree 3).
  auto block =
      testing::fill_block(testing::block_mesh(CellType::Quad4, {4, 4, 1}), Kinematics::Axisymmetric,
                          [](const Vec3& x) { return x.y() < 2.0 ? 0 : -1; });
  const FacetBox top = box({0.0, 4.0}, std::array<double, 2>{1.5, 2.5});
  double weight = 0.0, moment = 0.0;
  for (const SurfaceFacet& f : zero_level_set(LevelSet(*block->grid, block->points), &top))
    for (const FacetPoint& q : facet_quadrature(f, true)) {
      weight += q.weight;
      moment += q.weight * q.x.x();
    }
  EXPECT_NEAR(weight, 8.0, round_off);
  EXPECT_NEAR(moment, 64.0 / 3.0, round_off);
}

}  // namespace
}  // namespace geompm

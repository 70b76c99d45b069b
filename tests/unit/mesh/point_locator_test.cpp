// Point location: agreement with a brute-force search, points on shared faces, hints, points
// outside the mesh, and a run of a million queries.
#include "geompm/mesh/point_locator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <thread>

#include "geompm/mesh/cell_geometry.hpp"
#include "mesh_test_support.hpp"

namespace geompm {
namespace {

using testing::all_cell_types;

/// Random points in the mesh's box widened by 10 %, so some fall outside the mesh.
std::vector<Vec3> random_points(const Mesh& mesh, int count, unsigned seed) {
  Vec3 lower = mesh.nodes[0], upper = mesh.nodes[0];
  for (const Vec3& x : mesh.nodes) lower = lower.cwiseMin(x), upper = upper.cwiseMax(x);
  const Vec3 margin = 0.1 * (upper - lower);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Vec3> points(count, Vec3::Zero());
  for (Vec3& x : points)
    for (int i = 0; i < mesh.dim(); ++i)
      x[i] = lower[i] - margin[i] + unit(rng) * (upper[i] - lower[i] + 2.0 * margin[i]);
  return points;
}

void expect_agreement_with_brute_force(const Mesh& mesh, unsigned seed) {
  const PointLocator locator(mesh);
  int inside = 0, outside = 0;
  for (const Vec3& x : random_points(mesh, 10000, seed)) {
    Index brute = -1;
    Vec3 xi;
    for (Index c = 0; c < mesh.num_cells() && brute < 0; ++c)
      if (cell_contains(mesh, c, x, xi)) brute = c;
    const auto found = locator.locate(x);
    if (brute < 0) {
      EXPECT_FALSE(found.has_value()) << x.transpose();
      ++outside;
      continue;
    }
    ++inside;
    ASSERT_TRUE(found.has_value()) << x.transpose() << " is in cell " << brute;
    // Away from faces a point is in one cell only; on a face either cell is right.
    Vec3 check;
    EXPECT_TRUE(cell_contains(mesh, found->cell, x, check));
    EXPECT_LT((map_to_physical(mesh, found->cell, found->xi) - x).norm(), 1e-10);
  }
  EXPECT_GT(inside, 1000);  // both branches are exercised
  EXPECT_GT(outside, 1000);
}

TEST(PointLocatorTest, AgreesWithBruteForceOnDistortedMeshes) {
  for (CellType type : all_cell_types) {
    SCOPED_TRACE(to_string(type));
    expect_agreement_with_brute_force(
        testing::distorted_mesh(type, cell_dimension(type) == 2 ? 12 : 5, 23), 1);
  }
}

TEST(PointLocatorTest, AgreesWithBruteForceOnUnstructuredGmshMeshes) {
  for (CellType type : {CellType::Tri3, CellType::Tri6, CellType::Quad4, CellType::Tet4}) {
    SCOPED_TRACE(to_string(type));
    expect_agreement_with_brute_force(testing::gmsh_mesh(type), 2);
  }
}

TEST(PointLocatorTest, AgreesWithBruteForceOnGradedMesh) {
  // Cells of very different sizes: the bucket size is a compromise.
  StructuredMeshSpec spec;
  spec.cell_type = CellType::Quad4;
  spec.axes[0] = {{0.1, 10, 1.0}, {10.0, 15, 20.0}};
  spec.axes[1] = {{5.0, 12, 0.05}};
  expect_agreement_with_brute_force(generate_structured_mesh(spec), 3);
}

TEST(PointLocatorTest, FindsNodesAndPointsOnSharedFaces) {
  for (CellType type : all_cell_types) {
    const Mesh mesh = testing::uniform_mesh(type, 4);
    const PointLocator locator(mesh);
    // Every node (corners of the domain included) and every midpoint of a cell edge.
    std::vector<Vec3> points = mesh.nodes;
    for (Index c = 0; c < mesh.num_cells(); ++c) {
      const auto nodes = mesh.cell_nodes(c);
      for (std::size_t a = 0; a < nodes.size(); ++a)
        for (std::size_t b = a + 1; b < nodes.size(); ++b)
          points.push_back(0.5 * (mesh.nodes[nodes[a]] + mesh.nodes[nodes[b]]));
    }
    for (const Vec3& x : points) {
      const auto found = locator.locate(x);
      ASSERT_TRUE(found.has_value()) << to_string(type) << " " << x.transpose();
      EXPECT_LT((map_to_physical(mesh, found->cell, found->xi) - x).norm(), 1e-12);
    }
  }
}

TEST(PointLocatorTest, FindsPointsOnEdgesOfDistortedAndUnstructuredCells) {
  // Points mapped from the edges of every cell: on faces shared with neighbours (up to
  // round-off on either side), or on the boundary of the domain.
  std::mt19937 rng(3);
  for (CellType type : all_cell_types) {
    std::vector<Mesh> meshes = {testing::distorted_mesh(type, cell_dimension(type) == 2 ? 8 : 3)};
    if (type != CellType::Hex8) meshes.push_back(testing::gmsh_mesh(type));
    for (const Mesh& mesh : meshes) {
      const PointLocator locator(mesh);
      for (Index c = 0; c < mesh.num_cells(); ++c)
        for (const Vec3& edge : testing::reference_edge_points(type, 2, rng)) {
          const Vec3 x = map_to_physical(mesh, c, edge);
          const auto found = locator.locate(x);
          ASSERT_TRUE(found.has_value())
              << to_string(type) << " cell " << c << " " << x.transpose();
          EXPECT_LT((map_to_physical(mesh, found->cell, found->xi) - x).norm(), 1e-10);
        }
    }
  }
}

TEST(PointLocatorTest, ReturnsNulloptOutsideTheMesh) {
  for (CellType type : all_cell_types) {
    const Mesh mesh = testing::uniform_mesh(type, 3);
    const PointLocator locator(mesh);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const Vec3& x : {Vec3(-1e-6, 0.5, 0.5), Vec3(0.5, 1.0 + 1e-6, 0.5), Vec3(5, 5, 5),
                          Vec3(-100, -100, -100), Vec3(nan, 0.5, 0.5)}) {
      EXPECT_FALSE(locator.locate(x).has_value()) << to_string(type) << " " << x.transpose();
      EXPECT_FALSE(locator.locate(x, 0).has_value()) << to_string(type) << " with a hint";
    }
    if (mesh.dim() == 3) {
      EXPECT_FALSE(locator.locate(Vec3(0.5, 0.5, 1.0 + 1e-6)).has_value()) << to_string(type);
    }
  }
}

TEST(PointLocatorTest, NonConvexDomainHasHolesThatAreOutside) {
  // An L-shaped mesh: the cells of the upper-right quarter removed.
  Mesh full = testing::uniform_mesh(CellType::Quad4, 4);
  Mesh mesh = full;
  mesh.connectivity.clear();
  for (Index c = 0; c < full.num_cells(); ++c) {
    const Vec3 centre = map_to_physical(full, c, Vec3::Zero());
    if (centre[0] > 0.5 && centre[1] > 0.5) continue;
    for (Index n : full.cell_nodes(c)) mesh.connectivity.push_back(n);
  }
  const PointLocator locator(mesh);
  EXPECT_FALSE(locator.locate(Vec3(0.75, 0.75, 0)).has_value());
  EXPECT_TRUE(locator.locate(Vec3(0.25, 0.75, 0)).has_value());
  EXPECT_TRUE(locator.locate(Vec3(0.5, 0.5, 0)).has_value());  // the re-entrant corner
}

TEST(PointLocatorTest, HintsAreUsedButNeverTrusted) {
  const Mesh mesh = testing::distorted_mesh(CellType::Quad4, 10, 4);
  const PointLocator locator(mesh);
  std::mt19937 rng(9);
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const Vec3 x = map_to_physical(mesh, c, Vec3(0.3, -0.6, 0.0));
    const auto near = locator.locate(x, c == 0 ? 1 : c - 1);  // a neighbour as the hint
    const auto far = locator.locate(x, mesh.num_cells() - 1 - c);
    const auto bad = locator.locate(x, mesh.num_cells() + 5);  // out of range: ignored
    const auto exact = locator.locate(x, c);
    for (const auto& found : {near, far, bad, exact}) {
      ASSERT_TRUE(found.has_value());
      EXPECT_EQ(found->cell, c);
      EXPECT_LT((found->xi - Vec3(0.3, -0.6, 0.0)).norm(), 1e-10);
    }
  }
}

TEST(PointLocatorTest, ConcurrentQueriesGiveTheSameAnswers) {
  const Mesh mesh = testing::distorted_mesh(CellType::Tri6, 10, 5);
  const PointLocator locator(mesh);
  const std::vector<Vec3> points = random_points(mesh, 20000, 4);
  std::vector<Index> serial(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    const auto found = locator.locate(points[k]);
    serial[k] = found ? found->cell : -1;
  }
  std::vector<std::vector<Index>> parallel(4, std::vector<Index>(points.size(), -2));
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      for (std::size_t k = 0; k < points.size(); ++k) {
        const auto found = locator.locate(points[k], t % 2 == 0 ? -1 : Index(k % 7));
        parallel[t][k] = found ? found->cell : -1;
      }
    });
  for (auto& thread : threads) thread.join();
  for (int t = 0; t < 4; t += 2) EXPECT_EQ(parallel[t], serial);
  // With hints a point on a shared face may land in the other cell, but never be lost.
  for (int t = 1; t < 4; t += 2)
    for (std::size_t k = 0; k < points.size(); ++k) EXPECT_EQ(parallel[t][k] < 0, serial[k] < 0);
}

TEST(PointLocatorTest, MillionQueriesOnA200By200Mesh) {
  // Exercises the bucket grid at scale (timing is left to bench/): every point is inside.
  const Mesh mesh = testing::uniform_mesh(CellType::Quad4, 200, Vec3(4.0, 2.0, 1.0));
  const PointLocator locator(mesh);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> x(0.0, 4.0), y(0.0, 2.0);
  Index found = 0, previous = -1;
  double checksum = 0.0;
  for (int k = 0; k < 1'000'000; ++k) {
    const auto location = locator.locate(Vec3(x(rng), y(rng), 0.0), previous);
    if (!location) continue;
    ++found;
    checksum += location->xi[0];
    previous = k % 2 == 0 ? location->cell : -1;  // half with a (useless) hint
  }
  EXPECT_EQ(found, 1'000'000);
  EXPECT_LT(std::abs(checksum) / found, 0.01);  // xi uniform in [-1, 1]: mean near 0
}

}  // namespace
}  // namespace geompm

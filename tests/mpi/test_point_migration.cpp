// Points between processes (points/point_exchange.hpp), run under mpirun with several processes
// (ctest -L mpi): after the cut, and after every point has moved to a cell far from its own, each
// process holds exactly the points of its cells, none is lost or duplicated, and each carries its
// own state (mass, position) along.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <numeric>

#include "geompm/mesh/partition.hpp"
#include "geompm/mesh/structured_mesh.hpp"
#include "geompm/points/point_exchange.hpp"
#include "mpi_world.hpp"

namespace geompm {
namespace {

// Four points per cell of a 12 x 6 block, point i of mass 1 + i / 1000.
MaterialPoints seed(const Mesh& mesh) {
  MaterialPoints points;
  for (Index c = 0; c < mesh.num_cells(); ++c)
    for (int k = 0; k < 4; ++k) {
      Vec3 x = Vec3::Zero();
      for (Index n : mesh.cell_nodes(c)) x += mesh.nodes[n] / 4.0;
      const Index p = points.add(0, 0, x, 1.0, 1.0, c, Vec3::Zero(), Vec3::Constant(0.1));
      points.mass[p] = 1.0 + p / 1000.0;
    }
  return points;
}

Mesh block() {
  StructuredMeshSpec spec;
  spec.axes[0] = {{2.0, 12, 1.0}};
  spec.axes[1] = {{1.0, 6, 1.0}};
  return generate_structured_mesh(spec);
}

void expect_whole(const MaterialPoints& points, const std::vector<int>& part, Index expected) {
  for (Index p = 0; p < points.size(); ++p)
    EXPECT_EQ(part[points.cell[p]], testing::world().rank());
  EXPECT_EQ(testing::world().sum(points.size()), expected);
  double mass = std::accumulate(points.mass.begin(), points.mass.end(), 0.0);
  testing::world().sum(&mass, 1);
  EXPECT_NEAR(mass, expected + (expected - 1) * expected / 2 / 1000.0, 1e-9);
  const MaterialPoints all = gather_points(points, testing::world());
  if (testing::world().rank() != 0) return;
  ASSERT_EQ(all.size(), expected);
  for (Index p = 0; p < all.size(); ++p) {
    EXPECT_EQ(all.id[p], p);  // ordered by id: each once
    EXPECT_DOUBLE_EQ(all.mass[p], 1.0 + p / 1000.0);
  }
}

TEST(PointMigration, EachProcessHoldsThePointsOfItsCells) {
  ASSERT_GE(testing::world().size(), 2) << "run under mpirun with 2 or more processes";
  const Mesh mesh = block();
  MaterialPoints points = seed(mesh);
  const Index n = points.size();
  std::vector<double> weight(mesh.num_cells(), 4.0);
  const std::vector<int> part = partition_cells(mesh, weight, testing::world().size());
  keep_own_points(points, part, testing::world().rank());
  EXPECT_GT(points.size(), 0);
  expect_whole(points, part, n);

  // Every point to the cell 6 columns and 2 rows on (as if convected far): the parts are slabs
  // of columns, so most points change process.
  Index leaving = 0;
  for (Index p = 0; p < points.size(); ++p) {
    points.cell[p] = (points.cell[p] + 2 * 12 + 6) % mesh.num_cells();
    points.position[p].x() += 1.0;
    leaving += part[points.cell[p]] != testing::world().rank();
  }
  const Index sent = migrate_points(points, part, testing::world());
  EXPECT_EQ(sent, leaving);
  EXPECT_GT(testing::world().sum(sent), n / 2);
  expect_whole(points, part, n);
  // The state travelled with the point: its position still says where it was seeded + 1.
  for (Index p = 0; p < points.size(); ++p)
    EXPECT_DOUBLE_EQ(points.position[p].x(), points.initial_position[p].x() + 1.0);
}

TEST(PointMigration, NothingMovesWhenNoPointChangesProcess) {
  const Mesh mesh = block();
  MaterialPoints points = seed(mesh);
  const std::vector<int> part =
      partition_cells(mesh, std::vector<double>(mesh.num_cells(), 4.0), testing::world().size());
  keep_own_points(points, part, testing::world().rank());
  const std::vector<Index> ids = points.id;
  EXPECT_EQ(testing::world().sum(migrate_points(points, part, testing::world())), 0);
  EXPECT_EQ(points.id, ids);
}

}  // namespace
}  // namespace geompm

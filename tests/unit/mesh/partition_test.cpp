// The cut of the background mesh into one part per process (mesh/partition.hpp): every cell owned
// once, the parts' weights balanced, nodes owned by the lowest owner of their cells, and the
// ghost layer exactly the cells that share a node with a part's own cells.
#include "geompm/mesh/partition.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "geompm/mesh/structured_mesh.hpp"

namespace geompm {
namespace {

Mesh block(CellType type, int nx, int ny, int nz = 0) {
  StructuredMeshSpec spec;
  spec.cell_type = type;
  spec.axes[0] = {{2.0, nx, 1.0}};
  spec.axes[1] = {{1.0, ny, 1.0}};
  if (nz > 0) spec.axes[2] = {{1.0, nz, 1.0}};
  return generate_structured_mesh(spec);
}

std::vector<double> part_weights(const std::vector<int>& part, const std::vector<double>& w,
                                 int parts) {
  std::vector<double> sum(parts, 0.0);
  for (std::size_t c = 0; c < part.size(); ++c) sum[part[c]] += w[c];
  return sum;
}

TEST(PartitionTest, EveryCellOwnedOnceAndEqualWeightsBalanced) {
  for (const int parts : {1, 2, 3, 4, 7}) {
    const Mesh mesh = block(CellType::Quad4, 40, 20);
    const std::vector<double> weights(mesh.num_cells(), 4.0);  // 4 points in every cell
    const std::vector<int> part = partition_cells(mesh, weights, parts);
    ASSERT_EQ(part.size(), std::size_t(mesh.num_cells()));
    for (int p : part) {
      EXPECT_GE(p, 0);
      EXPECT_LT(p, parts);
    }
    // 800 cells: each part within one cell's weight of the even share.
    const auto sum = part_weights(part, weights, parts);
    for (double s : sum) EXPECT_NEAR(s, 4.0 * 800 / parts, 4.0 + 1e-9) << parts;
  }
}

TEST(PartitionTest, WeightsFollowThePointsNotTheCells) {
  // Points only in the lower half of the mesh: both parts get half of them, not half the cells.
  const Mesh mesh = block(CellType::Quad4, 20, 20);
  std::vector<double> weights(mesh.num_cells(), 0.0);
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    Vec3 centre = Vec3::Zero();
    for (Index n : mesh.cell_nodes(c)) centre += mesh.nodes[n] / 4.0;
    if (centre.y() < 0.5) weights[c] = 4.0;
  }
  const std::vector<int> part = partition_cells(mesh, weights, 2);
  const auto sum = part_weights(part, weights, 2);
  EXPECT_NEAR(sum[0], sum[1], 2 * 4.0);
  EXPECT_GT(sum[0], 0.0);
}

TEST(PartitionTest, NodeOwnerIsTheLowestPartOfItsCells) {
  const Mesh mesh = block(CellType::Tri3, 12, 9);
  const std::vector<int> part =
      partition_cells(mesh, std::vector<double>(mesh.num_cells(), 1.0), 3);
  const std::vector<int> owner = node_owners(mesh, part);
  std::vector<int> expected(mesh.num_nodes(), 99);
  for (Index c = 0; c < mesh.num_cells(); ++c)
    for (Index n : mesh.cell_nodes(c)) expected[n] = std::min(expected[n], part[c]);
  EXPECT_EQ(owner, expected);
  EXPECT_EQ(*std::min_element(owner.begin(), owner.end()), 0);
}

TEST(PartitionTest, GhostLayerIsEveryNeighbourOfTheOwnCells) {
  const Mesh mesh = block(CellType::Hex8, 6, 5, 4);
  const MeshTopology topology = build_mesh_topology(mesh);
  const std::vector<int> part =
      partition_cells(mesh, std::vector<double>(mesh.num_cells(), 1.0), 3);
  for (int p = 0; p < 3; ++p) {
    const std::vector<Index> ghosts = ghost_cells(topology, part, p, 1);
    // Brute force: a cell not owned by p that shares a node with one of p's cells.
    std::set<Index> expected;
    for (Index c = 0; c < mesh.num_cells(); ++c) {
      if (part[c] == p) continue;
      for (Index d = 0; d < mesh.num_cells() && !expected.count(c); ++d) {
        if (part[d] != p) continue;
        for (Index a : mesh.cell_nodes(c))
          for (Index b : mesh.cell_nodes(d))
            if (a == b) expected.insert(c);
      }
    }
    EXPECT_EQ(std::set<Index>(ghosts.begin(), ghosts.end()), expected) << p;
    EXPECT_FALSE(ghosts.empty());
    // Two layers hold one and more.
    const std::vector<Index> two = ghost_cells(topology, part, p, 2);
    EXPECT_GT(two.size(), ghosts.size());
    for (Index g : ghosts) EXPECT_TRUE(std::binary_search(two.begin(), two.end(), g));
  }
}

}  // namespace
}  // namespace geompm

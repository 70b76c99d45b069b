// Generation of graded rectangle and box meshes.
#include "geompm/mesh/structured_mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <stdexcept>

#include "geompm/mesh/cell_geometry.hpp"
#include "mesh_test_support.hpp"

namespace geompm {
namespace {

using testing::all_cell_types;

TEST(AxisCoordinatesTest, UniformSegment) {
  const std::vector<double> x = axis_coordinates(2.0, {{3.0, 6, 1.0}});
  ASSERT_EQ(x.size(), 7u);
  for (int i = 0; i <= 6; ++i) EXPECT_NEAR(x[i], 2.0 + 0.5 * i, 1e-14);
}

TEST(AxisCoordinatesTest, GradingRatioIsLastOverFirstCellSize) {
  for (double ratio : {0.1, 0.5, 2.0, 8.0, 30.0}) {
    const std::vector<double> x = axis_coordinates(-1.0, {{4.0, 9, ratio}});
    ASSERT_EQ(x.size(), 10u);
    const double first = x[1] - x[0], last = x[9] - x[8];
    EXPECT_NEAR(last / first, ratio, 1e-10 * ratio) << ratio;
    EXPECT_DOUBLE_EQ(x.back(), 3.0);
    // Sizes grow (or shrink) by the same factor from cell to cell.
    const double q = (x[2] - x[1]) / first;
    for (int i = 1; i < 9; ++i) EXPECT_NEAR((x[i + 1] - x[i]) / (x[i] - x[i - 1]), q, 1e-10);
  }
}

TEST(AxisCoordinatesTest, SegmentsFollowEachOther) {
  const std::vector<double> x =
      axis_coordinates(0.0, {{1.0, 4, 0.25}, {2.0, 1, 5.0}, {3.0, 3, 1.0}});
  ASSERT_EQ(x.size(), 9u);
  EXPECT_DOUBLE_EQ(x[4], 1.0);
  EXPECT_DOUBLE_EQ(x[5], 3.0);  // one cell: the ratio has no effect
  EXPECT_DOUBLE_EQ(x[8], 6.0);
  EXPECT_NEAR((x[4] - x[3]) / (x[1] - x[0]), 0.25, 1e-12);
  EXPECT_TRUE(std::is_sorted(x.begin(), x.end()));
}

TEST(AxisCoordinatesTest, RejectsBadSegments) {
  EXPECT_THROW(axis_coordinates(0.0, {}), std::invalid_argument);
  EXPECT_THROW(axis_coordinates(0.0, {{1.0, 0, 1.0}}), std::invalid_argument);
  EXPECT_THROW(axis_coordinates(0.0, {{0.0, 2, 1.0}}), std::invalid_argument);
  EXPECT_THROW(axis_coordinates(0.0, {{-1.0, 2, 1.0}}), std::invalid_argument);
  EXPECT_THROW(axis_coordinates(0.0, {{1.0, 2, 0.0}}), std::invalid_argument);
  EXPECT_THROW(axis_coordinates(0.0, {{1.0, 2, -2.0}}), std::invalid_argument);
}

TEST(StructuredMeshTest, RejectsMissingOrBadAxes) {
  StructuredMeshSpec spec;
  spec.cell_type = CellType::Quad4;
  spec.axes[0] = {{1.0, 2, 1.0}};
  EXPECT_THROW(generate_structured_mesh(spec), std::invalid_argument);  // no y axis
  spec.axes[1] = {{1.0, 2, 1.0}};
  EXPECT_NO_THROW(generate_structured_mesh(spec));
  spec.cell_type = CellType::Hex8;
  EXPECT_THROW(generate_structured_mesh(spec), std::invalid_argument);  // no z axis
  spec.axes[2] = {{1.0, 0, 1.0}};
  EXPECT_THROW(generate_structured_mesh(spec), std::invalid_argument);
  spec.axes[2] = {{1.0, 1, 1.0}};
  EXPECT_NO_THROW(generate_structured_mesh(spec));
}

StructuredMeshSpec graded_spec(CellType type) {
  StructuredMeshSpec spec;
  spec.cell_type = type;
  spec.origin = Vec3(1.0, -2.0, 3.0);
  spec.axes[0] = {{2.0, 3, 2.0}, {1.0, 2, 1.0}};  // 5 cells
  spec.axes[1] = {{1.5, 4, 0.5}};                 // 4 cells
  spec.axes[2] = {{1.0, 3, 3.0}};                 // 3 cells
  return spec;
}

TEST(StructuredMeshTest, CountsOfNodesAndCells) {
  const std::map<CellType, std::array<Index, 2>> expected = {
      {CellType::Quad4, {6 * 5, 5 * 4}},
      {CellType::Tri3, {6 * 5, 2 * 5 * 4}},
      {CellType::Tri6, {11 * 9, 2 * 5 * 4}},
      {CellType::Hex8, {6 * 5 * 4, 5 * 4 * 3}},
      {CellType::Tet4, {6 * 5 * 4, 6 * 5 * 4 * 3}}};
  for (const auto& [type, counts] : expected) {
    const Mesh mesh = generate_structured_mesh(graded_spec(type));
    EXPECT_EQ(mesh.cell_type, type);
    EXPECT_EQ(mesh.num_nodes(), counts[0]) << to_string(type);
    EXPECT_EQ(mesh.num_cells(), counts[1]) << to_string(type);
  }
}

TEST(StructuredMeshTest, CellsArePositivelyOrientedAndEveryNodeIsUsed) {
  for (CellType type : all_cell_types) {
    const Mesh mesh = generate_structured_mesh(graded_spec(type));
    EXPECT_NO_THROW(validate_mesh(mesh, "generated")) << to_string(type);
    for (Index c = 0; c < mesh.num_cells(); ++c)
      EXPECT_GT(cell_min_relative_jacobian(mesh, c), 0.0) << to_string(type) << " " << c;
    std::vector<char> used(mesh.nodes.size(), 0);
    for (Index n : mesh.connectivity) used[n] = 1;
    EXPECT_EQ(std::count(used.begin(), used.end(), 1), mesh.num_nodes()) << to_string(type);
  }
}

TEST(StructuredMeshTest, NoTwoNodesCoincide) {
  for (CellType type : all_cell_types) {
    const Mesh mesh = generate_structured_mesh(graded_spec(type));
    std::set<std::array<double, 3>> distinct;
    for (const Vec3& x : mesh.nodes) distinct.insert({x[0], x[1], x[2]});
    EXPECT_EQ(distinct.size(), mesh.nodes.size()) << to_string(type);
  }
}

/// Faces (2D: edges) by their sorted corner node ids, with how many cells hold each.
std::map<std::vector<Index>, int> count_faces(const Mesh& mesh) {
  std::vector<std::vector<int>> faces;
  switch (mesh.cell_type) {
    case CellType::Tri3:
    case CellType::Tri6:
      faces = {{0, 1}, {1, 2}, {2, 0}};
      break;
    case CellType::Quad4:
      faces = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
      break;
    case CellType::Tet4:
      faces = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
      break;
    case CellType::Hex8:
      faces = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
      break;
  }
  std::map<std::vector<Index>, int> count;
  for (Index c = 0; c < mesh.num_cells(); ++c)
    for (const auto& face : faces) {
      std::vector<Index> key;
      for (int a : face) key.push_back(mesh.cell_nodes(c)[a]);
      std::sort(key.begin(), key.end());
      ++count[key];
    }
  return count;
}

TEST(StructuredMeshTest, MeshesAreConforming) {
  // Every face is shared by two cells, or lies on the boundary of the box.
  for (CellType type : all_cell_types) {
    const Mesh mesh = generate_structured_mesh(graded_spec(type));
    const Vec3 lower = graded_spec(type).origin, upper = lower + Vec3(3.0, 1.5, 1.0);
    for (const auto& [face, cells] : count_faces(mesh)) {
      ASSERT_LE(cells, 2) << to_string(type);
      if (cells == 2) continue;
      bool on_boundary = false;
      for (int i = 0; i < mesh.dim(); ++i) {
        bool all_at_lower = true, all_at_upper = true;
        for (Index n : face) {
          all_at_lower &= std::abs(mesh.nodes[n][i] - lower[i]) < 1e-12;
          all_at_upper &= std::abs(mesh.nodes[n][i] - upper[i]) < 1e-12;
        }
        on_boundary |= all_at_lower || all_at_upper;
      }
      EXPECT_TRUE(on_boundary) << to_string(type) << ": a hanging face inside the mesh";
    }
  }
}

TEST(StructuredMeshTest, Tri6MidSideNodesAreSharedEdgeMidpoints) {
  const Mesh mesh = generate_structured_mesh(graded_spec(CellType::Tri6));
  constexpr int ends[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  std::map<std::pair<Index, Index>, Index> mid_of_edge;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const auto nodes = mesh.cell_nodes(c);
    for (int e = 0; e < 3; ++e) {
      const Index a = nodes[ends[e][0]], b = nodes[ends[e][1]], mid = nodes[3 + e];
      EXPECT_LT((mesh.nodes[mid] - 0.5 * (mesh.nodes[a] + mesh.nodes[b])).norm(), 1e-14);
      const auto [it, inserted] = mid_of_edge.emplace(std::minmax(a, b), mid);
      if (!inserted) {
        EXPECT_EQ(it->second, mid) << "edge with two mid-side nodes";
      }
    }
  }
}

TEST(StructuredMeshTest, TrianglesAlternateTheirDiagonals) {
  const Mesh mesh = testing::uniform_mesh(CellType::Tri3, 2);
  // Rectangle (0,0) splits along node 0 - node 4, its neighbour (1,0) along node 2 - node 4.
  const auto faces = count_faces(mesh);
  EXPECT_EQ(faces.count({0, 4}), 1u);
  EXPECT_EQ(faces.count({2, 4}), 1u);
  EXPECT_EQ(faces.count({1, 3}), 0u);
}

TEST(StructuredMeshTest, BoundaryGroupsHoldExactlyTheNodesOnEachSide) {
  for (CellType type : all_cell_types) {
    const StructuredMeshSpec spec = graded_spec(type);
    const Mesh mesh = generate_structured_mesh(spec);
    const Vec3 lower = spec.origin, upper = lower + Vec3(3.0, 1.5, 1.0);
    const bool three_d = mesh.dim() == 3;
    struct Side {
      const char* name;
      int axis;
      double at;
    };
    std::vector<Side> sides = {{"left", 0, lower[0]}, {"right", 0, upper[0]}};
    if (three_d) {
      sides.insert(sides.end(), {{"front", 1, lower[1]},
                                 {"back", 1, upper[1]},
                                 {"bottom", 2, lower[2]},
                                 {"top", 2, upper[2]}});
    } else {
      sides.insert(sides.end(), {{"bottom", 1, lower[1]}, {"top", 1, upper[1]}});
    }
    EXPECT_EQ(mesh.node_groups.size(), sides.size()) << to_string(type);
    for (const Side& side : sides) {
      ASSERT_TRUE(mesh.node_groups.count(side.name)) << to_string(type) << " " << side.name;
      std::vector<Index> expected;
      for (Index n = 0; n < mesh.num_nodes(); ++n)
        if (std::abs(mesh.nodes[n][side.axis] - side.at) < 1e-12) expected.push_back(n);
      EXPECT_EQ(mesh.node_groups.at(side.name), expected) << to_string(type) << " " << side.name;
    }
    ASSERT_TRUE(mesh.cell_groups.count("all"));
    EXPECT_EQ(static_cast<Index>(mesh.cell_groups.at("all").size()), mesh.num_cells());
    EXPECT_TRUE(
        std::is_sorted(mesh.cell_groups.at("all").begin(), mesh.cell_groups.at("all").end()));
  }
}

TEST(StructuredMeshTest, TwoDimensionalNodesLieInThePlane) {
  for (CellType type : {CellType::Tri3, CellType::Tri6, CellType::Quad4}) {
    const Mesh mesh = generate_structured_mesh(graded_spec(type));
    for (const Vec3& x : mesh.nodes) EXPECT_EQ(x[2], 0.0);
  }
}

}  // namespace
}  // namespace geompm

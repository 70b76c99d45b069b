// Generation of graded rectangle and box meshes.
#include "geompm/mesh/structured_mesh.hpp"

#include <gtest/gtest.h>

#include <Eigen/QR>

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

/// The graded meshes of every cell type, and Tri3 with crossed diagonals.
std::vector<StructuredMeshSpec> every_graded_spec() {
  std::vector<StructuredMeshSpec> specs;
  for (CellType type : all_cell_types) specs.push_back(graded_spec(type));
  specs.push_back(graded_spec(CellType::Tri3));
  specs.back().diagonals = Diagonals::Crossed;
  return specs;
}

std::string describe(const StructuredMeshSpec& spec) {
  return std::string(to_string(spec.cell_type)) +
         (spec.diagonals == Diagonals::Crossed ? " (crossed)" : "");
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
  // Crossed diagonals: a node at each rectangle's centre, four triangles around it.
  StructuredMeshSpec crossed = graded_spec(CellType::Tri3);
  crossed.diagonals = Diagonals::Crossed;
  const Mesh mesh = generate_structured_mesh(crossed);
  EXPECT_EQ(mesh.num_nodes(), 6 * 5 + 5 * 4);
  EXPECT_EQ(mesh.num_cells(), 4 * 5 * 4);
}

TEST(StructuredMeshTest, CellsArePositivelyOrientedAndEveryNodeIsUsed) {
  for (const StructuredMeshSpec& spec : every_graded_spec()) {
    const Mesh mesh = generate_structured_mesh(spec);
    EXPECT_NO_THROW(validate_mesh(mesh, "generated")) << describe(spec);
    for (Index c = 0; c < mesh.num_cells(); ++c)
      EXPECT_GT(cell_min_relative_jacobian(mesh, c), 0.0) << describe(spec) << " " << c;
    std::vector<char> used(mesh.nodes.size(), 0);
    for (Index n : mesh.connectivity) used[n] = 1;
    EXPECT_EQ(std::count(used.begin(), used.end(), 1), mesh.num_nodes()) << describe(spec);
  }
}

TEST(StructuredMeshTest, NoTwoNodesCoincide) {
  for (const StructuredMeshSpec& spec : every_graded_spec()) {
    const Mesh mesh = generate_structured_mesh(spec);
    std::set<std::array<double, 3>> distinct;
    for (const Vec3& x : mesh.nodes) distinct.insert({x[0], x[1], x[2]});
    EXPECT_EQ(distinct.size(), mesh.nodes.size()) << describe(spec);
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
    case CellType::Pyramid5:  // not generated
      faces = {{0, 1, 2, 3}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
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
  for (const StructuredMeshSpec& spec : every_graded_spec()) {
    const Mesh mesh = generate_structured_mesh(spec);
    const Vec3 lower = spec.origin, upper = lower + Vec3(3.0, 1.5, 1.0);
    for (const auto& [face, cells] : count_faces(mesh)) {
      ASSERT_LE(cells, 2) << describe(spec);
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
      EXPECT_TRUE(on_boundary) << describe(spec) << ": a hanging face inside the mesh";
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

TEST(StructuredMeshTest, CrossedDiagonalsMeetAtEachRectanglesCentre) {
  StructuredMeshSpec spec = graded_spec(CellType::Tri3);
  spec.diagonals = Diagonals::Crossed;
  const Mesh mesh = generate_structured_mesh(spec);
  const Mesh corners = generate_structured_mesh(graded_spec(CellType::Quad4));
  ASSERT_EQ(mesh.num_cells(), 4 * corners.num_cells());
  for (Index r = 0; r < corners.num_cells(); ++r) {
    Vec3 centre = Vec3::Zero();
    for (Index n : corners.cell_nodes(r)) centre += 0.25 * corners.nodes[n];
    double area = 0.0;
    for (Index t = 4 * r; t < 4 * r + 4; ++t) {
      const auto nodes = mesh.cell_nodes(t);
      EXPECT_LT((mesh.nodes[nodes[2]] - centre).norm(), 1e-14);  // the shared centre node
      const Vec3 a = mesh.nodes[nodes[1]] - mesh.nodes[nodes[0]];
      const Vec3 b = mesh.nodes[nodes[2]] - mesh.nodes[nodes[0]];
      area += 0.5 * (a.x() * b.y() - a.y() * b.x());
    }
    const Vec3 d =
        corners.nodes[corners.cell_nodes(r)[2]] - corners.nodes[corners.cell_nodes(r)[0]];
    EXPECT_NEAR(area, d.x() * d.y(), 1e-13);  // the four tile their rectangle
  }
}

/// The dimension of the space of nodal velocities, zero on the boundary, under which every cell
/// keeps its volume: the velocities the constant-strain triangles leave to an incompressible
/// (or, plastically, a constantly dilating) flow. Zero means the mesh locks.
Index incompressible_velocity_fields(const Mesh& mesh) {
  const std::vector<char> fixed = testing::boundary_nodes(mesh);
  std::vector<Index> unknown(mesh.nodes.size(), -1);
  Index count = 0;
  for (Index n = 0; n < mesh.num_nodes(); ++n)
    if (!fixed[n]) unknown[n] = count++;
  Eigen::MatrixXd divergence = Eigen::MatrixXd::Zero(mesh.num_cells(), 2 * count);
  using E = Element<CellType::Tri3>;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    Eigen::Matrix<double, 3, 2> X;
    for (int a = 0; a < 3; ++a) X.row(a) = mesh.nodes[mesh.cell_nodes(c)[a]].head<2>().transpose();
    const E::Gradients dN = E::shape_gradients(E::centroid());
    const Eigen::Matrix<double, 3, 2> grad = dN * (X.transpose() * dN).inverse();
    for (int a = 0; a < 3; ++a)
      if (const Index u = unknown[mesh.cell_nodes(c)[a]]; u >= 0) {
        divergence(c, 2 * u) = grad(a, 0);
        divergence(c, 2 * u + 1) = grad(a, 1);
      }
  }
  return 2 * count - Eigen::ColPivHouseholderQR<Eigen::MatrixXd>(divergence).rank();
}

TEST(StructuredMeshTest, TrianglesLeaveIncompressibleFlowFree) {
  // Nagtegaal, Parks & Rice (1974): a mesh locks when its cells' constant-volume constraints
  // leave no velocity field but rest. On an N x N grid with the boundary held, constant-strain
  // triangles with one diagonal per rectangle have 2N^2 constraints on 2(N-1)^2 velocities, but
  // the generated diagonals alternate, so every 2 x 2 block of rectangles is a union jack of
  // eight triangles around its centre node, and at such a node the constraints are dependent.
  // Crossed diagonals make every rectangle a union jack of four, whose constraints satisfy
  // one relation (the alternating sum of the four volume changes vanishes). The counts are
  // measured: (N - 2)^2 incompressible flows crossed, 2 (N/2 - 1)(N/2 - 2) alternating; both grow
  // like the number of cells, so neither pattern locks (docs/theory.md §15). With the centre node
  // off the diagonals' crossing a rectangle's four constraints are independent.
  for (int n : {4, 6, 8}) {
    StructuredMeshSpec spec;
    spec.cell_type = CellType::Tri3;
    spec.axes[0] = {{2.0, n, 1.0}};
    spec.axes[1] = {{1.0, n, 1.0}};
    const Mesh alternating = generate_structured_mesh(spec);
    spec.diagonals = Diagonals::Crossed;
    const Mesh crossed = generate_structured_mesh(spec);
    EXPECT_EQ(incompressible_velocity_fields(alternating), 2 * (n / 2 - 1) * (n / 2 - 2)) << n;
    EXPECT_EQ(incompressible_velocity_fields(crossed), (n - 2) * (n - 2)) << n;
  }
}

TEST(StructuredMeshTest, CrossedDiagonalsNeedTri3Cells) {
  for (CellType type : {CellType::Tri6, CellType::Quad4, CellType::Tet4, CellType::Hex8}) {
    StructuredMeshSpec spec = graded_spec(type);
    spec.diagonals = Diagonals::Crossed;
    EXPECT_THROW(generate_structured_mesh(spec), std::invalid_argument) << to_string(type);
  }
}

TEST(StructuredMeshTest, BoundaryGroupsHoldExactlyTheNodesOnEachSide) {
  for (const StructuredMeshSpec& spec : every_graded_spec()) {
    const CellType type = spec.cell_type;
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

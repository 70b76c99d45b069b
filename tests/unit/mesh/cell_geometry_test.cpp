// The isoparametric map of a cell, its inverse, measures and mesh validation.
#include "geompm/mesh/cell_geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "geompm/core/error.hpp"
#include "mesh_test_support.hpp"

namespace geompm {
namespace {

using testing::all_cell_types;
using testing::distorted_mesh;
using testing::total_measure;
using testing::uniform_mesh;

/// Random reference point of the cell type, as a Vec3 (unused entries zero).
Vec3 random_reference(CellType type, std::mt19937& rng) {
  return dispatch_cell_type(type, [&](auto element) {
    Vec3 xi = Vec3::Zero();
    xi.head<decltype(element)::dim>() =
        testing::random_reference_point<cell_type_of<decltype(element)>>(rng);
    return xi;
  });
}

std::string expect_input_error(const Mesh& mesh, const std::string& source) {
  try {
    validate_mesh(mesh, source);
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "validate_mesh accepted a bad mesh";
  return "";
}

TEST(CellGeometryTest, MapToReferenceInvertsMapToPhysicalOnDistortedCells) {
  std::mt19937 rng(11);
  for (CellType type : all_cell_types) {
    const Mesh mesh = distorted_mesh(type, 4);
    ASSERT_NO_THROW(validate_mesh(mesh, "distorted"));
    for (Index c = 0; c < mesh.num_cells(); ++c)
      for (int k = 0; k < 10; ++k) {
        const Vec3 xi = random_reference(type, rng);
        const Vec3 x = map_to_physical(mesh, c, xi);
        const auto back = map_to_reference(mesh, c, x);
        ASSERT_TRUE(back.has_value()) << to_string(type) << " cell " << c;
        EXPECT_LT((*back - xi).norm(), 1e-10) << to_string(type) << " cell " << c;
        Vec3 found;
        EXPECT_TRUE(cell_contains(mesh, c, x, found)) << to_string(type) << " cell " << c;
        EXPECT_LT((found - xi).norm(), 1e-10);
      }
  }
}

TEST(CellGeometryTest, MapToReferenceOfCurvedTri6) {
  // One triangle with a strongly curved edge 1-2 (its mid-side node pushed outwards).
  Mesh mesh;
  mesh.cell_type = CellType::Tri6;
  mesh.nodes = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 0, 0}, {1.3, 1.3, 0}, {0, 1, 0}};
  mesh.connectivity = {0, 1, 2, 3, 4, 5};
  ASSERT_NO_THROW(validate_mesh(mesh, "curved"));
  std::mt19937 rng(5);
  for (int k = 0; k < 200; ++k) {
    const Vec3 xi = random_reference(CellType::Tri6, rng);
    const auto back = map_to_reference(mesh, 0, map_to_physical(mesh, 0, xi));
    ASSERT_TRUE(back.has_value());
    EXPECT_LT((*back - xi).norm(), 1e-10);
  }
  // The bulge beyond the straight edge x + y = 2 belongs to the cell...
  Vec3 xi;
  EXPECT_TRUE(cell_contains(mesh, 0, Vec3(1.1, 1.1, 0), xi));
  // ... and its area is the triangle's (2) plus the parabolic segment (2/3 * base * height).
  const double bulge = 2.0 / 3.0 * std::sqrt(8.0) * (0.3 * std::sqrt(2.0));
  EXPECT_NEAR(cell_measure(mesh, 0), 2.0 + bulge, 1e-12);
}

TEST(CellGeometryTest, CurvedTri6BulgeBeyondItsNodesIsInsideTheCellAndItsBox) {
  // Edge 1-2 from (2, 0) to (0, 2) with its mid-side node at (1.6, 1.2): the edge reaches
  // x = 2 + 1/60 near its start, beyond every node.
  Mesh mesh;
  mesh.cell_type = CellType::Tri6;
  mesh.nodes = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 0, 0}, {1.6, 1.2, 0}, {0, 1, 0}};
  mesh.connectivity = {0, 1, 2, 3, 4, 5};
  ASSERT_NO_THROW(validate_mesh(mesh, "curved"));
  const auto [lower, upper] = cell_bounding_box(mesh, 0);
  EXPECT_GE(upper[0], 2.0 + 1.0 / 60.0 - 1e-12);
  std::mt19937 rng(8);
  for (int k = 0; k < 1000; ++k) {
    const Vec3 x = map_to_physical(mesh, 0, random_reference(CellType::Tri6, rng));
    EXPECT_TRUE((x.array() >= lower.array()).all() && (x.array() <= upper.array()).all());
  }
  Vec3 xi;
  EXPECT_TRUE(cell_contains(mesh, 0, Vec3(2.01, 0.228, 0), xi));
  EXPECT_FALSE(cell_contains(mesh, 0, Vec3(2.03, 0.228, 0), xi));
}

TEST(CellGeometryTest, CellContainsRejectsPointsOutside) {
  for (CellType type : all_cell_types) {
    const Mesh mesh = uniform_mesh(type, 1);
    Vec3 xi;
    EXPECT_FALSE(cell_contains(mesh, 0, Vec3(1.5, 0.5, 0.5), xi)) << to_string(type);
    EXPECT_FALSE(cell_contains(mesh, 0, Vec3(-1e-6, 0.5, 0.5), xi)) << to_string(type);
    EXPECT_FALSE(cell_contains(mesh, 0, Vec3(40.0, -30.0, 25.0), xi)) << to_string(type);
  }
}

TEST(CellGeometryTest, CellContainsFindsPointsOnTheCellBoundary) {
  std::mt19937 rng(12);
  for (CellType type : all_cell_types) {
    const Mesh mesh = distorted_mesh(type, 3);
    for (Index c = 0; c < mesh.num_cells(); ++c) {
      Vec3 xi;
      for (Index n : mesh.cell_nodes(c))
        EXPECT_TRUE(cell_contains(mesh, c, mesh.nodes[n], xi)) << to_string(type) << " " << c;
      for (const Vec3& edge : testing::reference_edge_points(type, 5, rng))
        EXPECT_TRUE(cell_contains(mesh, c, map_to_physical(mesh, c, edge), xi))
            << to_string(type) << " " << c << " at " << edge.transpose();
    }
  }
}

TEST(CellGeometryTest, MeasuresSumToTheDomainForEveryType) {
  for (CellType type : all_cell_types) {
    StructuredMeshSpec spec;
    spec.cell_type = type;
    spec.origin = Vec3(-1.0, 2.0, 0.5);
    spec.axes[0] = {{1.5, 3, 2.0}, {2.5, 4, 0.5}};
    spec.axes[1] = {{3.0, 5, 3.0}};
    spec.axes[2] = {{0.5, 2, 1.0}, {1.5, 3, 4.0}};
    Mesh mesh = generate_structured_mesh(spec);
    const double expected = cell_dimension(type) == 2 ? 4.0 * 3.0 : 4.0 * 3.0 * 2.0;
    EXPECT_NEAR(total_measure(mesh), expected, 1e-12) << to_string(type);
    // Moving interior nodes (and curving Tri6 edges) keeps the total.
    testing::perturb_interior_nodes(mesh, 0.05, 0.01, 3);
    ASSERT_NO_THROW(validate_mesh(mesh, "perturbed"));
    EXPECT_NEAR(total_measure(mesh), expected, 1e-12) << to_string(type) << " perturbed";
  }
}

TEST(CellGeometryTest, RadialMeasureIsTheIntegralOfTheRadius) {
  // Rectangle r in [0.5, 3], y in [-1, 1]: int r dA = (3^2 - 0.5^2) / 2 * 2.
  const double expected = (9.0 - 0.25) / 2.0 * 2.0;
  for (CellType type : {CellType::Tri3, CellType::Tri6, CellType::Quad4}) {
    StructuredMeshSpec spec;
    spec.cell_type = type;
    spec.origin = Vec3(0.5, -1.0, 0.0);
    spec.axes[0] = {{2.5, 7, 3.0}};
    spec.axes[1] = {{2.0, 4, 1.0}};
    Mesh mesh = generate_structured_mesh(spec);
    EXPECT_NEAR(total_measure(mesh, true), expected, 1e-12) << to_string(type);
    testing::perturb_interior_nodes(mesh, 0.08, 0.02, 9);
    EXPECT_NEAR(total_measure(mesh, true), expected, 1e-12) << to_string(type) << " perturbed";
  }
}

TEST(CellGeometryTest, RadialMeasureOfOneQuadMatchesClosedForm) {
  // A trapezoid, where x det J is biquadratic: int x dA over x in [1, 3], 0 <= y <= x.
  Mesh mesh;
  mesh.cell_type = CellType::Quad4;
  mesh.nodes = {{1, 0, 0}, {3, 0, 0}, {3, 3, 0}, {1, 1, 0}};
  mesh.connectivity = {0, 1, 2, 3};
  EXPECT_NEAR(cell_measure(mesh, 0), 4.0, 1e-14);               // int_1^3 x dx
  EXPECT_NEAR(cell_measure(mesh, 0, true), 26.0 / 3.0, 1e-13);  // int_1^3 x^2 dx
}

TEST(CellGeometryTest, MinRelativeJacobianIsOneForAffineCellsAndLowerWhenDistorted) {
  for (CellType type : all_cell_types) {
    const Mesh regular = uniform_mesh(type, 2);
    for (Index c = 0; c < regular.num_cells(); ++c)
      EXPECT_NEAR(cell_min_relative_jacobian(regular, c), 1.0, 1e-12) << to_string(type);
  }
  Mesh kite;  // a strongly non-parallelogram quad: det J varies over the cell
  kite.cell_type = CellType::Quad4;
  kite.nodes = {{0, 0, 0}, {1, 0, 0}, {0.6, 0.6, 0}, {0, 1, 0}};
  kite.connectivity = {0, 1, 2, 3};
  const double relative = cell_min_relative_jacobian(kite, 0);
  EXPECT_GT(relative, 0.0);
  EXPECT_LT(relative, 0.9);
  kite.nodes[2] = {0.3, 0.3, 0};  // now re-entrant at node 2: det J < 0 there
  EXPECT_LT(cell_min_relative_jacobian(kite, 0), 0.0);
}

TEST(CellGeometryTest, ValidateMeshAcceptsGeneratedMeshes) {
  for (CellType type : all_cell_types)
    EXPECT_NO_THROW(validate_mesh(uniform_mesh(type, 3), "generated")) << to_string(type);
}

TEST(CellGeometryTest, ValidateMeshNamesTheInvertedCellAndItsNodes) {
  Mesh mesh = uniform_mesh(CellType::Quad4, 2);
  std::swap(mesh.connectivity[4 * 2 + 1], mesh.connectivity[4 * 2 + 3]);  // clockwise cell 2
  const std::string message = expect_input_error(mesh, "model.msh");
  EXPECT_NE(message.find("model.msh"), std::string::npos) << message;
  EXPECT_NE(message.find("cell 2 "), std::string::npos) << message;
  EXPECT_NE(message.find("(0, 0.5)"), std::string::npos) << message;  // a node of cell 2
  EXPECT_NE(message.find("counter-clockwise"), std::string::npos) << message;
}

TEST(CellGeometryTest, ValidateMeshRejectsInvertedCellsOfEveryType) {
  for (CellType type : all_cell_types) {
    Mesh mesh = uniform_mesh(type, 2);
    const int per_cell = mesh.nodes_per_cell();
    // Mirror the last cell: swapping two corners (and for Tri6 the mid-side nodes that go
    // with them) reverses its orientation.
    Index* last = mesh.connectivity.data() + (mesh.num_cells() - 1) * per_cell;
    switch (type) {
      case CellType::Tri6:
        std::swap(last[1], last[2]);
        std::swap(last[3], last[5]);
        break;
      case CellType::Hex8:
        std::swap(last[1], last[3]);
        std::swap(last[5], last[7]);
        break;
      default:
        std::swap(last[1], last[2]);
    }
    const std::string message = expect_input_error(mesh, "mirror");
    EXPECT_NE(message.find("cell " + std::to_string(mesh.num_cells() - 1) + " "), std::string::npos)
        << to_string(type) << ": " << message;
  }
}

TEST(CellGeometryTest, ValidateMeshRejectsDegenerateCell) {
  Mesh mesh;
  mesh.cell_type = CellType::Tri3;
  mesh.nodes = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  mesh.connectivity = {0, 1, 2};
  EXPECT_NE(expect_input_error(mesh, "flat").find("cell 0 "), std::string::npos);
}

TEST(CellGeometryTest, ValidateMeshRejectsEmptyMesh) {
  Mesh mesh;
  EXPECT_NE(expect_input_error(mesh, "empty.msh").find("empty"), std::string::npos);
  mesh.nodes = {{0, 0, 0}};
  EXPECT_NE(expect_input_error(mesh, "empty.msh").find("empty"), std::string::npos);
}

TEST(CellGeometryTest, ValidateMeshRejectsNodeIndexOutOfRange) {
  Mesh mesh = uniform_mesh(CellType::Tri3, 2);
  mesh.connectivity[3 * 5 + 2] = mesh.num_nodes();
  const std::string message = expect_input_error(mesh, "range");
  EXPECT_NE(message.find("cell 5 "), std::string::npos) << message;
  mesh.connectivity[3 * 5 + 2] = -1;
  EXPECT_NE(expect_input_error(mesh, "range").find("cell 5 "), std::string::npos);
}

TEST(CellGeometryTest, ValidateMeshRejectsNonFiniteCoordinates) {
  Mesh mesh = uniform_mesh(CellType::Hex8, 2);
  mesh.nodes[7][1] = std::numeric_limits<double>::quiet_NaN();
  const std::string message = expect_input_error(mesh, "nan");
  EXPECT_NE(message.find("node 7 "), std::string::npos) << message;
  mesh.nodes[7][1] = std::numeric_limits<double>::infinity();
  EXPECT_NE(expect_input_error(mesh, "inf").find("node 7 "), std::string::npos);
}

TEST(CellGeometryTest, ValidateMeshRejectsOutOfPlaneNodesIn2D) {
  Mesh mesh = uniform_mesh(CellType::Quad4, 2);
  mesh.nodes[4][2] = 1e-3;
  const std::string message = expect_input_error(mesh, "plane");
  EXPECT_NE(message.find("node 4 "), std::string::npos) << message;
  EXPECT_NE(message.find("z = 0"), std::string::npos) << message;
}

TEST(CellGeometryTest, ValidateMeshRejectsGroupsWithBadIds) {
  Mesh mesh = uniform_mesh(CellType::Quad4, 2);
  mesh.cell_groups["soil"] = {0, 4};
  EXPECT_NE(expect_input_error(mesh, "groups").find("soil"), std::string::npos);
  mesh.cell_groups["soil"] = {0, 3};
  mesh.node_groups["pile"] = {9};
  EXPECT_NE(expect_input_error(mesh, "groups").find("pile"), std::string::npos);
}

}  // namespace
}  // namespace geompm

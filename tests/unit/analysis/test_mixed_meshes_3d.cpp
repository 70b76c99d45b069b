// Whole runs on a 3D mixed mesh (docs/theory.md §19.5): the box [0, 2] x [0, 1]^2 that Gmsh meshes
// with hexahedra left of x = 1, tetrahedra right of it and pyramids between them
// (tests/unit/mesh/data/mixed_box.msh, made by tests/tools/mixed_box_msh.cpp). Patch tests (a layer
// compressed by 1 % in one step, all MPM or all FEM, reproduces the homogeneous deformation
// exactly: the reaction, one stress at every point, the linear displacement), the all-FEM layer
// against the Hencky closed form at every step, and a block of points drifting from hexahedra
// through pyramids into tetrahedra, keeping its mass and momentum and translating rigidly.
#include <gtest/gtest.h>

#include <cmath>

#include "example_text.hpp"
#include "geompm/analysis/model.hpp"
#include "geompm/io/model_reader.hpp"
#include "hencky_layer.hpp"
#include "run_model.hpp"

namespace geompm {
namespace {

using testing::replace_once;

/// The mixed box's mesh file (tests/tools/mixed_box_msh.cpp).
std::string mixed_box_file() {
  return std::string(GEOMPM_SOURCE_DIR) + "/tests/unit/mesh/data/mixed_box.msh";
}

// The box as a layer compressed in z by its top nodes, rollers on the four sides.
const char* kLayer = R"m(
analysis: {kinematics: 3d}
mesh: {file: MESH}
regions:
  REGIONS
materials:
  soil: {model: linear_elastic, E: 10000, nu: 0.3, density: 0}
bodies:
  layer: {material: soil, region: all, points_per_cell: 8}
phases:
  - name: compression
    duration: 1.0
    time_step: {initial: STEP, min: 0.001, max: STEP}
    # Newton well below the tolerances checked: what is left is the discretisation's error.
    newton: {residual_tolerance: 1.0e-11, displacement_tolerance: 1.0e-11}
    grid_motion: [{boundary: top, displacement: [~, ~, "-SQUEEZE*t"]}]
    fixities:
      - {boundary: left, fix: normal}
      - {boundary: right, fix: normal}
      - {boundary: front, fix: normal}
      - {boundary: back, fix: normal}
      - {boundary: bottom, fix: all}
output:
  history:
    - {quantity: reaction, boundary: top, component: z, name: top_reaction}
    - {quantity: reaction, boundary: bottom, component: z, name: base_reaction}
)m";

constexpr double kTopArea = 2.0;  // the layer's top, 2 x 1

std::string layer(const std::string& regions, const std::string& squeeze, const std::string& step) {
  std::string text = replace_once(kLayer, "MESH", mixed_box_file());
  text = replace_once(text, "REGIONS", regions);
  text = replace_once(text, "SQUEEZE", squeeze);
  text = replace_once(text, "initial: STEP", "initial: " + step);
  return replace_once(text, "max: STEP", "max: " + step);
}

/// How many of the points lie in cells of each type: tet4, hex8, pyramid5.
std::array<Index, 3> points_by_cell_type(const Model& model, const MaterialPoints& points) {
  std::array<Index, 3> count{0, 0, 0};
  for (Index p = 0; p < points.size(); ++p) {
    const CellType type = model.mesh.type_of(points.cell[p]);
    ++count[type == CellType::Tet4 ? 0 : type == CellType::Hex8 ? 1 : 2];
  }
  return count;
}

TEST(MixedMeshes3d, MpmPatchTestOnHexahedraPyramidsAndTetrahedra) {
  const auto run = testing::run_spec(
      read_model_from_string(layer("{all: {kind: mpm, region: all}}", "0.01", "1.0"), "layer.yaml"),
      "mixed_3d_mpm");
  ASSERT_TRUE(run.model->mesh.mixed());
  EXPECT_EQ(cell_type_names(run.model->mesh), "tet4 + hex8 + pyramid5");
  EXPECT_FALSE(run.model->fem);
  const auto count = points_by_cell_type(*run.model, run.model->points);
  EXPECT_EQ(count[1], 8 * 8);  // 2 x 2 x 2 hexahedra
  EXPECT_EQ(count[2], 4 * 8);  // a pyramid on each quadrangle of the interface
  EXPECT_GT(count[0], 100 * 8);
  testing::expect_confined_patch_passes(run, run.model->points, 2, kTopArea);
}

// A body that gives no points_per_cell on an imported mesh gets each cell type's default: a
// hexahedron and a pyramid have no 4-point rule, so a body-wide 4 could not seed them.
TEST(MixedMeshes3d, ABodyWithoutACountSeedsEachCellTypesDefault) {
  const std::string text = replace_once(layer("{all: {kind: mpm, region: all}}", "0.01", "1.0"),
                                        "region: all, points_per_cell: 8}", "region: all}");
  const auto model = build_model(read_model_from_string(text, "layer.yaml"));
  const auto count = points_by_cell_type(*model, model->points);
  EXPECT_EQ(count[1], 8 * 8);  // 8 in each of the 8 hexahedra
  EXPECT_EQ(count[2], 4 * 8);  // 8 in each of the 4 pyramids
  EXPECT_EQ(count[0] % 4, 0);  // 4 in each tetrahedron
  EXPECT_GT(count[0], 100 * 4);
  EXPECT_NE(describe_model(*model).find("4 per tetrahedron, 8 per hexahedron or pyramid"),
            std::string::npos);
}

TEST(MixedMeshes3d, FemPatchTestOnHexahedraPyramidsAndTetrahedra) {
  const auto run = testing::run_spec(
      read_model_from_string(layer("{all: {kind: fem, region: all}}", "0.01", "1.0"), "layer.yaml"),
      "mixed_3d_fem");
  ASSERT_TRUE(run.model->fem);
  EXPECT_EQ(run.model->points.size(), 0);
  const MaterialPoints& gauss = run.model->fem->gauss_points();
  const auto count = points_by_cell_type(*run.model, gauss);
  EXPECT_EQ(count[1], 8 * 8);  // hex8: 2 x 2 x 2 Gauss points
  EXPECT_EQ(count[2], 4 * 8);  // pyramid5: the 8-point collapsed rule
  EXPECT_EQ(count[0] % 4, 0);  // tet4: 4 points
  testing::expect_confined_patch_passes(run, gauss, 2, kTopArea);
}

TEST(MixedMeshes3d, AllFemLayerCompressesAsTheClosedForm) {
  // Ten steps to 10 %: homogeneous, so exact at every step.
  const auto run = testing::run_spec(
      read_model_from_string(layer("{all: {kind: fem, region: all}}", "0.1", "0.1"), "layer.yaml"),
      "mixed_3d_fem_layer");
  testing::expect_top_reaction_as_closed_form(run, kTopArea);
}

// A free block of points (no gravity, no support) filling the hexahedra of x in [0.5, 1],
// moving at 1 m/s along x, Newmark.
const char* kMovingBlock = R"m(
analysis: {kinematics: 3d}
mesh: {file: MESH}
materials:
  soil: {model: linear_elastic, E: 10000, nu: 0.3, density: 2}
bodies:
  block: {material: soil, region: {box: {min: [0.5, 0, 0], max: [1, 1, 1]}}, points_per_cell: 8,
          initial_velocity: ["1", "0", "0"]}
phases:
  - name: drift
    duration: DURATION
    time_step: {initial: 0.1, min: 0.001, max: 0.1}
    dynamics: newmark
output:
  history:
    - {quantity: newton_iterations}
)m";

/// The block after drifting for `duration` seconds: rigidly translated, mass and momentum kept.
std::array<Index, 3> drift_block(const std::string& duration) {
  const std::string text =
      replace_once(replace_once(kMovingBlock, "MESH", mixed_box_file()), "DURATION", duration);
  const auto run =
      testing::run_spec(read_model_from_string(text, "block.yaml"), "mixed_3d_block_" + duration);
  const MaterialPoints& points = run.model->points;
  EXPECT_EQ(points.size(), 4 * 8);  // the 2 x 2 hexahedra of x in [0.5, 1], 8 points each
  const double distance = std::stod(duration);
  double mass = 0.0;
  Vec3 momentum = Vec3::Zero();
  for (Index p = 0; p < points.size(); ++p) {
    mass += points.mass[p];
    momentum += points.mass[p] * points.velocity[p];
    EXPECT_NEAR(points.displacement[p].x(), distance, 1e-9) << "point " << p;
    EXPECT_NEAR(points.displacement[p].tail<2>().norm(), 0.0, 1e-9) << "point " << p;
  }
  EXPECT_NEAR(mass, 2.0 * 0.5, 1e-12);
  EXPECT_NEAR(momentum.x(), 1.0, 1e-9);
  EXPECT_NEAR(momentum.tail<2>().norm(), 0.0, 1e-9);
  return points_by_cell_type(*run.model, points);
}

TEST(MixedMeshes3d, PointsMovingFromHexahedraThroughPyramidsIntoTetrahedraKeepMassAndMomentum) {
  // Half way (x in [1, 1.5]) part of the block lies in the pyramids; at 0.9 (x from 1.4) most of
  // it in the tetrahedra, none in the hexahedra.
  const auto half_way = drift_block("0.5");
  EXPECT_GT(half_way[2], 0) << "no point in a pyramid";
  EXPECT_EQ(half_way[1], 0);
  const auto beyond = drift_block("0.9");
  EXPECT_EQ(beyond[1], 0);
  EXPECT_GT(beyond[0], beyond[2]);
}

}  // namespace
}  // namespace geompm

// Regions of the background mesh and FEM cells in whole runs (docs/theory.md §19): the cells'
// kinds from the model file, the seeding that skips FEM and buffer cells and puts a point at each
// Gauss point of an FEM cell, the errors of bad regions, and the confined compression of an
// elastic layer that is all FEM, or FEM below and MPM above (one system with shared nodes, the
// MPM mesh relaxed after each step), against the closed form of the Hencky material. The same on
// meshes of mixed cell types (issue 43, seed §3.4; a region's `cell`): patch tests (a layer
// compressed by 1 % in one step, all MPM or all FEM on quad4 and tri3 cells, reproduces the
// homogeneous deformation exactly: the reaction, one stress at every point, the linear
// displacement at every point), the all-FEM layer on quad4 + tri3 and on tri6 cells, the coupled
// layer with tri3 FEM below quad4 MPM, points that move from quad4 into tri3 cells keeping the
// body's mass and momentum, and the refusals (tri6 under material points, ddmp on a mixed mesh).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "example_text.hpp"
#include "geompm/analysis/model.hpp"
#include "geompm/core/error.hpp"
#include "geompm/io/model_reader.hpp"
#include "geompm/mesh/cell_geometry.hpp"
#include "hencky_layer.hpp"
#include "run_model.hpp"

namespace geompm {
namespace {

// A 1 x 1 layer of 4 x 4 cells compressed by 10 % by its top nodes, rollers on the sides.
const char* kLayer = R"m(
analysis: {kinematics: plane_strain}
mesh:
  generate: {cell: quad4, origin: [0, 0], x: {length: 1, cells: 4}, y: {length: 1, cells: 4}}
regions:
  REGIONS
materials:
  soil: {model: linear_elastic, E: 10000, nu: 0.3, density: 0}
bodies:
  layer: {material: soil, region: all, points_per_cell: 4}
phases:
  - name: compression
    duration: 1.0
    time_step: {initial: 0.1, min: 0.001, max: 0.1}
    grid_motion: [{boundary: top, displacement: [~, "-0.1*t"]}]
    fixities:
      - {boundary: left, fix: normal}
      - {boundary: right, fix: normal}
      - {boundary: bottom, fix: all}
output:
  history:
    - {quantity: reaction, boundary: top, component: y, name: top_reaction}
    - {quantity: reaction, boundary: bottom, component: y, name: base_reaction}
    - {quantity: mesh_smallest_angle}
)m";

std::string layer(const std::string& regions) {
  std::string text = kLayer;
  return text.replace(text.find("REGIONS"), 7, regions);
}

// sigma_yy of the confined layer at the stretch l, on a width of 1.
double confined_stress(double l) { return testing::hencky_confined_stress(l); }

TEST(FemRegions, SeedFemCellsAtTheirGaussPointsAndBufferCellsNot) {
  const auto model = build_model(read_model_from_string(
      layer("{deep: {kind: fem, region: {box: {min: [0, 0], max: [1, 0.5]}}}, "
            "top: {kind: buffer, region: {box: {min: [0, 0.75], max: [1, 1]}}}}"),
      "layer.yaml"));
  ASSERT_TRUE(model->fem);
  EXPECT_EQ(model->fem->cells().size(), 8u);
  EXPECT_EQ(model->points.size(), 4 * 4);  // one row of MPM cells, 4 points each
  for (Index p = 0; p < model->points.size(); ++p) {
    EXPECT_GT(model->points.position[p].y(), 0.5);
    EXPECT_LT(model->points.position[p].y(), 0.75);
  }
  const MaterialPoints& gauss = model->fem->gauss_points();
  ASSERT_EQ(gauss.size(), 8 * 4);
  double volume = 0.0;
  for (Index g = 0; g < gauss.size(); ++g) volume += gauss.volume[g];
  EXPECT_NEAR(volume, 0.5, 1e-14);
}

TEST(FemRegions, AnMpmOnlyModelHasNoFemRegion) {
  const auto model = build_model(
      read_model_from_string(layer("{all_mpm: {kind: mpm, region: all}}"), "layer.yaml"));
  EXPECT_FALSE(model->fem);
  EXPECT_EQ(model->points.size(), 16 * 4);
}

// The message of the InputError building the model throws, or "" if it builds.
std::string error_of(const std::string& regions) {
  try {
    build_model(read_model_from_string(layer(regions), "layer.yaml"));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(FemRegions, RefuseBadRegions) {
  EXPECT_NE(error_of("{a: {kind: fem, region: {group: clay}}}").find("no region 'clay'"),
            std::string::npos);
  const std::string overlap = error_of(
      "{a: {kind: fem, region: all}, b: {kind: buffer, region: {box: {min: [0, 0.5], max: [1, "
      "1]}}}}");
  EXPECT_NE(overlap.find("regions 'a' (fem) and 'b' (buffer) overlap"), std::string::npos)
      << overlap;
  EXPECT_NE(overlap.find("layer.yaml"), std::string::npos) << overlap;
  EXPECT_NE(
      error_of("{a: {kind: fem, region: {box: {min: [2, 2], max: [3, 3]}}}}").find("holds no cell"),
      std::string::npos);
  try {
    read_model_from_string(layer("{a: {kind: finite, region: all}}"), "layer.yaml");
    ADD_FAILURE() << "an unknown kind was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("regions.a.kind"), std::string::npos) << e.what();
  }
}

TEST(FemRegions, RefuseAnFemCellNoBodyHolds) {
  std::string text = layer("{a: {kind: fem, region: all}}");
  text.replace(text.find("region: all, points"), 11, "region: {box: {min: [0, 0], max: [1, 0.5]}}");
  try {
    build_model(read_model_from_string(text, "layer.yaml"));
    ADD_FAILURE() << "an FEM cell with no body was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no body holds"), std::string::npos) << e.what();
  }
}

TEST(FemRegions, AnAllFemLayerCompressesAsTheClosedForm) {
  const auto run = testing::run_spec(
      read_model_from_string(layer("{all: {kind: fem, region: all}}"), "layer.yaml"), "fem_layer");
  EXPECT_EQ(run.model->points.size(), 0);
  const std::vector<double> top = run.column("top_reaction");
  ASSERT_EQ(top.size(), 11u);
  // Homogeneous deformation: exact up to Newton's tolerance, at every step.
  for (std::size_t k = 1; k < top.size(); ++k) {
    const double expected = confined_stress(1.0 - 0.01 * static_cast<double>(k));
    EXPECT_NEAR(top[k], expected, 1e-8 * std::abs(expected)) << "step " << k;
    EXPECT_NEAR(run.column("base_reaction")[k], -expected, 1e-8 * std::abs(expected));
  }
  // The Gauss points carry the stress, uniform.
  const MaterialPoints& gauss = run.model->fem->gauss_points();
  for (Index g = 0; g < gauss.size(); ++g)
    EXPECT_NEAR(gauss.stress[g](1, 1), confined_stress(0.9), 1e-8 * std::abs(top.back()));
}

// The oedometer example with FEM cells below y = 0.5: MPM above, driven by a prescribed motion
// of its top points (the grid above the body is empty).
const char* kCoupledLayer = R"m(
analysis: {kinematics: plane_strain}
mesh:
  generate: {cell: quad4, origin: [0, 0], x: {length: 1, cells: 4}, y: {length: 1.25, cells: 5}}
regions:
  deep: {kind: fem, region: {box: {min: [0, 0], max: [1, 0.5]}}}
materials:
  soil: {model: linear_elastic, E: 10000, nu: 0.3, density: 0}
bodies:
  layer: {material: soil, region: {box: {min: [0, 0], max: [1, 1]}}, points_per_cell: 4}
point_sets:
  top: {body: layer, region: {box: {min: [0, 0.875], max: [1, 1]}}}
phases:
  - name: compression
    duration: 1.0
    time_step: {initial: 0.1, min: 0.001, max: 0.1}
    prescribed_motion: [{point_set: top, displacement: [~, "-0.1*t"]}]
    fixities:
      - {boundary: left, fix: normal}
      - {boundary: right, fix: normal}
      - {boundary: bottom, fix: all}
output:
  history:
    - {quantity: reaction, boundary: bottom, component: y, name: base_reaction}
    - {quantity: reaction, point_set: top, component: y, name: top_reaction}
    - {quantity: mesh_smallest_angle}
)m";

// The coupled layer's checks: equilibrium through the interface at every step, the base reaction
// against the Hencky stress of the Gauss points' mean stretch, the relaxed MPM cells' shape.
void expect_coupled_layer_as_closed_form(const testing::ModelRun& run) {
  // Equilibrium through the interface: the base carries what the top set's motion pushes, at
  // every step.
  const std::vector<double> base = run.column("base_reaction"), top = run.column("top_reaction");
  ASSERT_EQ(base.size(), 11u);
  for (std::size_t k = 1; k < base.size(); ++k)
    EXPECT_NEAR(base[k], -top[k], 1e-8 * std::abs(top[k])) << "step " << k;
  // The Gauss points' mean stretch l and the Hencky stress of it against the base's reaction
  // (width 1): the same to the MPM region's discretisation (its points' quadrature in the relaxed
  // cells).
  const MaterialPoints& gauss = run.model->fem->gauss_points();
  double l = 0.0, volume = 0.0;
  for (Index g = 0; g < gauss.size(); ++g) {
    l += gauss.deformation_gradient[g](1, 1) * gauss.volume[g];
    volume += gauss.volume[g];
  }
  l /= volume;
  EXPECT_LT(l, 0.95);
  std::printf("coupled layer: l = %.6f, base %.4f, closed form %.4f\n", l, base.back(),
              -confined_stress(l));
  // Measured 9e-6 relative on quad4 cells, 1.0e-5 with tri3 FEM cells.
  EXPECT_NEAR(base.back(), -confined_stress(l), 1e-4 * std::abs(confined_stress(l)));
  // The MPM cells' smallest angle: the interface has come down below the side nodes held at their
  // initial place; the relaxed cells stay near square.
  const double angle = run.column("mesh_smallest_angle").back();
  EXPECT_GT(angle, 80.0);
  EXPECT_LT(angle, 90.0);
}

TEST(FemRegions, ACoupledLayerCompressesAsTheClosedForm) {
  // The interface nodes are shared unknowns; the FEM nodes move with the solution and the MPM
  // mesh above is relaxed between the interface and the outer boundary after each step.
  const auto run =
      testing::run_spec(read_model_from_string(kCoupledLayer, "coupled.yaml"), "coupled_layer");
  expect_coupled_layer_as_closed_form(run);
}

// ---- Mixed cell types ----------------------------------------------------------------------

// The layer with a region's cell type, `squeeze` of compression in steps of `step`, on `cell`s.
std::string mixed_layer(const std::string& regions, const std::string& squeeze = "0.1",
                        const std::string& step = "0.1", const std::string& cell = "quad4") {
  using testing::replace_once;
  std::string text = replace_once(layer(regions), "\"-0.1*t\"", "\"-" + squeeze + "*t\"");
  text = replace_once(text, "initial: 0.1, min: 0.001, max: 0.1",
                      "initial: " + step + ", min: 0.001, max: " + step);
  return replace_once(text, "cell: quad4", "cell: " + cell);
}

const char* kLeftTriangles =
    "{left: {kind: mpm, cell: tri3, region: {box: {min: [0, 0], "
    "max: [0.5, 1]}}}}";

TEST(MixedMeshes, ARegionsCellTypeSplitsItsRectangles) {
  const auto model = build_model(read_model_from_string(mixed_layer(kLeftTriangles), "layer.yaml"));
  const Mesh& mesh = model->mesh;
  ASSERT_TRUE(mesh.mixed());
  EXPECT_EQ(mesh.num_cells(), 8 + 2 * 8);  // 8 quad4 on the right, 8 rectangles split on the left
  Index triangles = 0;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const Vec3 x = map_to_physical(mesh, c, Vec3(0.3, 0.3, 0));
    if (mesh.type_of(c) == CellType::Tri3) {
      ++triangles;
      EXPECT_LT(x.x(), 0.5);
    } else {
      EXPECT_GT(x.x(), 0.5);
    }
  }
  EXPECT_EQ(triangles, 16);
  EXPECT_EQ(cell_type_names(mesh), "tri3 + quad4");
  // 4 points in each cell, whatever its type.
  EXPECT_EQ(model->points.size(), 4 * 24);
  double volume = 0.0;
  for (Index p = 0; p < model->points.size(); ++p) volume += model->points.volume[p];
  EXPECT_NEAR(volume, 1.0, 1e-14);
}

// The layer's patch test: 1 % in one step along y (tests/support/hencky_layer.hpp).
void expect_patch_passes(const testing::ModelRun& run, const MaterialPoints& points) {
  testing::expect_confined_patch_passes(run, points, 1);
}

TEST(MixedMeshes, MpmPatchTestOnQuadAndTriangleCells) {
  // The displacement formulation and the mixed p-u one (a pressure unknown at every node of
  // both kinds of cell, the stabilisation and the empty cells' pressure block per cell type).
  for (const std::string formulation : {"displacement", "mixed"}) {
    SCOPED_TRACE(formulation);
    const std::string text =
        testing::replace_once(mixed_layer(kLeftTriangles, "0.01", "1.0"), "nu: 0.3, density: 0}",
                              "nu: 0.3, density: 0, formulation: " + formulation + "}");
    const auto run =
        testing::run_spec(read_model_from_string(text, "layer.yaml"), "mixed_mpm_" + formulation);
    ASSERT_TRUE(run.model->mesh.mixed());
    EXPECT_FALSE(run.model->fem);
    expect_patch_passes(run, run.model->points);
  }
}

TEST(MixedMeshes, FemPatchTestOnQuadAndTriangleCells) {
  const std::string regions =
      "{left: {kind: fem, cell: tri3, region: {box: {min: [0, 0], max: [0.5, 1]}}}, "
      "right: {kind: fem, region: {box: {min: [0.5, 0], max: [1, 1]}}}}";
  const auto run = testing::run_spec(
      read_model_from_string(mixed_layer(regions, "0.01", "1.0"), "layer.yaml"), "mixed_fem");
  ASSERT_TRUE(run.model->fem);
  EXPECT_EQ(run.model->points.size(), 0);
  const MaterialPoints& gauss = run.model->fem->gauss_points();
  EXPECT_EQ(gauss.size(), 16 * 3 + 8 * 4);  // tri3: 3 Gauss points, quad4: 4
  expect_patch_passes(run, gauss);
}

TEST(MixedMeshes, AllFemMixedLayerCompressesAsTheClosedForm) {
  // Ten steps to 10 %: exact at every step (homogeneous), on tri3 and quad4 FEM cells.
  const std::string regions =
      "{left: {kind: fem, cell: tri3, region: {box: {min: [0, 0], max: [0.5, 1]}}}, "
      "right: {kind: fem, region: {box: {min: [0.5, 0], max: [1, 1]}}}}";
  const auto run = testing::run_spec(read_model_from_string(mixed_layer(regions), "layer.yaml"),
                                     "mixed_fem_layer");
  testing::expect_top_reaction_as_closed_form(run);
}

TEST(MixedMeshes, Tri6FemLayerCompressesAsTheClosedForm) {
  const auto run = testing::run_spec(
      read_model_from_string(mixed_layer("{all: {kind: fem, region: all}}", "0.1", "0.1", "tri6"),
                             "layer.yaml"),
      "tri6_fem_layer");
  EXPECT_EQ(run.model->mesh.cell_type, CellType::Tri6);
  EXPECT_EQ(run.model->points.size(), 0);
  EXPECT_EQ(run.model->fem->gauss_points().size(), 32 * 6);
  testing::expect_top_reaction_as_closed_form(run);
}

TEST(MixedMeshes, ACoupledTriangleFemQuadMpmLayerCompressesAsTheClosedForm) {
  const auto run = testing::run_spec(
      read_model_from_string(testing::replace_once(kCoupledLayer, "deep: {kind: fem,",
                                                   "deep: {kind: fem, cell: tri3,"),
                             "coupled.yaml"),
      "mixed_coupled_layer");
  ASSERT_TRUE(run.model->mesh.mixed());
  EXPECT_EQ(run.model->fem->gauss_points().size(), 16 * 3);  // tri3: 3 Gauss points each
  expect_coupled_layer_as_closed_form(run);
}

// A free block of points (no gravity, no support) moving at 1 m/s from quad4 cells into tri3
// cells, Newmark: it translates rigidly and keeps its mass and momentum.
const char* kMovingBlock = R"m(
analysis: {kinematics: plane_strain}
mesh:
  generate: {cell: quad4, origin: [0, 0], x: {length: 4, cells: 8}, y: {length: 1, cells: 2}}
regions:
  right: {kind: mpm, cell: tri3, region: {box: {min: [2, 0], max: [4, 1]}}}
materials:
  soil: {model: linear_elastic, E: 10000, nu: 0.3, density: 2}
bodies:
  block: {material: soil, region: {box: {min: [1, 0], max: [2, 1]}}, points_per_cell: 4,
          initial_velocity: ["1", "0"]}
phases:
  - name: drift
    duration: 1.0
    time_step: {initial: 0.1, min: 0.001, max: 0.1}
    dynamics: newmark
output:
  history:
    - {quantity: newton_iterations}
)m";

TEST(MixedMeshes, PointsMovingFromQuadsIntoTrianglesKeepMassAndMomentum) {
  const auto run =
      testing::run_spec(read_model_from_string(kMovingBlock, "block.yaml"), "mixed_block");
  const Model& model = *run.model;
  const MaterialPoints& points = model.points;
  ASSERT_EQ(points.size(), 2 * 2 * 4);
  double mass = 0.0;
  Vec3 momentum = Vec3::Zero();
  Index in_triangles = 0;
  for (Index p = 0; p < points.size(); ++p) {
    mass += points.mass[p];
    momentum += points.mass[p] * points.velocity[p];
    EXPECT_NEAR(points.displacement[p].x(), 1.0, 1e-9) << "point " << p;
    EXPECT_NEAR(points.displacement[p].y(), 0.0, 1e-9) << "point " << p;
    if (model.mesh.type_of(points.cell[p]) == CellType::Tri3) ++in_triangles;
  }
  EXPECT_EQ(in_triangles, points.size());  // all of them crossed x = 2
  EXPECT_NEAR(mass, 2.0 * 1.0, 1e-12);
  EXPECT_NEAR(momentum.x(), 2.0, 1e-9);
  EXPECT_NEAR(momentum.y(), 0.0, 1e-9);
}

TEST(MixedMeshes, RefuseTri6UnderMaterialPoints) {
  const std::string error =
      testing::build_error(mixed_layer("{all: {kind: mpm, region: all}}", "0.1", "0.1", "tri6"));
  EXPECT_NE(error.find("tri6 cell"), std::string::npos) << error;
  EXPECT_NE(error.find("FEM region"), std::string::npos) << error;
  EXPECT_NE(error.find("bodies.layer"), std::string::npos) << error;
}

TEST(MixedMeshes, RefuseWhatAMixedMeshCannotCarry) {
  // A region's cell type of a tri6 mesh (tri6 has mid-side nodes no quad4 shares).
  try {
    read_model_from_string(mixed_layer(kLeftTriangles, "0.1", "0.1", "tri6"), "layer.yaml");
    ADD_FAILURE() << "a typed region in a tri6 mesh was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("regions.left.cell"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("tri6"), std::string::npos) << e.what();
  }
  // DDMP's smoothed gradients are per cell type.
  std::string text = mixed_layer(kLeftTriangles);
  text += "numerics: {interpolation: ddmp}\n";
  const std::string error = testing::build_error(text);
  EXPECT_NE(error.find("mixes cell types"), std::string::npos) << error;
}

}  // namespace
}  // namespace geompm

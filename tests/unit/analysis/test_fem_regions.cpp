// Regions of the background mesh and FEM cells in whole runs (docs/theory.md §19): the cells'
// kinds from the model file, the seeding that skips FEM and buffer cells and puts a point at each
// Gauss point of an FEM cell, the errors of bad regions, and the confined compression of an
// elastic layer that is all FEM, or FEM below and MPM above (one system with shared nodes, the
// MPM mesh relaxed after each step), against the closed form of the Hencky material.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "geompm/analysis/model.hpp"
#include "geompm/core/error.hpp"
#include "geompm/io/model_reader.hpp"
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

// The Hencky material's confined compression to the stretch l: sigma_yy = M ln(l) / l on a width
// of 1 (the oedometer example's closed form), M = E (1 - nu) / ((1 + nu) (1 - 2 nu)).
double confined_stress(double l) {
  const double E = 10000, nu = 0.3;
  return E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) * std::log(l) / l;
}

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

TEST(FemRegions, ACoupledLayerCompressesAsTheClosedForm) {
  // The interface nodes are shared unknowns; the FEM nodes move with the solution and the MPM
  // mesh above is relaxed between the interface and the outer boundary after each step.
  const auto run =
      testing::run_spec(read_model_from_string(kCoupledLayer, "coupled.yaml"), "coupled_layer");
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
  // Measured 9e-6 relative.
  EXPECT_NEAR(base.back(), -confined_stress(l), 1e-4 * std::abs(confined_stress(l)));
  // The MPM cells' smallest angle: the interface has come down below the side nodes held at their
  // initial place; the relaxed cells stay near square.
  const double angle = run.column("mesh_smallest_angle").back();
  EXPECT_GT(angle, 80.0);
  EXPECT_LT(angle, 90.0);
}

}  // namespace
}  // namespace geompm

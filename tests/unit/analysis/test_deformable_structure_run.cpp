// A deformable structure in a whole run (docs/theory.md §17.7-17.8): an elastic column standing
// beside a soil block, held at its base and sliding along its sides, under the phase's gravity.
// Its drive's reaction is its weight, its top settles as the confined column's closed form, the
// mean vertical stress over its mid-height section is the weight above, and a drive whose nodes
// select none, or name a group its mesh lacks, is refused when the model is built.
#include <gtest/gtest.h>

#include <cmath>

#include "geompm/io/model_reader.hpp"
#include "run_model.hpp"

namespace geompm {
namespace {

const char* kModel = R"m(
analysis: {kinematics: plane_strain}
mesh:
  generate: {cell: quad4, origin: [0, 0], x: {length: 4, cells: 4}, y: {length: 4, cells: 4}}
materials:
  soil: {model: linear_elastic, E: 1000, nu: 0.3, density: 0}
  steel: {model: linear_elastic, E: 100000, nu: 0.3, density: 2}
bodies:
  ground: {material: soil, region: {box: {min: [0, 0], max: [4, 1]}}, points_per_cell: 4}
structures:
  - name: column
    shape: {type: footing, width: 0.2, height: 2, position: [3, 1.5], cell: quad4, cell_size: 0.1}
    deformable: {material: steel}
    contact: none
phases:
  - name: weigh
    duration: 1
    time_step: 1
    gravity: {acceleration: [0, -10]}
    fixities: [{boundary: bottom, fix: all}, {boundary: left, fix: normal},
               {boundary: right, fix: normal}]
    structures:
      column:
        - {nodes: bottom, displacement: [0, 0]}
        - {nodes: left, displacement: [0, ~]}
        - {nodes: right, displacement: [0, ~]}
output:
  history:
    - {quantity: reaction, structure: column, component: y}
    - {quantity: displacement, structure: column, nodes: top, component: y, name: top_uy}
    - {quantity: section_stress, structure: column, section: {point: [3, 2.55], normal: [0, 1]},
       name: mid_stress}
)m";

TEST(DeformableStructureRun, CarriesItsWeightOnItsHeldBase) {
  const auto run = testing::run_spec(read_model_from_string(kModel, "column.yaml"), "column");
  const double rho_g = 20.0, L = 2.0, B = 0.2, E = 1e5, nu = 0.3;
  const double M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  EXPECT_NEAR(run.column("reaction_column_y").back(), rho_g * L * B, 1e-9 * rho_g * L * B);
  // Small strain (2e-4): the closed form rho g L^2 / (2 M) within 1e-3.
  const double settlement = rho_g * L * L / (2 * M);
  EXPECT_NEAR(run.column("top_uy").back(), -settlement, 1e-3 * settlement);
  // At y = 2.55 (1.05 above the base at 1.5) the weight above, rho g (L - 1.05) = 19: for a
  // stress linear in y each cut cell's mean is the stress at its centre, within half a cell
  // (h = 0.1) of the section, so eq. 17.15 is within rho g h / 4 = 0.5 of it (measured 0.07 on
  // Gmsh's quad4 mesh).
  EXPECT_NEAR(run.column("mid_stress").back(), -rho_g * (L - 1.05), 0.25 * rho_g * 0.1);
}

TEST(DeformableStructureRun, RefusesADriveOfNoNodes) {
  std::string text = kModel;
  text.replace(text.find("{nodes: left,"), 13, "{nodes: {min: [9, 9], max: [9, 9]},");
  EXPECT_NE(testing::build_error(text).find("selects none of the structure's nodes"),
            std::string::npos);
  text = kModel;
  text.replace(text.find("{nodes: left,"), 13, "{nodes: shaft,");
  EXPECT_NE(testing::build_error(text).find("has no node group 'shaft'"), std::string::npos);
}

}  // namespace
}  // namespace geompm

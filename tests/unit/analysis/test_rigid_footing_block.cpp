// The rigid footing's penalty contact (docs/theory.md §13) in a whole run: the reaction of a
// confined elastic block pressed by a smooth footing against its closed form, in plane strain and
// axisymmetry, on quadrilaterals and triangles.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>

#include "geompm/io/model_reader.hpp"
#include "run_model.hpp"

namespace geompm {
namespace {

// A block [0, 1] x [0, 1] (E = 10 MPa, nu = 0.3) with rollers on both sides and its base fixed,
// pressed by a smooth footing wider than it: confined (1D) compression. The contact acts at the
// top of the top row of points' domains, which is the surface, so the grid sees the footing's
// load at its top nodes and the block is uniformly compressed, in series with the penalty's
// kappa W (W the width, or R^2 / 2 per radian in axisymmetry):
//   F = W d / (H / E_oed + 1 / kappa).
std::string confined_block(const std::string& kinematics, int cells, double kappa,
                           const std::string& cell) {
  return fmt::format(R"m(analysis: {{kinematics: {}}}
mesh: {{generate: {{{}x: {{length: 1, cells: {}}}, y: {{length: {}, cells: {}}}}}}}
materials:
  soil: {{model: linear_elastic, E: 10000, nu: 0.3}}
bodies:
  block: {{material: soil, region: {{box: {{min: [0, 0], max: [1, 1]}}}}}}
phases:
  - name: press
    time_step: 1
    newton: {{residual_tolerance: 1.0e-9, displacement_tolerance: 1.0e-9}}
    rigid_footings:
      - {{name: plate, base: 1, x: [0, 1.5], contact: smooth, displacement: [0, "-1e-4*t"],
         penalty: {}}}
    fixities:
      - {{boundary: left, fix: normal}}
      - {{boundary: right, fix: normal}}
      - {{boundary: bottom, fix: all}}
output:
  vtk: {{every: 0}}
  history:
    - {{quantity: displacement, footing: plate, component: y, name: settlement}}
    - {{quantity: reaction, footing: plate, component: y, name: force}}
    - {{quantity: reaction, boundary: bottom, component: y, name: base}}
)m",
                     kinematics, cell, cells, 1.0 + 1.0 / cells, cells + 1, kappa);
}

// `cell`: the generated mesh's cell settings (quad4 when empty).
void check_confined_block(const std::string& kinematics, int cells, const std::string& cell = "") {
  const double E = 1e4, nu = 0.3, d = 1e-4, kappa = 1e2 * E * cells;
  const double E_oed = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  // Width W per unit thickness, or the area R^2 / 2 per radian.
  const double W = kinematics == "axisymmetric" ? 0.5 : 1.0;
  const double expected = W * d / (1.0 / E_oed + 1.0 / kappa);
  const auto run = testing::run_spec(
      read_model_from_string(confined_block(kinematics, cells, kappa, cell), "block.yaml"),
      "rigid_footing_block_" + kinematics);
  const double force = -run.column("force").back();  // the footing pushes down
  EXPECT_NEAR(run.column("settlement").back(), -d, 1e-15);
  // Small strain (d / H = 1e-4): the Hencky law is linear to 1e-4.
  EXPECT_NEAR(force / expected, 1.0, 5e-4) << kinematics << ", " << cells << " cells " << cell;
  // The footing's force reaches the fixed base.
  EXPECT_NEAR(run.column("base").back() / force, 1.0, 1e-6);
}

TEST(RigidFootingBlock, ConfinedBlockReactionIsTheClosedFormPlaneStrain) {
  check_confined_block("plane_strain", 4);
  check_confined_block("plane_strain", 8);
}

TEST(RigidFootingBlock, ConfinedBlockReactionIsTheClosedFormAxisymmetric) {
  check_confined_block("axisymmetric", 4);
}

TEST(RigidFootingBlock, ConfinedBlockReactionIsTheClosedFormOnTriangles) {
  // The footing touches the top faces of the soil's triangles, which lie on the surface and tile
  // it (seeding: SimplexTopFacesTileTheSurfaceAndStayBelowIt); a domain reaching above the
  // surface would be pressed before the footing moves, and the force would be off by its
  // penetration over the settlement.
  for (const char* cell : {"cell: tri3, ", "cell: tri3, diagonals: crossed, "}) {
    check_confined_block("plane_strain", 4, cell);
    check_confined_block("axisymmetric", 4, cell);
  }
}

}  // namespace
}  // namespace geompm

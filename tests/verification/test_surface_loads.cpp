// Surface loads on the level set (docs/theory.md §16; seed §3.5) in whole runs. A uniform pressure
// q on the top of a weightless elastic block, confined by rollers on its sides, in one load step:
// the top is on a grid line, so the facets are the cells' top edges (faces) and the load is the
// consistent nodal load of the traction; the stress is uniform and sigma_yy = -q exactly (the
// width does not change, so whatever the strain the Cauchy stress carries q on it), and the
// lateral stress is sigma_xx = nu / (1 - nu) sigma_yy (Hencky, uniaxial strain: tau = lambda
// ln(l) I + 2 mu ln(l) e_y e_y, both over J). Plane strain, axisymmetric, 3D, and triangles; fixed
// and following. In several load steps the surface moves off the grid line into the top cells:
// the load's resultant stays exact (the facets still span the block's width), so the base
// reaction is q times the width at every step.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "geompm/io/model_reader.hpp"
#include "run_model.hpp"

namespace geompm {
namespace {

struct BlockCase {
  const char* name;
  const char* cell;
  const char* kinematics;
  bool three_d;
  const char* direction;
};

std::string block_model(const BlockCase& c, int steps) {
  const std::string xyz = c.three_d ? "[0, 0, 0]" : "[0, 0]";
  const std::string top = c.three_d ? "[2, 1, 2]" : "[2, 2]";
  std::string text = R"(title: Pressure on a confined block
analysis: {kinematics: @KINEMATICS@}
mesh:
  generate:
    cell: @CELL@
    origin: @ORIGIN@
    x: {length: 2, cells: 4}
    y: {length: @YLENGTH@, cells: @YCELLS@}
@ZAXIS@
materials:
  soil: {model: linear_elastic, E: 10000, nu: 0.3, density: 0}
bodies:
  block: {material: soil, region: {box: {min: @ORIGIN@, max: @TOP@}}, points_per_cell: @PPC@}
phases:
  - name: load
    duration: 1.0
    time_step: {initial: @STEP@, max: @STEP@}
    newton: {residual_tolerance: 1.0e-12, displacement_tolerance: 1.0e-12}
    surface_loads:
      - {pressure: "150*t", direction: @DIRECTION@}
    fixities:
      - {boundary: left, fix: normal}
      - {boundary: right, fix: normal}
@FIXITIES@
output:
  vtk: {every: 0}
  history:
    - {quantity: reaction, boundary: bottom, component: @UP@, name: base}
)";
  const auto set = [&](const std::string& key, const std::string& value) {
    const std::string token = "@" + key + "@";
    for (std::size_t at; (at = text.find(token)) != std::string::npos;)
      text.replace(at, token.size(), value);
  };
  set("KINEMATICS", c.kinematics);
  set("CELL", c.cell);
  set("ORIGIN", xyz);
  set("TOP", top);
  set("YLENGTH", c.three_d ? "1" : "2.5");
  set("YCELLS", c.three_d ? "2" : "5");
  set("ZAXIS", c.three_d ? "    z: {length: 2.5, cells: 5}" : "");
  set("PPC", c.three_d ? "8" : "4");
  set("STEP", std::to_string(1.0 / steps));
  set("DIRECTION", c.direction);
  set("FIXITIES", c.three_d ? "      - {boundary: front, fix: normal}\n"
                              "      - {boundary: back, fix: normal}\n"
                              "      - {boundary: bottom, fix: all}"
                            : "      - {boundary: bottom, fix: all}");
  set("UP", c.three_d ? "z" : "y");
  return text;
}

class PressureOnABlock : public ::testing::TestWithParam<BlockCase> {};

TEST_P(PressureOnABlock, GivesTheExactStressInEveryPoint) {
  const BlockCase& c = GetParam();
  const auto spec = read_model_from_string(block_model(c, 1), std::string(c.name) + ".yaml");
  const auto run = testing::run_spec(spec, std::string("surface_block_") + c.name);
  ASSERT_EQ(run.summary.steps, 1);
  const int up = c.three_d ? 2 : 1;
  const double q = 150.0, nu = 0.3;
  const MaterialPoints& p = run.model->points;
  double worst = 0.0;
  for (Index i = 0; i < p.size(); ++i) {
    worst = std::max(worst, std::abs(p.stress[i](up, up) + q));
    worst = std::max(worst, std::abs(p.stress[i](0, 0) + nu / (1 - nu) * q));
  }
  // Round-off and Newton's tolerance (1e-12) of a stress of 150.
  EXPECT_LT(worst, 1e-8 * q) << c.name;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, PressureOnABlock,
    ::testing::Values(BlockCase{"plane_strain", "quad4", "plane_strain", false, "fixed"},
                      BlockCase{"following", "quad4", "plane_strain", false, "following"},
                      BlockCase{"tri3", "tri3", "plane_strain", false, "fixed"},
                      BlockCase{"hex8", "hex8", "3d", true, "following"}),
    [](const auto& info) { return std::string(info.param.name); });

class PressureInSteps : public ::testing::TestWithParam<BlockCase> {};

TEST_P(PressureInSteps, BaseReactionIsTheLoadAtEveryStepAsTheSurfaceLeavesTheGridLine) {
  const BlockCase& c = GetParam();
  const auto spec = read_model_from_string(block_model(c, 4), std::string(c.name) + ".yaml");
  const auto run = testing::run_spec(spec, std::string("surface_steps_") + c.name);
  ASSERT_EQ(run.summary.steps, 4);
  // q times the width 2 (plane strain), or q R^2 / 2 per radian for the disc R = 2: 300 t both.
  const auto time = run.column("time"), base = run.column("base");
  for (std::size_t k = 1; k < time.size(); ++k)
    EXPECT_NEAR(base[k], 300.0 * time[k], 1e-7 * 300.0) << "t = " << time[k];  // CSV: 10 digits
  // The top has moved into the top cells: its points are below where they started.
  for (Index i = 0; i < run.model->points.size(); ++i)
    EXPECT_LT(run.model->points.position[i].y(), run.model->points.initial_position[i].y());
}

// In axisymmetry the stress is not exact point by point: the points' quadrature of r dN/dy
// (sub-cell centres, weights int r dA) is off by 12 % at the nodes on the axis with two points
// across the first cell, so a uniform stress is not in balance with the exact load there
// (docs/validation.md); the resultant, and so the base reaction, is exact.
INSTANTIATE_TEST_SUITE_P(
    Cases, PressureInSteps,
    ::testing::Values(BlockCase{"plane_strain", "quad4", "plane_strain", false, "following"},
                      BlockCase{"axisymmetric", "quad4", "axisymmetric", false, "following"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(SurfaceLoadOutput, WritesTheBoundaryAsPolyDataWithItsNormals) {
  // The block's top at the step's end: 4 segments (one per cell), normal (0, 1), as boundary.pvd.
  std::string text = block_model({"vtp", "quad4", "plane_strain", false, "fixed"}, 1);
  const std::string from = "vtk: {every: 0}";
  text.replace(text.find(from), from.size(), "vtk: {every: 1, grid: false}");
  const auto run = testing::run_spec(read_model_from_string(text, "vtp.yaml"), "surface_vtp");
  ASSERT_TRUE(std::filesystem::exists(run.output / "boundary.pvd"));
  std::ifstream in(run.output / "vtk" / "boundary_000001.vtp");
  std::stringstream vtp;
  vtp << in.rdbuf();
  EXPECT_NE(vtp.str().find("NumberOfLines=\"4\""), std::string::npos) << vtp.str();
  EXPECT_NE(vtp.str().find("Name=\"normal\""), std::string::npos);
  EXPECT_NE(vtp.str().find("\n0 1 0\n"), std::string::npos);
}

}  // namespace
}  // namespace geompm

// The points' plastic state in the ParaView output (points.vtu): the accumulated equivalent
// plastic strain of the material's state, and `plastic`, 1 where the point flowed plastically in
// the step written. A Tresca block compressed one-dimensionally (an oedometer) yields in its
// first steps and then flows plastically in every step; at the start nothing has yielded.
#include <gtest/gtest.h>

#include <string>

#include "geompm/io/model_reader.hpp"
#include "read_vtu.hpp"
#include "run_model.hpp"

namespace geompm {
namespace {

constexpr const char* kOedometer = R"m(
analysis: {kinematics: plane_strain}
mesh: {generate: {x: {length: 1, cells: 2}, y: {length: 1.5, cells: 3}}}
materials:
  clay: {model: tresca, su: 5, E: 10000, nu: 0.3, density: 0}
bodies:
  block: {material: clay, region: {box: {min: [0, 0], max: [1, 1]}}, points_per_cell: 4}
point_sets:
  top: {body: block, region: {box: {min: [0, 0.75], max: [1, 1]}}}
phases:
  - name: compression
    time_step: 0.1
    prescribed_motion: [{point_set: top, displacement: [~, "-0.05*t"]}]
    fixities:
      - {boundary: left, fix: normal}
      - {boundary: right, fix: normal}
      - {boundary: bottom, fix: all}
output:
  vtk: {every: 1, grid: false}
)m";

TEST(PlasticOutput, PointsCarryTheirPlasticStrainAndWhetherTheyFlowedInTheStep) {
  const testing::ModelRun run =
      testing::run_spec(read_model_from_string(kOedometer, "oedometer.yaml"), "plastic_output");
  ASSERT_EQ(run.summary.steps, 10);
  const testing::ReadVtu start =
      testing::read_with_meshio(run.output / "vtk" / "points_000000.vtu");
  const testing::ReadVtu end = testing::read_with_meshio(run.output / "vtk" / "points_000010.vtu");
  for (const testing::ReadVtu* vtu : {&start, &end}) {
    ASSERT_TRUE(vtu->point_data.count("equivalent_plastic_strain"));
    ASSERT_TRUE(vtu->point_data.count("plastic"));
  }
  const auto& strain_start = start.point_data.at("equivalent_plastic_strain").rows;
  const auto& plastic_start = start.point_data.at("plastic").rows;
  const auto& strain_end = end.point_data.at("equivalent_plastic_strain").rows;
  const auto& plastic_end = end.point_data.at("plastic").rows;
  ASSERT_EQ(strain_end.size(), 16u);  // 2 x 2 cells of 4 points
  for (std::size_t p = 0; p < strain_end.size(); ++p) {
    EXPECT_EQ(strain_start[p][0], 0.0);
    EXPECT_EQ(plastic_start[p][0], 0.0);
    // 5 % compression, yield at about 0.1 %: nearly all of it plastic.
    EXPECT_GT(strain_end[p][0], 0.01) << "point " << p;
    EXPECT_EQ(plastic_end[p][0], 1.0) << "point " << p;
  }
}

}  // namespace
}  // namespace geompm

// The points' plastic state in the ParaView output (points.vtu): the accumulated equivalent
// plastic strain of the material's state, and `plastic`, 1 where the point flowed plastically in
// the step written. A Tresca block compressed one-dimensionally (an oedometer) yields in its
// first steps and then flows plastically in every step; at the start nothing has yielded.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
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

// A footing pushed into a Tresca block: under it the points flow plastically and cross cells,
// beside it they stay elastic. The points are reordered by cell every step, so `plastic` must
// follow each point by its id: it is 1 exactly where a point's plastic strain grew since the
// file before. The displacement formulation, as the case was written (pushed 0.3 m on cells of
// 0.25 m, the default mixed p-u formulation turns a point inside out at 0.19 m).
constexpr const char* kFooting = R"m(
analysis: {kinematics: plane_strain}
mesh: {generate: {x: {length: 2, cells: 8}, y: {length: 1.25, cells: 5}}}
materials:
  clay: {model: tresca, su: 5, E: 2000, nu: 0.3, density: 0, formulation: displacement}
bodies:
  block: {material: clay, region: {box: {min: [0, 0], max: [2, 1]}}, points_per_cell: 4}
point_sets:
  footing: {body: block, region: {box: {min: [0, 0.8], max: [0.5, 1]}}}
phases:
  - name: push
    time_step: 0.1
    prescribed_motion: [{point_set: footing, displacement: [0, "-0.3*t"]}]
    fixities:
      - {boundary: left, fix: normal}
      - {boundary: right, fix: normal}
      - {boundary: bottom, fix: all}
output:
  vtk: {every: 1, grid: false}
)m";

TEST(PlasticOutput, ThePlasticFlagFollowsEachPointAsPointsAreReordered) {
  const testing::ModelRun run =
      testing::run_spec(read_model_from_string(kFooting, "footing.yaml"), "plastic_reordered");
  ASSERT_GT(run.summary.steps, 6);
  int reordered = 0, flowed = 0, elastic = 0;
  // The last six files (each read costs a Python start): points have crossed cells by then.
  for (int step = run.summary.steps - 5; step <= run.summary.steps; ++step) {
    const auto file = [&](int k) {
      char name[40];
      std::snprintf(name, sizeof name, "points_%06d.vtu", k);
      return testing::read_with_meshio(run.output / "vtk" / name);
    };
    const testing::ReadVtu before = file(step - 1), now = file(step);
    std::map<long, double> strain_before;
    const auto& ids_before = before.point_data.at("id").rows;
    for (std::size_t p = 0; p < ids_before.size(); ++p)
      strain_before[std::lround(ids_before[p][0])] =
          before.point_data.at("equivalent_plastic_strain").rows[p][0];
    const auto& ids = now.point_data.at("id").rows;
    for (std::size_t p = 0; p < ids.size(); ++p) {
      const long id = std::lround(ids[p][0]);
      reordered += id != std::lround(ids_before[p][0]);
      const bool grew =
          now.point_data.at("equivalent_plastic_strain").rows[p][0] > strain_before.at(id);
      EXPECT_EQ(now.point_data.at("plastic").rows[p][0], grew ? 1.0 : 0.0)
          << "point " << id << ", step " << step;
      (grew ? flowed : elastic) += 1;
    }
  }
  // The case exercises what it is meant to: reordering, and points of both kinds.
  EXPECT_GT(reordered, 0);
  EXPECT_GT(flowed, 0);
  EXPECT_GT(elastic, 0);
}

}  // namespace
}  // namespace geompm

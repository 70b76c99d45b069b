// A body driven through a rigid translation (prescribed motion of all its points, docs/theory.md
// §5): its stresses and spring forces are round-off at the solution, so Newton's residual must be
// measured against the forces the motion would take in the body's stiffness, not against
// round-off. Before, every step failed with a relative residual of 1 and the run stopped. Exact
// answer: every point moves by the prescribed displacement, and nothing is strained.
#include <gtest/gtest.h>

#include "run_model.hpp"

namespace geompm {
namespace {

constexpr const char* translated_block = R"(
title: Rigid translation
analysis: {kinematics: plane_strain}
mesh:
  generate: {cell: quad4, origin: [0, 0], x: {length: 4, cells: 8}, y: {length: 4, cells: 8}}
materials:
  block: {model: linear_elastic, E: 1.0e4, nu: 0.3, density: 2}
bodies:
  block: {material: block, region: {box: {min: [1, 1], max: [2, 2]}}}
point_sets:
  all: {body: block, region: all}
phases:
  - name: move
    duration: 1.0
    time_step: 0.1
    prescribed_motion:
      - {point_set: all, displacement: ["0.5*t", "0.2*t"]}
output:
  vtk: {every: 0}
)";

TEST(RigidMotion, AQuasiStaticPrescribedTranslationConvergesAndStrainsNothing) {
  const auto run =
      testing::run_spec(read_model_from_string(translated_block, "move.yaml"), "rigid_motion");
  EXPECT_EQ(run.summary.status, "finished");
  EXPECT_EQ(run.summary.cutbacks, 0);
  const MaterialPoints& points = run.model->points;
  ASSERT_GT(points.size(), 0);
  for (Index p = 0; p < points.size(); ++p) {
    EXPECT_NEAR(points.displacement[p].x(), 0.5, 1e-9);
    EXPECT_NEAR(points.displacement[p].y(), 0.2, 1e-9);
    EXPECT_LT(points.stress[p].norm(), 1e-9 * 1.0e4);
  }
}

}  // namespace
}  // namespace geompm

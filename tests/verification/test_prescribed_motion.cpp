// Prescribed motion of a point set and its reaction: confined compression of an elastic block by
// its top layer of points (examples/oedometer/oedometer.yaml). Closed form (Hencky law):
// sigma_yy = (lambda + 2 mu) ln(l) / l with l = 1 - d / H over the height H below the driven
// points; reaction = sigma_yy x width.
#include <gtest/gtest.h>

#include <cmath>

#include "run_model.hpp"

namespace geompm {
namespace {

struct OedometerResult {
  double reaction_error;  // first step: before any point crosses a cell
  double displacement_error;
  double equilibrium_error;
};

OedometerResult run_oedometer(int cells) {
  auto spec = testing::read_example("oedometer/oedometer.yaml");
  const double h = 1.0 / cells;
  auto& grid = *spec.mesh.generate;
  grid.axes[0] = {AxisSegment{1.0, 1, 1.0}};
  grid.axes[1] = {AxisSegment{1.0 + h, cells + 1, 1.0}};
  spec.point_sets.at(0).region.min.y() = 1.0 - h / 2;  // the top row of points
  spec.phases.at(0).duration = 0.1;                    // one step of 1 % compression
  const auto run = testing::run_spec(spec, "oedometer_" + std::to_string(cells));
  const double E = 10000, nu = 0.3;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const double H = 1.0 - h / 4;  // initial height of the driven points (2 x 2 points per cell)
  const double d = -run.column("top_uy").back();
  const double l = 1.0 - d / H;
  const double exact = (lambda + 2 * mu) * std::log(l) / l * 1.0;  // width 1
  const double reaction = run.column("top_reaction").back();
  OedometerResult r;
  r.reaction_error = std::abs(reaction / exact - 1.0);
  r.displacement_error = std::abs(d - 0.01) / 0.01;
  r.equilibrium_error =
      std::abs(reaction + run.column("base_reaction").back()) / std::abs(reaction);
  return r;
}

TEST(PrescribedMotion, PointSetFollowsItsMotionAndTheReactionConverges) {
  std::vector<double> errors;
  for (int cells : {4, 8, 16, 32}) {
    const auto r = run_oedometer(cells);
    std::printf("[oedometer h = 1/%d] reaction error %.4f, displacement error %.2e\n", cells,
                r.reaction_error, r.displacement_error);
    EXPECT_LT(r.displacement_error, 1e-3);  // penalty alpha = 1e4 meets the motion to ~1e-4
    EXPECT_LT(r.equilibrium_error, 1e-8);   // weightless: the two reactions balance exactly
    errors.push_back(r.reaction_error);
  }
  // Loading through points inside the top cell is first-order accurate in h.
  for (std::size_t k = 1; k < errors.size(); ++k) EXPECT_LT(errors[k], 0.6 * errors[k - 1]);
  EXPECT_LT(errors.back(), 0.01);
}

// A body driven through a rigid translation (prescribed motion of all its points, docs/theory.md
// §5): its stresses and spring forces are round-off at the solution, so Newton's residual must be
// measured against the forces the motion would take in the body's stiffness, not against
// round-off. Before, every step failed with a relative residual of 1 and the run stopped. Exact
// answer: every point moves by the prescribed displacement, and nothing is strained.
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

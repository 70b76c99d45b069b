// Newton's extrapolated first iterate (`newton: {predictor: extrapolated}`, docs/theory.md §4.5):
// the last converged step's increment, scaled to this step's length. It changes where Newton
// starts, not the equations, so a run must find the same solution (to the Newton tolerance) as
// from a zero increment, and where the plastic zone and its flow carry over from step to step it
// should find it in fewer iterations. Where the extrapolated start fails, the step is solved again
// from zero before it is cut back.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "example_text.hpp"
#include "run_model.hpp"

namespace geompm {
namespace {

// The phase's Newton settings `newton` (a flow mapping, "newton: {...}") written into the example,
// which gives none: after its `dynamics: quasi_static` line.
std::string with_newton_line(const std::string& text, const std::string& newton) {
  return testing::replace_once(text, "    dynamics: quasi_static\n",
                               "    dynamics: quasi_static\n    " + newton + "\n");
}

std::string with_predictor(const std::string& newton) {
  return testing::replace_once(newton, "newton: {", "newton: {predictor: extrapolated, ");
}

// The example run twice, VTK output off: from zero and with the extrapolated start.
struct BothStarts {
  testing::ModelRun zero, extrapolated;
};
BothStarts run_both_starts(const std::string& example, const std::string& vtk,
                           const std::string& newton, const std::string& name,
                           const std::string& empty_cells = "",
                           const std::pair<std::string, std::string>& edit = {}) {
  auto text = testing::replace_once(testing::example_text(example), vtk, "vtk: {every: 0}");
  if (!edit.first.empty()) text = testing::replace_once(text, edit.first, edit.second);
  if (!empty_cells.empty())
    text = testing::with_numerics(text, "empty_cell_stiffness", empty_cells);
  return {testing::run_spec(read_model_from_string(with_newton_line(text, newton), name + ".yaml"),
                            name + "_zero"),
          testing::run_spec(read_model_from_string(with_newton_line(text, with_predictor(newton)),
                                                   name + ".yaml"),
                            name + "_extrapolated")};
}

double largest_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double scale = 0.0, difference = 0.0;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k) {
    scale = std::max(scale, std::abs(a[k]));
    difference = std::max(difference, std::abs(a[k] - b[k]));
  }
  return difference / scale;
}

TEST(NewtonPredictor, ExtrapolatedStartFindsTheSameSolutionInFewerIterations) {
  // The thick Tresca cylinder of docs/validation.md §10 (mixed p-u), expanded in 20 equal steps
  // and fully plastic from about the fifth: the plastic zone, the pressure field and their rates
  // carry over from step to step.
  const std::string newton =
      "newton: {max_iterations: 10, residual_tolerance: 1.0e-9, displacement_tolerance: 1.0e-9}";
  const auto [zero, extrapolated] =
      run_both_starts("thick_cylinder/thick_cylinder.yaml", "vtk: {every: 5}", newton, "tube");
  std::printf("[thick cylinder] Newton iterations: %d from zero, %d extrapolated (steps %d, %d)\n",
              zero.summary.iterations, extrapolated.summary.iterations, zero.summary.steps,
              extrapolated.summary.steps);
  ASSERT_EQ(zero.summary.steps, extrapolated.summary.steps);
  // The same solution: the reaction at every step within the Newton tolerance's reach (measured
  // 7e-10 of its largest value).
  EXPECT_LT(largest_difference(zero.column("force"), extrapolated.column("force")), 1e-7);
  // In fewer iterations: measured 60 against 25; a predictor that did nothing would give 60.
  EXPECT_LT(extrapolated.summary.iterations, 0.7 * zero.summary.iterations);
}

TEST(NewtonPredictor, AStepWhoseExtrapolatedStartFailsIsSolvedFromZero) {
  // The c-phi strip of docs/validation.md §8 (displacement formulation, E = 1000 c) pushed 0.05 B:
  // at about 0.0375 B the extrapolated start makes Newton cycle between the plastic states of two
  // nodes under the footing's edge, at every step size (measured), while the zero start, whose
  // first iterate is elastic, converges. With the fallback the run finishes, on the same curve;
  // without it, it stops there.
  const std::string newton =
      "newton: {max_iterations: 20, residual_tolerance: 1.0e-8, displacement_tolerance: 1.0e-8}";
  // As measured: 1e-6 of E in the empty cells. With the default 1e-4 the two starts take
  // different steps, and the forces at 0.05 B differ by 3e-4 (the path of plastic flow).
  // And steps that do not grow back after a cut-back (growth: 1): the step grows with Newton's
  // iteration count (docs/theory.md §4.6), which differs between the two starts, and the curve is
  // compared step by step.
  const auto [zero, extrapolated] =
      run_both_starts("mohr_coulomb_footing/mohr_coulomb_footing.yaml", "vtk: {every: 10}", newton,
                      "strip", "1.0e-6", {"max: 0.025}", "max: 0.025, growth: 1.0}"});
  const double q_zero = zero.column("force").back(),
               q_extrapolated = extrapolated.column("force").back();
  std::printf(
      "[c-phi strip] Newton iterations: %d from zero (at most %d a step), %d extrapolated (at "
      "most %d); force at 0.05 B %.5f and %.5f\n",
      zero.summary.iterations, zero.summary.max_iterations_in_a_step,
      extrapolated.summary.iterations, extrapolated.summary.max_iterations_in_a_step, q_zero,
      q_extrapolated);
  EXPECT_NEAR(-extrapolated.column("settlement").back(), 0.05, 1e-6);
  // The extrapolated start has half of max_iterations (20), and more only while it converges
  // superlinearly: a step with more than 10 iterations either fell back to the zero start
  // (measured: one step, 10 + 9, cycling) or converged quadratically after the tenth.
  EXPECT_GT(extrapolated.summary.max_iterations_in_a_step, 10);
  // The same curve (measured: the same 45 steps, forces equal to 1e-10).
  EXPECT_NEAR(q_extrapolated / q_zero, 1.0, 1e-6);
}

}  // namespace
}  // namespace geompm

// The adaptive time step (solver/step_controller): the step sequences it gives for scripted
// Newton outcomes, worked out by hand; the same sequence as a loop written out below from the
// rule (docs/theory.md §4.6) over many random outcomes; and a controller restored from another's
// saved state takes exactly the same steps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "geompm/solver/step_controller.hpp"

namespace geompm {
namespace {

StepControlSettings settings(double initial, double min, double max) {
  StepControlSettings s;
  s.initial = initial;
  s.min = min;
  s.max = max;
  return s;  // growth 1.5, cutback 0.5, target_iterations 8
}

// Runs the controller to the phase's end with every step converging in `iterations`; returns
// the steps taken.
std::vector<double> converged_steps(StepController& control, int iterations) {
  std::vector<double> steps;
  while (!control.finished() && steps.size() < 1000) {
    const double dt = control.trial_step();
    control.converged(dt, iterations);
    steps.push_back(dt);
  }
  return steps;
}

TEST(StepController, GrowsAfterEasyStepsUpToItsMaximum) {
  StepController control(settings(0.1, 0.01, 0.25), 1.0);
  const std::vector<double> steps = converged_steps(control, 3);
  // 0.1, x1.5 = 0.15, x1.5 = 0.225, capped at 0.25 twice: 0.725; then 0.25 leaves 0.025, which
  // is no sliver (>= 1 % of the step), and the last step takes the remaining 0.025.
  ASSERT_EQ(steps.size(), 6u);
  EXPECT_DOUBLE_EQ(steps[0], 0.1);
  EXPECT_DOUBLE_EQ(steps[1], 0.15);
  EXPECT_DOUBLE_EQ(steps[2], 0.225);
  EXPECT_DOUBLE_EQ(steps[3], 0.25);
  EXPECT_DOUBLE_EQ(steps[4], 0.25);
  EXPECT_NEAR(steps[5], 0.025, 1e-15);
  EXPECT_NEAR(control.time(), 1.0, 1e-15);
  EXPECT_TRUE(control.finished());
}

TEST(StepController, KeepsTheStepAtTheTargetCount) {
  StepController control(settings(0.2, 0.01, 0.5), 1.0);
  const std::vector<double> steps = converged_steps(control, 8);  // the target
  ASSERT_EQ(steps.size(), 5u);
  for (double dt : steps) EXPECT_NEAR(dt, 0.2, 1e-15);
}

TEST(StepController, GrowsByTheSquareRootOfTheIterationRatio) {
  StepController grows(settings(0.1, 0.001, 1.0), 10.0);
  grows.converged(grows.trial_step(), 6);
  EXPECT_DOUBLE_EQ(grows.trial_step(), 0.1 * std::sqrt(8.0 / 6.0));
  StepController at_most_growth(settings(0.1, 0.001, 1.0), 10.0);
  at_most_growth.converged(at_most_growth.trial_step(), 1);  // sqrt(8) > 1.5
  EXPECT_DOUBLE_EQ(at_most_growth.trial_step(), 0.15);
}

// Points switching between plastic states can set Newton's count whatever the step's size (the
// stiff N_q strip: 9 iterations a step down to 1e-7 of its phase): a converged step is never
// shortened, or such a run would shrink its step to nothing.
TEST(StepController, NeverShortensAConvergedStep) {
  for (int n : {9, 15, 100}) {
    StepController control(settings(0.1, 0.001, 1.0), 10.0);
    control.converged(control.trial_step(), n);
    EXPECT_DOUBLE_EQ(control.trial_step(), 0.1) << n << " iterations";
  }
}

// Issue 45: plastic steps take 6-8 Newton iterations whatever their size, and a rule that grew
// only after steps of at most 4 never grew back after a cut-back.
TEST(StepController, APlasticRunGrowsBackToItsMaximumAfterACutBack) {
  StepController control(settings(0.4, 0.001, 0.4), 100.0);
  ASSERT_TRUE(control.failed(control.trial_step()));
  ASSERT_TRUE(control.failed(control.trial_step()));
  ASSERT_DOUBLE_EQ(control.trial_step(), 0.1);
  int steps = 0;
  while (control.trial_step() < 0.4 && steps < 100) {
    control.converged(control.trial_step(), 7);
    ++steps;
  }
  // 0.1 (8/7)^(n/2) >= 0.4 for n >= 2 ln 4 / ln(8/7) = 20.8.
  EXPECT_EQ(steps, 21);
}

TEST(StepController, TakesASliverWithTheLastStep) {
  // 0.5 + 0.5 would leave 0.001 (0.2 % of the step): the second step takes it along.
  StepController control(settings(0.5, 0.01, 0.5), 1.001);
  const std::vector<double> steps = converged_steps(control, 1);
  ASSERT_EQ(steps.size(), 2u);
  EXPECT_EQ(steps[0], 0.5);
  EXPECT_EQ(steps[1], 1.001 - 0.5);
  EXPECT_TRUE(control.finished());
}

TEST(StepController, CutsBackUntilBelowTheMinimum) {
  StepController control(settings(0.4, 0.1, 0.4), 1.0);
  EXPECT_EQ(control.trial_step(), 0.4);
  EXPECT_TRUE(control.failed(0.4));
  EXPECT_EQ(control.trial_step(), 0.2);
  EXPECT_TRUE(control.failed(0.2));
  EXPECT_EQ(control.trial_step(), 0.1) << "the minimum itself is allowed";
  EXPECT_FALSE(control.failed(0.1)) << "0.05 is below the minimum";
  EXPECT_EQ(control.time(), 0.0) << "failed steps do not advance the time";
}

// Whether a failed step could still be cut back: the simulation tries a step that cannot once
// more with backtracking before it stops (docs/theory.md §4.4).
TEST(StepController, SaysWhetherAFailedStepCanBeCutBack) {
  const StepController control(settings(0.4, 0.1, 0.4), 1.0);
  EXPECT_TRUE(control.can_cut_back(0.4));
  EXPECT_TRUE(control.can_cut_back(0.2)) << "to the minimum itself";
  EXPECT_FALSE(control.can_cut_back(0.1));
  EXPECT_FALSE(control.can_cut_back(0.15));
}

TEST(StepController, GrowsAgainAfterACutBack) {
  StepController control(settings(0.4, 0.01, 0.4), 1.0);
  ASSERT_TRUE(control.failed(control.trial_step()));
  control.converged(control.trial_step(), 2);  // 0.2, grows by at most 1.5
  EXPECT_EQ(control.time(), 0.2);
  EXPECT_DOUBLE_EQ(control.trial_step(), 0.3);
}

// The rule written out as one loop (the shape of the loop run_analysis had before the controller,
// commit fa2d2d1): the controller must give the same step sequence, bit for bit.
struct Outcome {
  bool converged;
  int iterations;
};
std::vector<double> reference_steps(const StepControlSettings& ts, double duration,
                                    const std::vector<Outcome>& outcomes) {
  std::vector<double> tried;
  double t = 0.0, dt = ts.initial;
  std::size_t k = 0;
  while (t < duration * (1.0 - 1e-12) && k < outcomes.size()) {
    double remaining = duration - t;
    double dt_try = std::min(dt, remaining);
    if (remaining - dt_try < 0.01 * dt_try) dt_try = remaining;
    tried.push_back(dt_try);
    const Outcome o = outcomes[k++];
    if (!o.converged) {
      dt = dt_try * ts.cutback;
      if (dt < ts.min * (1.0 - 1e-12)) break;
      continue;
    }
    t += dt_try;
    double factor = std::sqrt(double(ts.target_iterations) / std::max(o.iterations, 1));
    factor = std::min(std::max(factor, 1.0), ts.growth);
    dt = std::min(dt_try * factor, ts.max);
  }
  return tried;
}

std::vector<double> controller_steps(const StepControlSettings& ts, double duration,
                                     const std::vector<Outcome>& outcomes) {
  std::vector<double> tried;
  StepController control(ts, duration);
  std::size_t k = 0;
  while (!control.finished() && k < outcomes.size()) {
    const double dt = control.trial_step();
    tried.push_back(dt);
    const Outcome o = outcomes[k++];
    if (!o.converged) {
      if (!control.failed(dt)) break;
      continue;
    }
    control.converged(dt, o.iterations);
  }
  return tried;
}

TEST(StepController, TakesTheStepsOfItsRuleOverRandomOutcomes) {
  std::mt19937 random(20261127);
  std::uniform_int_distribution<int> iterations(0, 15);
  std::bernoulli_distribution fails(0.2);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int compared = 0;
  for (int trial = 0; trial < 200; ++trial) {
    StepControlSettings ts;
    ts.max = 0.05 + 0.5 * unit(random);
    ts.initial = ts.max * (0.1 + 0.9 * unit(random));
    ts.min = ts.initial * 1e-3;
    ts.growth = 1.0 + unit(random);
    ts.cutback = 0.2 + 0.6 * unit(random);
    ts.target_iterations = 2 + trial % 12;
    const double duration = 0.5 + 3.0 * unit(random);
    std::vector<Outcome> outcomes(400);
    for (Outcome& o : outcomes) o = {!fails(random), iterations(random)};
    const std::vector<double> expected = reference_steps(ts, duration, outcomes);
    EXPECT_EQ(controller_steps(ts, duration, outcomes), expected) << "trial " << trial;
    compared += static_cast<int>(expected.size());
  }
  EXPECT_GT(compared, 2000);
}

TEST(StepController, ARestoredControllerTakesTheSameSteps) {
  const StepControlSettings ts = settings(0.05, 1e-4, 0.2);
  StepController original(ts, 2.0);
  for (int k = 0; k < 7; ++k) original.converged(original.trial_step(), k % 2 ? 3 : 6);
  ASSERT_TRUE(original.failed(original.trial_step()));

  StepController restored(ts, 2.0);
  restored.restore(original.state());
  while (!original.finished()) {
    ASSERT_FALSE(restored.finished());
    const double dt = original.trial_step();
    ASSERT_EQ(restored.trial_step(), dt);
    original.converged(dt, 4);
    restored.converged(dt, 4);
    ASSERT_EQ(restored.time(), original.time());
  }
  EXPECT_TRUE(restored.finished());
}

}  // namespace
}  // namespace geompm

// Newton's convergence test (docs/theory.md eq. 4.5 and §4.5) on its own: both criteria, the
// correction the converged residual asks for, and the ways Newton gives up, in their order.
#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "geompm/solver/convergence_test.hpp"

namespace geompm {
namespace {

NewtonSettings tolerances() {
  NewtonSettings settings;
  settings.residual_tolerance = 1e-8;
  settings.displacement_tolerance = 1e-6;
  settings.max_iterations = 5;
  return settings;
}

// A current_correction() that must not be asked.
double not_asked() {
  ADD_FAILURE() << "the current correction was measured";
  return 0.0;
}

TEST(ConvergenceTest, NeedsTheResidualAndTheCorrection) {
  const ConvergenceTest test(tolerances());
  const std::vector<double> small{1.0, 1e-9};
  // The last correction was small: converged without measuring another.
  EXPECT_EQ(test.judge(small, 1.0, 1e-7, not_asked).kind, Verdict::Converged);
  // The last correction was large: the one the current residual asks for decides.
  int asked = 0;
  EXPECT_EQ(test.judge(small, 1.0, 1e-3, [&] { return ++asked, 1e-7; }).kind, Verdict::Converged);
  EXPECT_EQ(test.judge(small, 1.0, 1e-3, [&] { return ++asked, 1e-5; }).kind, Verdict::GoOn);
  EXPECT_EQ(asked, 2);
  // A failed measurement (infinite) does not converge.
  EXPECT_EQ(
      test.judge(small, 1.0, 1e-3, [] { return std::numeric_limits<double>::infinity(); }).kind,
      Verdict::GoOn);
  // A residual above tolerance goes on whatever the correction.
  EXPECT_EQ(test.judge(std::vector<double>{1.0, 1e-7}, 1.0, 0.0, not_asked).kind, Verdict::GoOn);
}

TEST(ConvergenceTest, TheFirstIterateHasNoCorrectionToTest) {
  const ConvergenceTest test(tolerances());
  EXPECT_EQ(test.judge(std::vector<double>{1e-9}, 1.0, 1.0, not_asked).kind, Verdict::Converged);
  // An exactly zero residual has converged whatever the force scale made of it.
  EXPECT_EQ(test.judge(std::vector<double>{0.5}, 0.0, 1.0, not_asked).kind, Verdict::Converged);
}

TEST(ConvergenceTest, GivesUpOnANonFiniteResidualFirst) {
  const ConvergenceTest test(tolerances());
  const Verdict v = test.judge(std::vector<double>{std::numeric_limits<double>::quiet_NaN()}, 0.0,
                               0.0, not_asked);
  EXPECT_EQ(v.kind, Verdict::Failed);
  EXPECT_EQ(v.failure, "the residual is not finite");
}

TEST(ConvergenceTest, GivesUpOnDivergenceAndAfterMaxIterations) {
  const ConvergenceTest test(tolerances());
  const Verdict diverged = test.judge(std::vector<double>{1e-3, 1e6}, 1.0, 1.0, not_asked);
  EXPECT_EQ(diverged.kind, Verdict::Failed);
  EXPECT_NE(diverged.failure.find("diverged"), std::string::npos) << diverged.failure;
  EXPECT_EQ(test.judge(std::vector<double>{1e-3, 1e4}, 1.0, 1.0, not_asked).kind, Verdict::GoOn);
  const std::vector<double> five(6, 1e-3);  // iterate k = 5 = max_iterations
  const Verdict out = test.judge(five, 1.0, 1.0, not_asked);
  EXPECT_EQ(out.kind, Verdict::Failed);
  EXPECT_NE(out.failure.find("no convergence in 5 iterations"), std::string::npos) << out.failure;
  EXPECT_EQ(test.judge(std::vector<double>(5, 1e-3), 1.0, 1.0, not_asked).kind, Verdict::GoOn);
}

TEST(ConvergenceTest, PastThePatienceOnlySuperlinearConvergenceGoesOn) {
  NewtonSettings settings = tolerances();
  settings.patience = 2;
  const ConvergenceTest test(settings);
  // Linear (a fifth an iteration) at k = 2: given up.
  const Verdict linear = test.judge(std::vector<double>{1.0, 0.2, 0.04}, 1.0, 1.0, not_asked);
  EXPECT_EQ(linear.kind, Verdict::Failed);
  EXPECT_NE(linear.failure.find("superlinearly"), std::string::npos) << linear.failure;
  // Superlinear (below a tenth of the one before), or before the patience: on.
  EXPECT_EQ(test.judge(std::vector<double>{1.0, 0.2, 0.01}, 1.0, 1.0, not_asked).kind,
            Verdict::GoOn);
  EXPECT_EQ(test.judge(std::vector<double>{1.0, 0.9}, 1.0, 1.0, not_asked).kind, Verdict::GoOn);
  // A residual within tolerance whose correction is still to be seen is not given up on.
  EXPECT_EQ(test.judge(std::vector<double>{1.0, 2e-8, 0.9e-8}, 1.0, 1.0, [] { return 1e-3; }).kind,
            Verdict::GoOn);
}

}  // namespace
}  // namespace geompm

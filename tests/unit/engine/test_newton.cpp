// Newton's backtracking (docs/theory.md §4.4) on R(x) = -atan(x), the classic case where plain
// Newton from |x0| > 1.39 overshoots further each iteration and diverges, while halving an
// overshooting correction brings it into the quadratic basin around the root x = 0; and the
// tangent check (newton.tangent_check), which must tell a consistent tangent from a wrong one; an
// inadmissible iterate stops Newton with the problem's own reason.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "geompm/solver/newton.hpp"

namespace geompm {
namespace {

class Arctangent final : public NonlinearProblem {
 public:
  explicit Arctangent(double tangent_factor = 1.0, double admissible_up_to = HUGE_VAL)
      : tangent_factor_(tangent_factor), admissible_up_to_(admissible_up_to) {}
  bool evaluate(const Vector& x, Vector& residual, double& force_scale,
                SparseMatrix* tangent) override {
    if (std::abs(x(0)) > admissible_up_to_) return false;
    residual = Vector::Constant(1, -std::atan(x(0)));
    force_scale = 1.0;
    if (tangent) {
      *tangent = SparseMatrix(1, 1);
      tangent->insert(0, 0) = tangent_factor_ / (1.0 + x(0) * x(0));  // K = -dR/dx if factor 1
    }
    return true;
  }
  double increment_norm(const Vector& x) const override { return std::max(std::abs(x(0)), 1.0); }
  std::string inadmissible_reason() const override { return "beyond the admissible range"; }

 private:
  double tangent_factor_;
  double admissible_up_to_;
};

// Newton on the arctangent from x0 with a tangent `tangent_factor` times the consistent one.
NewtonResult solve_arctangent(double tangent_factor, const NewtonSettings& settings, double x0,
                              Vector& x) {
  Arctangent problem(tangent_factor);
  auto solver = create_linear_solver("sparse_lu");
  x = Vector::Constant(1, x0);
  SparseMatrix tangent;
  return solve_newton(problem, *solver, settings, x, tangent);
}

NewtonSettings settings_to(double tolerance, int max_iterations) {
  NewtonSettings settings;
  settings.max_iterations = max_iterations;
  settings.residual_tolerance = tolerance;
  settings.displacement_tolerance = tolerance;
  return settings;
}

NewtonResult solve_from(double x0, int halvings, Vector& x) {
  NewtonSettings settings = settings_to(1e-12, 30);
  settings.max_halvings = halvings;
  return solve_arctangent(1.0, settings, x0, x);
}

TEST(NewtonBacktracking, PlainNewtonDivergesOnTheArctangent) {
  Vector x;
  EXPECT_FALSE(solve_from(2.0, 0, x).converged);
}

TEST(NewtonBacktracking, HalvingTheOvershootFindsTheRoot) {
  Vector x;
  const NewtonResult result = solve_from(2.0, 4, x);
  ASSERT_TRUE(result.converged) << result.failure;
  EXPECT_NEAR(x(0), 0.0, 1e-12);
  EXPECT_GT(result.halvings, 0);
  EXPECT_LT(result.iterations, 15);
}

// Plain Newton from x0 = 2 jumps to x1 = 2 - atan(2) (1 + 4) = -3.54: beyond |x| <= 3 the problem
// refuses the iterate, and Newton stops there in the problem's words (the engine's: a point
// turned inside out, or its stress update failed); with |x| <= 4 the same iterate is evaluated.
TEST(NewtonInadmissible, StopsWithTheProblemsReason) {
  Arctangent problem(1.0, 3.0);
  auto solver = create_linear_solver("sparse_lu");
  Vector x = Vector::Constant(1, 2.0);
  SparseMatrix tangent;
  const NewtonResult refused = solve_newton(problem, *solver, settings_to(1e-12, 30), x, tangent);
  EXPECT_FALSE(refused.converged);
  EXPECT_TRUE(refused.inadmissible);
  EXPECT_EQ(refused.failure, "beyond the admissible range");
  EXPECT_EQ(refused.iterations, 1);
  Arctangent wider(1.0, 4.0);
  x = Vector::Constant(1, 2.0);
  const NewtonResult diverged = solve_newton(wider, *solver, settings_to(1e-12, 1), x, tangent);
  EXPECT_FALSE(diverged.inadmissible);
  EXPECT_NEAR(x(0), 2.0 - std::atan(2.0) * 5.0, 1e-12);
}

NewtonResult solve_checked(double tangent_factor, Vector& x) {
  NewtonSettings settings = settings_to(1e-10, 60);
  settings.tangent_check = 1e-6;
  return solve_arctangent(tangent_factor, settings, 0.5, x);
}

TEST(NewtonTangentCheck, AConsistentTangentMatchesTheFiniteDifference) {
  Vector x;
  const NewtonResult result = solve_checked(1.0, x);
  ASSERT_TRUE(result.converged) << result.failure;
  ASSERT_EQ(result.tangent_errors.size(), static_cast<std::size_t>(result.iterations));
  // Truncation O(e |R''/R'| |dx|) and round-off 1e-16 / e: below 1e-4 while |R| is not tiny.
  EXPECT_LT(result.tangent_errors.front(), 1e-5);
}

TEST(NewtonTangentCheck, AWrongTangentIsReportedAndSlowsNewton) {
  Vector x;
  // A tangent 30 % too stiff: dR/dx along dx is off by 1 - 1/1.3 = 23 % (relative to R).
  const NewtonResult result = solve_checked(1.3, x);
  ASSERT_TRUE(result.converged) << result.failure;  // linear convergence, still to the root
  EXPECT_NEAR(x(0), 0.0, 1e-9);
  ASSERT_FALSE(result.tangent_errors.empty());
  EXPECT_NEAR(result.tangent_errors.front(), 1.0 - 1.0 / 1.3, 1e-3);
  const NewtonResult consistent = solve_checked(1.0, x);
  EXPECT_GT(result.iterations, consistent.iterations);
}

// Patience (the extrapolated start's budget, docs/theory.md §4.5): after `patience` iterations
// Newton goes on only while each residual is below a tenth of the one before. On the arctangent
// from x0 = 0.5 the consistent tangent converges quadratically (each residual far below a tenth of
// the one before) and is let run past the patience; a tangent 30 % too stiff converges linearly
// (each residual about 0.23 of the one before) and gives up at the patience.
NewtonResult solve_with_patience(double tangent_factor, int patience) {
  NewtonSettings settings = settings_to(1e-14, 60);
  settings.patience = patience;
  Vector x;
  return solve_arctangent(tangent_factor, settings, 0.5, x);
}

TEST(NewtonPatience, QuadraticConvergenceGoesOnPastThePatience) {
  const NewtonResult without = solve_with_patience(1.0, 0);
  ASSERT_TRUE(without.converged) << without.failure;
  ASSERT_GE(without.iterations, 3);
  const NewtonResult with = solve_with_patience(1.0, 2);
  ASSERT_TRUE(with.converged) << with.failure;
  EXPECT_EQ(with.iterations, without.iterations);
}

TEST(NewtonPatience, LinearConvergenceGivesUpAtThePatience) {
  const NewtonResult without = solve_with_patience(1.3, 0);
  ASSERT_TRUE(without.converged) << without.failure;
  ASSERT_GT(without.iterations, 4);
  const NewtonResult with = solve_with_patience(1.3, 4);
  EXPECT_FALSE(with.converged);
  EXPECT_EQ(with.iterations, 4);
  EXPECT_NE(with.failure.find("superlinearly"), std::string::npos) << with.failure;
}

// A residual already within tolerance when the patience runs out, with only the correction's
// test pending, is converged, not stalling: Newton goes on although it converges linearly.
TEST(NewtonPatience, AConvergedResidualIsNotGivenUp) {
  NewtonSettings settings = settings_to(2e-3, 60);
  settings.displacement_tolerance = 1e-10;
  settings.patience = 4;
  Vector x;
  const NewtonResult with = solve_arctangent(1.3, settings, 0.5, x);
  ASSERT_TRUE(with.converged) << with.failure;
  ASSERT_GT(with.residuals.size(), 5u);
  // The case in question: at the patience the residual is within tolerance and the residuals
  // fall linearly (by about 0.23 an iteration), so the superlinear test alone would give up.
  EXPECT_LE(with.residuals[4], settings.residual_tolerance);
  EXPECT_GT(with.residuals[4], superlinear_contraction * with.residuals[3]);
  settings.patience = 0;
  const NewtonResult without = solve_arctangent(1.3, settings, 0.5, x);
  ASSERT_TRUE(without.converged) << without.failure;
  EXPECT_EQ(with.iterations, without.iterations);
}

}  // namespace
}  // namespace geompm

// Newton's backtracking (docs/theory.md §4.4) on R(x) = -atan(x), the classic case where plain
// Newton from |x0| > 1.39 overshoots further each iteration and diverges, while halving an
// overshooting correction brings it into the quadratic basin around the root x = 0; and the
// tangent check (newton.tangent_check), which must tell a consistent tangent from a wrong one; an
// inadmissible iterate stops Newton with the problem's own reason; the energy line search on a
// residual with a steep ramp between two soft branches, where plain Newton and backtracking cycle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
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

// Newton reached the root, with the globalisation under test (its count `used`) taking part.
void expect_root_found(const NewtonResult& result, const Vector& x, double root, int used) {
  ASSERT_TRUE(result.converged) << result.failure;
  EXPECT_NEAR(x(0), root, 1e-12);
  EXPECT_GT(used, 0);
}

TEST(NewtonBacktracking, PlainNewtonDivergesOnTheArctangent) {
  Vector x;
  EXPECT_FALSE(solve_from(2.0, 0, x).converged);
}

TEST(NewtonBacktracking, HalvingTheOvershootFindsTheRoot) {
  Vector x;
  const NewtonResult result = solve_from(2.0, 4, x);
  expect_root_found(result, x, 0.0, result.halvings);
  EXPECT_LT(result.iterations, 15);
  // Each correction's kept fraction is 1/2 to the power of its halvings, and they add up.
  ASSERT_EQ(result.step_lengths.size(), std::size_t(result.iterations));
  int halved = 0;
  for (const double kept : result.step_lengths) {
    const double times = -std::log2(kept);
    EXPECT_NEAR(times, std::round(times), 1e-12) << kept;
    halved += int(std::round(times));
  }
  EXPECT_EQ(halved, result.halvings);
}

// Plain Newton from x0 = 2 jumps to x1 = 2 - atan(2) (1 + 4) = -3.54: beyond |x| <= 3 the problem
// refuses the iterate (the engine's: a point turned inside out, or its stress update failed).
// Without halvings Newton stops there in the problem's words; with |x| <= 4 the same iterate is
// evaluated.
TEST(NewtonInadmissible, StopsWithTheProblemsReason) {
  Arctangent problem(1.0, 3.0);
  auto solver = create_linear_solver("sparse_lu");
  Vector x = Vector::Constant(1, 2.0);
  SparseMatrix tangent;
  NewtonSettings no_halvings = settings_to(1e-12, 30);
  no_halvings.inadmissible_halvings = 0;
  const NewtonResult refused = solve_newton(problem, *solver, no_halvings, x, tangent);
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

// The default settings (newton.line_search 0) halve the inadmissible iterate: x = 2 - 5.54 / 2 =
// -0.77 is admissible and inside the arctangent's quadratic basin, so plain Newton finds the root
// where it would otherwise have stopped (and it does not halve the iterates whose residual grew).
TEST(NewtonInadmissible, TheDefaultHalvesAnInadmissibleIterate) {
  Arctangent problem(1.0, 3.0);
  auto solver = create_linear_solver("sparse_lu");
  Vector x = Vector::Constant(1, 2.0);
  SparseMatrix tangent;
  const NewtonResult result = solve_newton(problem, *solver, settings_to(1e-12, 30), x, tangent);
  expect_root_found(result, x, 0.0, result.halvings);
  EXPECT_EQ(result.halvings, 1);
  EXPECT_DOUBLE_EQ(result.step_lengths.front(), 0.5);
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

// R(x) = f - r(x) with r soft (slope 1) on either side of a steep ramp (slope 1000 over
// 0 <= x <= 0.01) and f = r(0.005): the root lies on the ramp. It is the force of a point whose
// returned stress sweeps across a flat face of the yield surface within a small change of its
// trial state (docs/theory.md §4.4): from either soft branch the tangent sees no ramp, and Newton
// jumps across it to the other branch and back (x = -1, 5, -4.99, 5, ...: a two-cycle; the
// residual's norm falls from 6 to 5 and stays at 5 and 4.99, so backtracking, which halves a
// correction only when the residual grows, cycles too).
class SteepRamp final : public NonlinearProblem {
 public:
  static double force(double x) { return x < 0.0 ? x : x < 0.01 ? 1000.0 * x : 10.0 + (x - 0.01); }
  bool evaluate(const Vector& x, Vector& residual, double& force_scale,
                SparseMatrix* tangent) override {
    residual = Vector::Constant(1, force(0.005) - force(x(0)));
    force_scale = 1.0;
    if (tangent) {
      *tangent = SparseMatrix(1, 1);
      tangent->insert(0, 0) = x(0) >= 0.0 && x(0) < 0.01 ? 1000.0 : 1.0;
    }
    return true;
  }
  double increment_norm(const Vector& x) const override { return std::max(std::abs(x(0)), 1.0); }
};

NewtonResult solve_ramp(double energy_search, int halvings, Vector& x) {
  SteepRamp problem;
  auto solver = create_linear_solver("sparse_lu");
  NewtonSettings settings = settings_to(1e-10, 30);
  settings.max_halvings = halvings;
  settings.energy_search = energy_search;
  x = Vector::Constant(1, -1.0);
  SparseMatrix tangent;
  return solve_newton(problem, *solver, settings, x, tangent);
}

TEST(NewtonEnergySearch, FindsTheRootOnASteepRampWherePlainNewtonAndBacktrackingCycle) {
  Vector x;
  const NewtonResult plain = solve_ramp(0.0, 0, x);
  EXPECT_FALSE(plain.converged);
  ASSERT_GE(plain.residuals.size(), 5u);
  EXPECT_NEAR(plain.residuals[3], plain.residuals[5], 1e-9);  // the two-cycle
  EXPECT_FALSE(solve_ramp(0.0, 6, x).converged);
  const NewtonResult searched = solve_ramp(0.1, 0, x);
  expect_root_found(searched, x, 0.005, searched.searches);
  EXPECT_LE(searched.iterations, 4);
  // The shortened corrections are the ones the search took part in, and shortened, not lengthened.
  ASSERT_EQ(searched.step_lengths.size(), std::size_t(searched.iterations));
  EXPECT_EQ(std::count_if(searched.step_lengths.begin(), searched.step_lengths.end(),
                          [](double kept) { return kept < 1.0; }),
            searched.searches);
  for (const double kept : searched.step_lengths) EXPECT_GT(kept, 0.0);
}

// Where the full correction does not overshoot by more than the tolerance, the search is not
// entered: on the arctangent from x0 = 0.2 the first correction lands at x1 = -0.0053, where
// dx . R is -0.027 of its start, and Newton converges as without the search, iterate for iterate.
// (From x0 = 0.5 it lands at -0.080, -0.17 of the start, and is shortened.)
TEST(NewtonEnergySearch, ANewtonStepThatDoesNotOvershootIsKept) {
  NewtonSettings settings = settings_to(1e-12, 30);
  Vector x;
  const NewtonResult without = solve_arctangent(1.0, settings, 0.2, x);
  settings.energy_search = 0.1;
  const NewtonResult with = solve_arctangent(1.0, settings, 0.2, x);
  ASSERT_TRUE(with.converged) << with.failure;
  EXPECT_EQ(with.searches, 0);
  EXPECT_EQ(with.residuals, without.residuals);
  settings.energy_search = 0.1;
  EXPECT_GT(solve_arctangent(1.0, settings, 0.5, x).searches, 0);
}

// A saddle point, as the mixed p-u system is: R = (1 - x1 - x1^3, x2 - 3), K = diag(1 + 3 x1^2,
// -1). From x = 0 the first correction (1, 3) has s(0) = dx . R = 1 - 9 < 0: it does not descend an
// energy, and the search (which would read the overshoot of x1 as one) stays out of it.
class SaddlePoint final : public NonlinearProblem {
 public:
  bool evaluate(const Vector& x, Vector& residual, double& force_scale,
                SparseMatrix* tangent) override {
    residual = Vector(2);
    residual << 1.0 - x(0) - x(0) * x(0) * x(0), x(1) - 1.2;
    force_scale = 1.0;
    if (tangent) {
      *tangent = SparseMatrix(2, 2);
      tangent->insert(0, 0) = 1.0 + 3.0 * x(0) * x(0);
      tangent->insert(1, 1) = -1.0;
    }
    return true;
  }
  double increment_norm(const Vector& x) const override { return std::max(x.norm(), 1.0); }
};

TEST(NewtonEnergySearch, ACorrectionThatDoesNotDescendAnEnergyIsNotSearched) {
  NewtonResult result[2];
  for (const int with : {0, 1}) {
    SaddlePoint problem;
    auto solver = create_linear_solver("sparse_lu");
    NewtonSettings settings = settings_to(1e-12, 30);
    settings.energy_search = with ? 0.1 : 0.0;
    Vector x = Vector::Zero(2);
    SparseMatrix tangent;
    result[with] = solve_newton(problem, *solver, settings, x, tangent);
    ASSERT_TRUE(result[with].converged) << result[with].failure;
  }
  EXPECT_EQ(result[1].searches, 0);
  EXPECT_EQ(result[1].residuals, result[0].residuals);
}

// Newton drives the solver through the LinearSolver interface only, as it would an iterative one:
// one setup and one solve per correction, and where the residual has converged before the
// correction has, one more solve against the last setup (no new setup) to measure the correction
// the converged residual asks for. The iterations the solver reports are summed.
class CountingSolver final : public LinearSolver {
 public:
  void analyse(const SparseMatrix& pattern, const LinearSolverHints& hints) override {
    inner_->analyse(pattern, hints);
  }
  void setup(const SparseMatrix& a) override {
    ++setups;
    inner_->setup(a);
  }
  int solve(const Vector& b, Vector& x, double relative_tolerance) override {
    ++solves;
    tolerance = relative_tolerance;
    inner_->solve(b, x, relative_tolerance);
    return 3;
  }
  const char* name() const override { return "counting"; }
  int setups = 0, solves = 0;
  double tolerance = 0.0;

 private:
  std::unique_ptr<LinearSolver> inner_ = create_linear_solver("sparse_lu");
};

TEST(NewtonLinearSolver, SetsUpOncePerCorrectionAndReSolvesForTheCorrectionCheck) {
  // A loose residual tolerance and a tight correction tolerance: the residual converges first.
  NewtonSettings settings = settings_to(1e-4, 30);
  settings.displacement_tolerance = 1e-12;
  Arctangent problem;
  CountingSolver solver;
  Vector x = Vector::Constant(1, 0.5);
  SparseMatrix tangent;
  const NewtonResult result = solve_newton(problem, solver, settings, x, tangent);
  ASSERT_TRUE(result.converged) << result.failure;
  EXPECT_EQ(solver.setups, result.iterations);
  EXPECT_GT(solver.solves, solver.setups);  // the correction checks
  EXPECT_EQ(result.linear_iterations, 3 * result.iterations);
  EXPECT_EQ(solver.tolerance, settings.linear_tolerance);
  // The same iterates as with the solver used directly.
  Vector y;
  const NewtonResult direct = solve_arctangent(1.0, settings, 0.5, y);
  EXPECT_EQ(result.residuals, direct.residuals);
  EXPECT_EQ(x(0), y(0));
}

}  // namespace
}  // namespace geompm

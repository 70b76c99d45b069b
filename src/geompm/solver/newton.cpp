#include "geompm/solver/newton.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "geompm/solver/backtracking.hpp"
#include "geompm/solver/convergence_test.hpp"
#include "geompm/solver/energy_line_search.hpp"
#include "geompm/solver/tangent_check.hpp"

namespace geompm {

NewtonResult solve_newton(NonlinearProblem& problem, LinearSolver& solver,
                          const NewtonSettings& settings, Vector& x, SparseMatrix& tangent) {
  NewtonResult result;
  const ConvergenceTest convergence(settings);
  Backtracking backtracking(settings.max_halvings, settings.inadmissible_halvings);
  EnergyLineSearch energy_search(settings.energy_search);
  Vector residual, dx;
  double force_scale = 0.0;
  double last_correction = 0.0;
  double eta = -1.0;  // the forcing term of the last solve (none yet)
  ForcingSettings forcing = settings.forcing;
  forcing.floor = settings.linear_tolerance;
  // The size of a correction relative to the step's increment at x, or to a full step's where
  // the step was cut back below it (eq. 4.5).
  const auto relative_to_increment = [&problem, &x, &settings](const Vector& correction) {
    const double scale = std::max(problem.increment_norm(x), settings.increment_floor);
    return scale > 0 ? correction.norm() / scale : 0.0;
  };
  // The correction the current residual asks for, against the operator of the last setup (for a
  // direct solver one back-substitution with the factorisation at hand; for an iterative one a
  // solve with the preconditioner at hand, to a tenth at least: the test compares its size with
  // the tolerance); infinite if the solve fails.
  const auto current_correction = [&] {
    Vector correction;
    try {
      const auto start = std::chrono::steady_clock::now();
      solver.solve(
          residual, correction,
          std::min(0.1, forcing_term(forcing, result.residuals, eta, settings.residual_tolerance)));
      result.linear_seconds +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    } catch (const LinearSolverFailure&) {
      return std::numeric_limits<double>::infinity();
    }
    return relative_to_increment(correction);
  };
  for (int k = 0;; ++k) {
    const bool admissible = problem.evaluate(x, residual, force_scale, &tangent);
    const double norm = admissible ? residual.norm() : 0.0;
    const double relative = norm / std::max(force_scale, 1e-300);
    // Globalisation (theory §4.4): the correction that led here is shortened and x evaluated
    // again where it went past the energy's minimum along it (energy line search, tried first)
    // or overshot (backtracking). Shortened corrections are not counted as iterations.
    if (k > 0) {
      double kept = 1.0;
      if (admissible && std::isfinite(relative) && backtracking.whole())
        kept = energy_search.shorten(problem, x, dx, residual);
      if (kept < 1.0) {
        ++result.searches;
      } else {
        const auto overshoot = Backtracking::overshoot(
            admissible, relative, result.residuals.back(), energy_search.searched());
        if (backtracking.retreat(overshoot, x, dx)) {
          kept = 0.5;
          ++result.halvings;
        }
      }
      if (kept < 1.0) {
        last_correction = relative_to_increment(dx);
        result.step_lengths.back() *= kept;
        --k;
        continue;
      }
    }
    backtracking.accept();
    if (!admissible) {
      result.failure = problem.inadmissible_reason();
      result.inadmissible = true;
      return result;
    }
    result.residuals.push_back(relative);
    result.largest.push_back(problem.largest_residual_unknown());
    result.active.push_back(problem.active_set());
    if (k == 0) result.active.back().changed = -1;  // against another solve's iterate
    const Verdict verdict =
        convergence.judge(result.residuals, norm, last_correction, current_correction);
    if (verdict.kind != Verdict::GoOn) {
      result.converged = verdict.kind == Verdict::Converged;
      result.failure = verdict.failure;
      return result;
    }
    // The Newton correction K dx = R (eq. 4.4), to the forcing term's tolerance (eq. 4.11).
    const auto start = std::chrono::steady_clock::now();
    try {
      solver.setup(tangent);
      eta = forcing_term(forcing, result.residuals, eta, settings.residual_tolerance);
      result.linear_iterations += solver.solve(residual, dx, eta);
    } catch (const LinearSolverFailure& e) {
      result.failure = e.what();
      return result;
    }
    result.linear_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    energy_search.start(dx, residual);
    if (settings.tangent_check > 0.0)
      result.tangent_errors.push_back(
          directional_tangent_error(problem, x, dx, residual, settings.tangent_check));
    x += dx;
    ++result.iterations;
    last_correction = relative_to_increment(dx);
    result.corrections.push_back(last_correction);
    result.step_lengths.push_back(1.0);
    Index moved_most = -1;
    if (dx.size() > 0) dx.cwiseAbs().maxCoeff(&moved_most);
    result.largest_correction.push_back(moved_most >= 0 ? problem.problem_unknown(moved_most) : -1);
  }
}

}  // namespace geompm

#include "geompm/solver/newton.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace geompm {
namespace {

// The tangent's relative error along the correction dx = K^-1 R(x): the directional finite
// difference of the residual, (R(x + e dx) - R(x)) / e, against -K dx = -R(x). Consistent
// tangents give O(e) (and round-off of order 1e-16 |R| / (e |R(x)|)); an inconsistent one an
// error of order one. The problem is evaluated at x + e dx without the tangent, and again at x
// by the caller's next iteration.
double directional_tangent_error(NonlinearProblem& problem, const Vector& x, const Vector& dx,
                                 const Vector& residual, double e) {
  Vector perturbed_residual;
  double force_scale = 0.0;
  if (!problem.evaluate(x + e * dx, perturbed_residual, force_scale, nullptr))
    return std::numeric_limits<double>::quiet_NaN();
  const double norm = residual.norm();
  return norm > 0.0 ? ((perturbed_residual - residual) / e + residual).norm() / norm : 0.0;
}

// The energy line search's budget of residual evaluations for one correction.
constexpr int energy_search_evaluations = 10;

// The energy line search (docs/theory.md §4.4, eq. 4.5a; Crisfield 1991, ch. 9): the step length
// eta along the correction dx from `start` at which the residual is orthogonal to dx,
// s(eta) = dx . R(start + eta dx) = 0, to within |s| <= tolerance s(0). s(0) = dx . K dx > 0 and
// the full step gave s(1) < -tolerance s(0): the correction went past the energy's minimum along
// it. Regula falsi between the two (Illinois: the end kept twice in a row has its s halved),
// each trial a residual without the tangent; returns the trial eta with the smallest |s|, or 1
// if none improves on the full step.
double energy_line_search(NonlinearProblem& problem, const Vector& start, const Vector& dx,
                          double s_start, double s_full, double tolerance) {
  double below = 0.0, s_below = s_start, beyond = 1.0, s_beyond = s_full;
  double best = 1.0, s_best = std::abs(s_full);
  int kept = 0;  // +1: `below` was moved last, -1: `beyond`
  Vector residual;
  double force_scale = 0.0;
  for (int m = 0; m < energy_search_evaluations; ++m) {
    const double margin = 0.05 * (beyond - below);
    const double eta = std::clamp(below + (beyond - below) * s_below / (s_below - s_beyond),
                                  below + margin, beyond - margin);
    const bool admissible = problem.evaluate(start + eta * dx, residual, force_scale, nullptr);
    // An inadmissible trial lies beyond the minimum as far as the search is concerned.
    const double s = admissible ? dx.dot(residual) : -s_start;
    if (admissible && std::abs(s) < s_best) {
      best = eta;
      s_best = std::abs(s);
      if (s_best <= tolerance * s_start) break;
    }
    if (s > 0.0) {
      below = eta;
      s_below = s;
      if (kept == 1) s_beyond *= 0.5;
      kept = 1;
    } else {
      beyond = eta;
      s_beyond = s;
      if (kept == -1) s_below *= 0.5;
      kept = -1;
    }
  }
  return best;
}

}  // namespace

NewtonResult solve_newton(NonlinearProblem& problem, LinearSolver& solver,
                          const NewtonSettings& settings, Vector& x, SparseMatrix& tangent) {
  NewtonResult result;
  Vector residual, dx;
  double force_scale = 0.0;
  double last_correction = 0.0;
  bool analysed = false;
  int halvings = 0;          // of the current correction
  bool searched = false;     // the current correction's length came from the energy line search
  double along_start = 0.0;  // s(0) = dx . R at the iterate the correction started from
  // The size of a correction relative to the step's increment at x.
  const auto relative_to_increment = [&problem, &x](const Vector& correction) {
    const double scale = problem.increment_norm(x);
    return scale > 0 ? correction.norm() / scale : 0.0;
  };
  for (int k = 0;; ++k) {
    const bool admissible = problem.evaluate(x, residual, force_scale, &tangent);
    const double norm = admissible ? residual.norm() : 0.0;
    const double relative = norm / std::max(force_scale, 1e-300);
    // Energy line search: the full correction went past the minimum of the energy along it, as
    // when a point's returned stress sweeps across a straight side of the yield surface's section
    // between the iterates (theory §4.4): it is shortened to the length at which the residual is
    // orthogonal to it, and the iterate there is evaluated again with its tangent.
    // Only where the correction descends the energy, s(0) > 0: the mixed p-u system is a saddle
    // point, along whose corrections dx . K dx can have either sign.
    if (k > 0 && settings.energy_search > 0.0 && !searched && halvings == 0 && admissible &&
        std::isfinite(relative) && along_start > 0.0) {
      const double along_full = dx.dot(residual);
      if (along_full < -settings.energy_search * along_start) {
        searched = true;
        const Vector start = x - dx;
        const double eta =
            energy_line_search(problem, start, dx, along_start, along_full, settings.energy_search);
        if (eta < 1.0) {
          dx *= eta;
          x = start + dx;
          last_correction = relative_to_increment(dx);
          ++result.searches;
          result.step_lengths.back() *= eta;
          --k;
          continue;
        }
      }
    }
    // Backtracking: the correction overshot (the residual grew, or a point turned inside out), so
    // go back half of it. For a small enough fraction the Newton direction reduces the residual;
    // a plastic switch at a few points, which can throw the full correction off, is approached
    // in shorter strides instead of failing the step. A length the energy line search found
    // stands unless its iterate is inadmissible.
    const bool overshot = !admissible || !std::isfinite(relative) ||
                          (k > 0 && !searched && relative > result.residuals.back());
    if (k > 0 && overshot && halvings < settings.max_halvings) {
      dx *= 0.5;
      x -= dx;
      last_correction = relative_to_increment(dx);
      ++halvings;
      ++result.halvings;
      result.step_lengths.back() *= 0.5;
      --k;
      continue;
    }
    halvings = 0;
    if (!admissible) {
      result.failure = problem.inadmissible_reason();
      result.inadmissible = true;
      return result;
    }
    result.residuals.push_back(relative);
    result.largest.push_back(problem.largest_residual_unknown());
    result.active.push_back(problem.active_set());
    if (k == 0) result.active.back().changed = -1;  // against another solve's iterate
    problem.iterate_accepted();
    if (!std::isfinite(relative)) {
      result.failure = "the residual is not finite";
      return result;
    }
    const bool residual_ok = relative <= settings.residual_tolerance || norm == 0.0;
    bool correction_ok = k == 0 || last_correction <= settings.displacement_tolerance;
    if (residual_ok && !correction_ok) {
      // The residual has converged but the last correction was still large (it answered the
      // previous, larger residual). The correction the current residual asks for is measured
      // with the factorisation already at hand (one back-substitution, no new factorisation):
      // near the solution it differs from the full Newton correction by a higher-order term.
      try {
        correction_ok =
            relative_to_increment(solver.solve(residual)) <= settings.displacement_tolerance;
      } catch (const LinearSolverFailure&) {
      }
    }
    if (residual_ok && correction_ok) {
      result.converged = true;
      return result;
    }
    if (k > 0 &&
        relative > settings.divergence_factor * std::max(result.residuals.front(), 1e-12)) {
      result.failure = fmt::format("diverged (relative residual {:.3e})", relative);
      return result;
    }
    if (k == settings.max_iterations) {
      result.failure =
          fmt::format("no convergence in {} iterations (relative residual {:.3e})", k, relative);
      return result;
    }
    // A residual already within tolerance is not given up on: only the size of the next
    // correction is still to be seen, and it is converged, not stalling.
    if (settings.patience > 0 && k >= settings.patience && !residual_ok &&
        !(relative < superlinear_contraction * result.residuals[k - 1])) {
      result.failure =
          fmt::format("not converging superlinearly after {} iterations (relative residual {:.3e})",
                      k, relative);
      return result;
    }
    try {
      if (!analysed) {
        solver.analyze(tangent);
        analysed = true;
      }
      solver.factorize(tangent);
      dx = solver.solve(residual);
      along_start = dx.dot(residual);
      searched = false;
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
      result.largest_correction.push_back(moved_most >= 0 ? problem.problem_unknown(moved_most)
                                                          : -1);
    } catch (const LinearSolverFailure& e) {
      result.failure = e.what();
      return result;
    }
  }
}

}  // namespace geompm

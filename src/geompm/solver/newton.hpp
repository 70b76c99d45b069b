// Newton-Raphson for one step (seed paper eqs. 6-7, docs/theory.md §4.4): K dx = R, x += dx,
// until the residual is small relative to the forces in play AND the last correction is small
// relative to the step's increment. Newton knows vectors, a sparse matrix and a LinearSolver
// only; the physics is a NonlinearProblem. Its pieces, each in its own file: the convergence test
// (convergence_test.hpp), the backtracking (backtracking.hpp), the energy line search
// (energy_line_search.hpp) and the tangent check (tangent_check.hpp).
#pragma once

#include <string>
#include <vector>

#include "geompm/core/types.hpp"
#include "geompm/solver/linear_solver.hpp"
#include "geompm/solver/newton_settings.hpp"
#include "geompm/solver/nonlinear_problem.hpp"

namespace geompm {

struct NewtonResult {
  bool converged = false;
  int iterations = 0;               // linear solves
  int halvings = 0;                 // corrections halved by the backtracking
  int searches = 0;                 // corrections shortened by the energy line search
  int linear_iterations = 0;        // the linear solver's, summed (1 a solve for a direct one)
  double linear_seconds = 0.0;      // wall time in the linear solver's setup and solves
  std::vector<double> residuals;    // relative residual before each solve, and the last
  std::vector<double> corrections;  // relative size of each correction
  /// Per correction: the fraction of it kept, 1 for the full Newton correction, below 1 where the
  /// backtracking halved it or the energy line search shortened it.
  std::vector<double> step_lengths;
  std::vector<Index> largest;  // per residual: the problem's largest_residual_unknown()
  /// Per correction: the unknown it moves most (its largest |dx_i|, as problem_unknown(i)).
  std::vector<Index> largest_correction;
  std::vector<ActiveSet> active;  // per residual: the problem's active_set()
  /// With NewtonSettings::tangent_check, per correction: |(R(x + e dx) - R(x)) / e + R(x)| /
  /// |R(x)|, the tangent's relative error along dx (NaN where x + e dx was inadmissible).
  std::vector<double> tangent_errors;
  std::string failure;        // why it did not converge
  bool inadmissible = false;  // it stopped at an inadmissible x (inadmissible_reason())
};

/// Solves problem(x) = 0 from x, into which the problem assembles its tangent (`tangent`, the
/// step's pattern). The solver must have been given the step's pattern (LinearSolver::analyse);
/// Newton calls setup once per correction and solve against the last setup's operator.
NewtonResult solve_newton(NonlinearProblem& problem, LinearSolver& solver,
                          const NewtonSettings& settings, Vector& x, SparseMatrix& tangent);

}  // namespace geompm

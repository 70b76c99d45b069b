// Newton-Raphson for one step (seed paper eqs. 6-7): K dx = R, x += dx, until the residual is
// small relative to the forces in play AND the last correction is small relative to the step's
// increment. The solver knows vectors and a sparse matrix only; the physics is a
// NonlinearProblem.
#pragma once

#include <string>
#include <vector>

#include "geompm/core/types.hpp"
#include "geompm/solver/linear_solver.hpp"

namespace geompm {

/// Newton's active set at an iterate: for a nonsmooth residual (return mapping), the members on
/// the nonsmooth side and how many switched since the iterate before. -1: not known.
struct ActiveSet {
  Index size = -1;
  Index changed = -1;
};

class NonlinearProblem {
 public:
  virtual ~NonlinearProblem() = default;
  /// Residual R(x) (out-of-balance force at the free unknowns), a force scale for the relative
  /// criterion, and the tangent K = -dR/dx when `tangent` is not null (its pattern fixed for the
  /// step). Returns false if x is inadmissible (a point turned inside out, or its stress update
  /// failed).
  virtual bool evaluate(const Vector& x, Vector& residual, double& force_scale,
                        SparseMatrix* tangent) = 0;
  /// After evaluate() returned false: why, for the failure message.
  virtual std::string inadmissible_reason() const {
    return "inadmissible deformation (a point's volume became <= 0)";
  }
  /// Norm of the whole increment of the step at x (prescribed parts included).
  virtual double increment_norm(const Vector& x) const = 0;
  /// The unknown with the largest residual at the last evaluation, in the problem's own
  /// numbering, or -1 if the problem does not say (for diagnostics only).
  virtual Index largest_residual_unknown() const { return -1; }
  /// The free unknown `free` (an index into x) in the problem's own numbering, as
  /// largest_residual_unknown() (for diagnostics only).
  virtual Index problem_unknown(Index free) const { return free; }
  /// For diagnostics: the size of the active set of the last evaluation (in plasticity the
  /// points returned plastically) and how many members entered or left it since the last call
  /// (-1 if the problem does not say; Newton sets -1 at a solve's first iterate). Called once
  /// per iterate that Newton logs.
  virtual ActiveSet active_set() { return {}; }
  /// Called once per iterate Newton accepts (after its evaluation, before the correction from
  /// it): a problem with a switch in its residual may hold the branch the iterate took for the
  /// rest of the solve, without changing the residual at the iterate itself.
  virtual void iterate_accepted() {}
};

/// A residual this much smaller than the one before marks Newton's superlinear (quadratic) regime:
/// while points still switch between elastic and plastic the residual falls by factors of about
/// 1.5-6 an iteration (measured on the N_q strip of validation.md §9; up to 15 while only tens of
/// points switch on the stiff Tresca strip of §5, which the test counts as superlinear, harmlessly:
/// that start goes on), in the quadratic regime by far more (docs/theory.md §4.5).
inline constexpr double superlinear_contraction = 0.1;

struct NewtonSettings {
  int max_iterations = 15;
  /// If > 0: after this many iterations Newton goes on (up to max_iterations) only while it
  /// converges superlinearly, each residual below superlinear_contraction times the one before;
  /// a start that has not reached Newton's quadratic regime by then gives up early.
  int patience = 0;
  double residual_tolerance = 1e-8;
  double displacement_tolerance = 1e-8;
  double divergence_factor =
      1e8;  // residual growth over the first residual that counts as divergence
  /// Backtracking: a correction that makes the residual grow, or turns a point inside out, is
  /// halved, at most this many times in a row (0: plain Newton).
  int max_halvings = 0;
  /// Energy line search (docs/theory.md §4.4): if > 0, a correction dx after which the residual's
  /// component along it, s = dx . R, has turned negative beyond this fraction of its value at the
  /// start is shortened to where |s| is within this fraction (0: off).
  double energy_search = 0.0;
  /// Diagnostic: if > 0, each correction dx is checked against the residual's directional
  /// finite difference, (R(x + e dx) - R(x)) / e with e this value, which a consistent tangent
  /// K = -dR/dx matches to O(e): K dx = R(x). Costs one more residual evaluation an iteration.
  double tangent_check = 0.0;
};

struct NewtonResult {
  bool converged = false;
  int iterations = 0;               // linear solves
  int halvings = 0;                 // corrections halved by the backtracking
  int searches = 0;                 // corrections shortened by the energy line search
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

NewtonResult solve_newton(NonlinearProblem& problem, LinearSolver& solver,
                          const NewtonSettings& settings, Vector& x, SparseMatrix& tangent);

}  // namespace geompm

// The energy line search (docs/theory.md §4.4, eq. 4.5a; Matthies & Strang 1979; Crisfield 1991,
// ch. 9, `newton.energy_line_search: beta`): a full Newton correction dx that went past the
// minimum of the energy along it, s(1) = dx . R(x + dx) < -beta s(0), is shortened to the length
// eta at which the residual is (nearly) orthogonal to it, |s(eta)| <= beta s(0).
#pragma once

#include "geompm/core/linear_algebra.hpp"
#include "geompm/solver/nonlinear_problem.hpp"

namespace geompm {

/// The energy line search's budget of residual evaluations for one correction.
inline constexpr int energy_search_evaluations = 10;

/// The step length eta along the correction dx from `start` at which s(eta) = dx . R(start + eta
/// dx) = 0, to within |s| <= tolerance s(0). s(0) = s_start = dx . K dx > 0, and the full step
/// gave s(1) = s_full < -tolerance s(0). Regula falsi between the two (Illinois: the end kept
/// twice in a row has its s halved), each trial a residual without the tangent; returns the trial
/// eta with the smallest |s|, or 1 if none improves on the full step.
double energy_line_search(NonlinearProblem& problem, const Vector& start, const Vector& dx,
                          double s_start, double s_full, double tolerance);

/// The search as Newton uses it, once per correction.
class EnergyLineSearch {
 public:
  /// `tolerance`: beta; 0 switches the search off.
  explicit EnergyLineSearch(double tolerance) : tolerance_(tolerance) {}

  /// A new full correction dx from an iterate with residual R: s(0) = dx . R.
  void start(const Vector& dx, const Vector& residual) {
    along_start_ = dx.dot(residual);
    searched_ = false;
  }
  /// At x, reached by the correction dx, with its residual R there (admissible and finite): if
  /// the correction is whole, descends an energy (s(0) > 0: not so along some corrections of the
  /// mixed p-u system, a saddle point) and went past its minimum by more than beta, searches its
  /// length eta, once per correction. Where eta < 1 it shortens the correction, dx <- eta dx,
  /// x <- x_start + dx, and returns eta; otherwise it returns 1 and leaves x and dx alone.
  double shorten(NonlinearProblem& problem, Vector& x, Vector& dx, const Vector& residual);
  /// Whether the current correction's length came from the search: backtracking lets it stand
  /// unless its iterate is inadmissible.
  bool searched() const { return searched_; }

 private:
  double tolerance_;
  double along_start_ = 0.0;  // s(0) of the current correction
  bool searched_ = false;
};

}  // namespace geompm

// The forcing term of an inexact Newton method (docs/theory.md §4.8): the relative tolerance
// eta_k to which an iterative linear solver solves K dx = R at Newton iteration k. Loose while
// the residual is far from converged (an accurate correction of a poor linearisation buys
// nothing), tightening as Newton converges so that its superlinear convergence is kept
// (Eisenstat & Walker 1996, choice 2), never tighter than the Newton tolerance needs (Kelley
// 1995, eq. 6.20). A direct solver ignores it.
#pragma once

#include <vector>

namespace geompm {

struct ForcingSettings {
  bool enabled = true;  // false: every solve to `floor`
  /// eta_0, the first solve of a step. Its correction carries the whole increment; where a loose
  /// one put a point's volume <= 0 beside a footing's edge (examples/mohr_coulomb_footing: the
  /// first step cut back four times with 0.1, once with 1e-3), a tight one takes the same steps
  /// and iterations as UMFPACK (docs/theory.md §4.8).
  double first = 1e-6;
  double maximum = 1e-3;  // eta_max: the loosest of the later solves
  double floor = 1e-10;   // the tightest (NewtonSettings::linear_tolerance)
  double gamma = 0.9;     // Eisenstat-Walker choice 2: eta = gamma (r_k / r_{k-1})^alpha
  double alpha = 2.0;
};

/// eta_k for the solve at the last of `residuals` (relative residuals r_0 .. r_k of the Newton
/// iterations so far), given eta_{k-1} (`previous`, < 0 at k = 0) and Newton's residual
/// tolerance.
double forcing_term(const ForcingSettings& settings, const std::vector<double>& residuals,
                    double previous, double residual_tolerance);

}  // namespace geompm

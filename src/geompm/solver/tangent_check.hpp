// Newton's tangent check (`newton.tangent_check: e`, a diagnostic): the tangent's relative error
// along the correction dx = K^-1 R(x), from the directional finite difference of the residual.
#pragma once

#include "geompm/core/linear_algebra.hpp"
#include "geompm/solver/nonlinear_problem.hpp"

namespace geompm {

/// |(R(x + e dx) - R(x)) / e + R(x)| / |R(x)|: -K dx = -R(x) against the finite difference.
/// Consistent tangents give O(e) (and round-off of order 1e-16 |R| / (e |R(x)|)); an inconsistent
/// one an error of order one. NaN where x + e dx is inadmissible. The problem is evaluated at
/// x + e dx without the tangent, and again at x by Newton's next iteration.
double directional_tangent_error(NonlinearProblem& problem, const Vector& x, const Vector& dx,
                                 const Vector& residual, double e);

}  // namespace geompm

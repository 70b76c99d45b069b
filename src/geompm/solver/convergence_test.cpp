#include "geompm/solver/convergence_test.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace geompm {

Verdict ConvergenceTest::judge(std::span<const double> residuals, double norm,
                               double last_correction,
                               const std::function<double()>& current_correction) const {
  const std::size_t k = residuals.size() - 1;
  const double relative = residuals.back();
  if (!std::isfinite(relative)) return {Verdict::Failed, "the residual is not finite"};
  // Eq. 4.5: the residual relative to the forces in play, and the correction relative to the
  // step's increment (none before the first correction).
  const bool residual_ok = relative <= settings_.residual_tolerance || norm == 0.0;
  bool correction_ok = k == 0 || last_correction <= settings_.displacement_tolerance;
  if (residual_ok && !correction_ok)
    correction_ok = current_correction() <= settings_.displacement_tolerance;
  if (residual_ok && correction_ok) return {Verdict::Converged, {}};
  if (k > 0 && relative > settings_.divergence_factor * std::max(residuals.front(), 1e-12))
    return {Verdict::Failed, fmt::format("diverged (relative residual {:.3e})", relative)};
  if (k == static_cast<std::size_t>(settings_.max_iterations))
    return {Verdict::Failed,
            fmt::format("no convergence in {} iterations (relative residual {:.3e})", k, relative)};
  // Patience (theory §4.5): past it, Newton goes on only while it converges superlinearly. A
  // residual already within tolerance is not given up on: only the size of the next correction
  // is still to be seen, and it is converged, not stalling.
  if (settings_.patience > 0 && k >= static_cast<std::size_t>(settings_.patience) && !residual_ok &&
      !(relative < superlinear_contraction * residuals[k - 1]))
    return {
        Verdict::Failed,
        fmt::format("not converging superlinearly after {} iterations (relative residual {:.3e})",
                    k, relative)};
  return {};
}

}  // namespace geompm

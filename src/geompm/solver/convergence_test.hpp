// Newton's verdict at an accepted iterate (docs/theory.md eq. 4.5 and §4.5): converged, given up
// (not finite, diverged, out of iterations, or not superlinear after the patience), or on.
#pragma once

#include <functional>
#include <span>
#include <string>

#include "geompm/solver/newton_settings.hpp"

namespace geompm {

struct Verdict {
  enum Kind { GoOn, Converged, Failed };
  Kind kind = GoOn;
  std::string failure;  // why, when Failed
};

class ConvergenceTest {
 public:
  explicit ConvergenceTest(const NewtonSettings& settings) : settings_(settings) {}

  /// The verdict at iterate k = residuals.size() - 1. `residuals`: the relative residuals of the
  /// accepted iterates of this solve, the current one last; `norm`: the current residual's
  /// absolute norm (an exactly zero residual has converged whatever the force scale);
  /// `last_correction`: the size of the correction that led here relative to the step's
  /// increment. Both criteria of eq. 4.5 must hold. Where the residual has converged but the
  /// last correction (which answered the previous, larger residual) was not yet small,
  /// `current_correction()` is asked for the relative size of the correction the current
  /// residual asks for: near the solution it differs from the full Newton correction by a
  /// higher-order term.
  Verdict judge(std::span<const double> residuals, double norm, double last_correction,
                const std::function<double()>& current_correction) const;

 private:
  NewtonSettings settings_;
};

}  // namespace geompm

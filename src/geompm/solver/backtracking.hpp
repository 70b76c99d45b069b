// Backtracking (docs/theory.md §4.4, `newton.line_search: n`): a correction that overshot (the
// residual grew, or a point turned inside out) is halved, x <- x - dx/2, dx <- dx/2, at most n
// times in a row, before the iterate is accepted. For a small enough fraction the Newton
// direction reduces the residual; a plastic switch at a few points, which can throw the full
// correction off, is approached in shorter strides instead of failing the step.
#pragma once

#include "geompm/core/linear_algebra.hpp"

namespace geompm {

class Backtracking {
 public:
  explicit Backtracking(int max_halvings) : max_halvings_(max_halvings) {}

  /// Whether the correction that led to an iterate overshot: the iterate is inadmissible, its
  /// relative residual is not finite, or it exceeds `last_accepted`, the relative residual of the
  /// iterate the correction started from. A length the energy line search found
  /// (`length_searched`) stands unless its iterate is inadmissible.
  static bool overshot(bool admissible, double relative, double last_accepted,
                       bool length_searched);

  /// If `overshot` and halvings of this correction remain: goes back half of the correction dx
  /// that led to x (x -= dx / 2, dx /= 2) and returns true.
  bool retreat(bool overshot, Vector& x, Vector& dx);

  /// The iterate is accepted: the next correction may be halved max_halvings times again.
  void accept() { halvings_ = 0; }
  /// Whether the current correction is still whole (not halved yet).
  bool whole() const { return halvings_ == 0; }

 private:
  int max_halvings_;
  int halvings_ = 0;  // of the current correction
};

}  // namespace geompm

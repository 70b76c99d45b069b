// Backtracking (docs/theory.md §4.4): a correction that overshot is halved, x <- x - dx/2,
// dx <- dx/2, a few times in a row before the iterate is accepted. An iterate that turned a point
// inside out (or whose residual is not finite) is always halved, up to `inadmissible_halvings`
// times: a point beside a structure's edge that heaves can invert in one full Newton correction
// though the step itself is admissible, and a halved correction costs nothing where it does not
// happen. An iterate whose residual merely grew is halved only with `newton.line_search: n`
// (n times), or, with it not set, in the last try of a step that failed at the smallest allowed
// step (analysis/simulation.cpp): Newton's residual often grows for an iterate or two while
// points change between elastic and plastic and then converges, and halving there can stall it.
#pragma once

#include "geompm/core/linear_algebra.hpp"

namespace geompm {

class Backtracking {
 public:
  /// How the correction that led to an iterate overshot.
  enum class Overshoot {
    None,
    Grown,        // the relative residual exceeds the one the correction started from
    Inadmissible  // a point turned inside out or failed its update; or a non-finite residual
  };

  /// `max_halvings` for a grown residual (newton.line_search), `inadmissible_halvings` (at least
  /// as many) for an inadmissible iterate.
  Backtracking(int max_halvings, int inadmissible_halvings)
      : max_halvings_(max_halvings), inadmissible_halvings_(inadmissible_halvings) {}

  /// Whether and how the correction that led to an iterate overshot: the iterate is
  /// inadmissible, its relative residual is not finite, or it exceeds `last_accepted`, the
  /// relative residual of the iterate the correction started from. A length the energy line
  /// search found (`length_searched`) stands unless its iterate is inadmissible.
  static Overshoot overshoot(bool admissible, double relative, double last_accepted,
                             bool length_searched);

  /// If the correction overshot and halvings of this correction remain for its kind: goes back
  /// half of the correction dx that led to x (x -= dx / 2, dx /= 2) and returns true.
  bool retreat(Overshoot overshoot, Vector& x, Vector& dx);

  /// The iterate is accepted: the next correction may be halved as often again.
  void accept() { halvings_ = 0; }
  /// Whether the current correction is still whole (not halved yet).
  bool whole() const { return halvings_ == 0; }

 private:
  int max_halvings_;
  int inadmissible_halvings_;
  int halvings_ = 0;  // of the current correction
};

}  // namespace geompm

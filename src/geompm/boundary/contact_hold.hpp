// Which soil points a rigid footing holds in contact in both directions through the Newton
// iterations of a step (docs/theory.md §13, eqs. 13.8-13.9). The penalty contact switches on
// at zero gap, a kink in the residual that the tangent does not see: a point sitting at it flips
// between touching and free from one iterate to the next, Newton bounces across the kink and
// stalls. Held points have no switch within the step.
#pragma once

#include <cstddef>
#include <vector>

namespace geompm {

class ContactHold {
 public:
  /// `held_at_start[i]`: point i touched the base at the end of the last converged step (eq.
  /// 13.8); it is held from the first iterate on.
  explicit ContactHold(std::vector<char> held_at_start);

  /// After an iterate Newton accepted: `pressed[i]` whether point i is pressed against the base
  /// there. A point that comes into contact a second time in the solve's iterates (pressed, free,
  /// pressed again) is held from then on (eq. 13.9); one pressed once, in an early iterate far
  /// from the solution, stays free to leave.
  void accept(const std::vector<char>& pressed);
  /// A new Newton solve of the same step: back to the points held at its start.
  void restart();

  bool held(std::size_t i) const { return held_[i] != 0; }
  std::size_t size() const { return held_.size(); }

 private:
  std::vector<char> start_, held_, pressed_, entries_;
};

}  // namespace geompm

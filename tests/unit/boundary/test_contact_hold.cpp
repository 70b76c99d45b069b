// The rigid footing's contact hold (docs/theory.md §13, eqs. 13.8-13.9): which points are held
// in contact in both directions through a step's Newton iterates.
#include <gtest/gtest.h>

#include <vector>

#include "geompm/boundary/contact_hold.hpp"

namespace geompm {
namespace {

using Flags = std::vector<char>;

TEST(ContactHold, PointsTouchingAtTheStartOfTheStepAreHeldFromTheFirstIterate) {
  // Eq. 13.8: point 0 touched at the end of the last step.
  ContactHold hold(Flags{1, 0});
  EXPECT_TRUE(hold.held(0));
  EXPECT_FALSE(hold.held(1));
  // Free at an iterate, it is still held: its contact does not switch within the step.
  hold.accept(Flags{0, 0});
  EXPECT_TRUE(hold.held(0));
}

TEST(ContactHold, APointPressedOnceStaysFreeToLeave) {
  // Pressed in an early iterate only (far from the solution): holding it would pull on the soil
  // where the converged state has it free.
  ContactHold hold(Flags{0});
  hold.accept(Flags{1});
  EXPECT_FALSE(hold.held(0));
  hold.accept(Flags{0});
  hold.accept(Flags{0});
  EXPECT_FALSE(hold.held(0));
  // Pressed at every iterate from its first contact on: one entry only, never held (it touches,
  // so holding it would change nothing).
  ContactHold stays(Flags{0});
  for (int k = 0; k < 5; ++k) stays.accept(Flags{1});
  EXPECT_FALSE(stays.held(0));
}

TEST(ContactHold, APointThatComesIntoContactAgainIsHeldForTheRestOfTheSolve) {
  // Eq. 13.9: pressed, free, pressed again - the flip at zero gap that stalls Newton.
  ContactHold hold(Flags{0, 0});
  hold.accept(Flags{1, 0});
  hold.accept(Flags{0, 1});
  EXPECT_FALSE(hold.held(0));
  hold.accept(Flags{1, 1});
  EXPECT_TRUE(hold.held(0));
  EXPECT_FALSE(hold.held(1));  // entered once and stayed
  // Held from then on, wherever the iterates put it.
  hold.accept(Flags{0, 0});
  EXPECT_TRUE(hold.held(0));
}

TEST(ContactHold, ANewSolveOfTheStepStartsAgainFromThePointsHeldAtItsStart) {
  ContactHold hold(Flags{1, 0});
  hold.accept(Flags{0, 1});
  hold.accept(Flags{0, 0});
  hold.accept(Flags{0, 1});
  ASSERT_TRUE(hold.held(1));
  hold.restart();
  EXPECT_TRUE(hold.held(0));
  EXPECT_FALSE(hold.held(1));
  // Its count of entries starts again too: one more entry does not hold it.
  hold.accept(Flags{1, 1});
  EXPECT_FALSE(hold.held(1));
}

}  // namespace
}  // namespace geompm

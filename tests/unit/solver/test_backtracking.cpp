// Newton's backtracking (docs/theory.md §4.4) on its own: what counts as an overshoot, and the
// halving of the correction, at most max_halvings times in a row.
#include <gtest/gtest.h>

#include <limits>

#include "geompm/solver/backtracking.hpp"

namespace geompm {
namespace {

TEST(Backtracking, AnOvershootIsAGrownResidualOrAnInadmissibleIterate) {
  EXPECT_TRUE(Backtracking::overshot(true, 2.0, 1.0, false));
  EXPECT_FALSE(Backtracking::overshot(true, 0.5, 1.0, false));
  EXPECT_TRUE(Backtracking::overshot(false, 0.0, 1.0, false));
  EXPECT_TRUE(Backtracking::overshot(true, std::numeric_limits<double>::infinity(), 1.0, false));
  // A length the energy line search found stands, unless its iterate is inadmissible.
  EXPECT_FALSE(Backtracking::overshot(true, 2.0, 1.0, true));
  EXPECT_TRUE(Backtracking::overshot(false, 0.0, 1.0, true));
}

TEST(Backtracking, HalvesTheCorrectionAtMostMaxHalvingsTimes) {
  Backtracking backtracking(2);
  Vector x = Vector::Constant(2, 5.0), dx = Vector::Constant(2, 4.0);  // from x0 = 1
  EXPECT_TRUE(backtracking.whole());
  EXPECT_FALSE(backtracking.retreat(false, x, dx));  // no overshoot: nothing to do
  EXPECT_TRUE(backtracking.retreat(true, x, dx));
  EXPECT_EQ(x, Vector::Constant(2, 3.0));
  EXPECT_EQ(dx, Vector::Constant(2, 2.0));
  EXPECT_FALSE(backtracking.whole());
  EXPECT_TRUE(backtracking.retreat(true, x, dx));
  EXPECT_EQ(x, Vector::Constant(2, 2.0));
  EXPECT_FALSE(backtracking.retreat(true, x, dx));  // the third in a row is refused
  EXPECT_EQ(x, Vector::Constant(2, 2.0));
  backtracking.accept();  // the next correction may be halved twice again
  EXPECT_TRUE(backtracking.whole());
  EXPECT_TRUE(backtracking.retreat(true, x, dx));
  EXPECT_FALSE(Backtracking(0).retreat(true, x, dx));  // plain Newton
}

}  // namespace
}  // namespace geompm

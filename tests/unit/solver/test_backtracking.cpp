// Newton's backtracking (docs/theory.md §4.4) on its own: what counts as an overshoot, and the
// halving of the correction, at most max_halvings times in a row for a grown residual and
// inadmissible_halvings times for an inadmissible iterate.
#include <gtest/gtest.h>

#include <limits>

#include "geompm/solver/backtracking.hpp"

namespace geompm {
namespace {

using Overshoot = Backtracking::Overshoot;

TEST(Backtracking, AnOvershootIsAGrownResidualOrAnInadmissibleIterate) {
  EXPECT_EQ(Backtracking::overshoot(true, 2.0, 1.0, false), Overshoot::Grown);
  EXPECT_EQ(Backtracking::overshoot(true, 0.5, 1.0, false), Overshoot::None);
  EXPECT_EQ(Backtracking::overshoot(false, 0.0, 1.0, false), Overshoot::Inadmissible);
  EXPECT_EQ(Backtracking::overshoot(true, std::numeric_limits<double>::infinity(), 1.0, false),
            Overshoot::Inadmissible);
  // A length the energy line search found stands, unless its iterate is inadmissible.
  EXPECT_EQ(Backtracking::overshoot(true, 2.0, 1.0, true), Overshoot::None);
  EXPECT_EQ(Backtracking::overshoot(false, 0.0, 1.0, true), Overshoot::Inadmissible);
}

TEST(Backtracking, HalvesAGrownResidualAtMostMaxHalvingsTimes) {
  Backtracking backtracking(2, 2);
  Vector x = Vector::Constant(2, 5.0), dx = Vector::Constant(2, 4.0);  // from x0 = 1
  EXPECT_TRUE(backtracking.whole());
  EXPECT_FALSE(backtracking.retreat(Overshoot::None, x, dx));  // nothing to do
  EXPECT_TRUE(backtracking.retreat(Overshoot::Grown, x, dx));
  EXPECT_EQ(x, Vector::Constant(2, 3.0));
  EXPECT_EQ(dx, Vector::Constant(2, 2.0));
  EXPECT_FALSE(backtracking.whole());
  EXPECT_TRUE(backtracking.retreat(Overshoot::Grown, x, dx));
  EXPECT_EQ(x, Vector::Constant(2, 2.0));
  EXPECT_FALSE(backtracking.retreat(Overshoot::Grown, x, dx));  // the third in a row is refused
  EXPECT_EQ(x, Vector::Constant(2, 2.0));
  backtracking.accept();  // the next correction may be halved twice again
  EXPECT_TRUE(backtracking.whole());
  EXPECT_TRUE(backtracking.retreat(Overshoot::Grown, x, dx));
}

TEST(Backtracking, PlainNewtonStillHalvesAnInadmissibleIterate) {
  Backtracking plain(0, 3);  // newton.line_search 0, the default
  Vector x = Vector::Constant(1, 9.0), dx = Vector::Constant(1, 8.0);  // from x0 = 1
  EXPECT_FALSE(plain.retreat(Overshoot::Grown, x, dx));  // a grown residual is accepted
  EXPECT_EQ(x, Vector::Constant(1, 9.0));
  EXPECT_TRUE(plain.retreat(Overshoot::Inadmissible, x, dx));
  EXPECT_TRUE(plain.retreat(Overshoot::Inadmissible, x, dx));
  EXPECT_TRUE(plain.retreat(Overshoot::Inadmissible, x, dx));
  EXPECT_EQ(x, Vector::Constant(1, 2.0));
  EXPECT_FALSE(plain.retreat(Overshoot::Inadmissible, x, dx));  // the fourth is refused
  EXPECT_FALSE(Backtracking(0, 0).retreat(Overshoot::Inadmissible, x, dx));  // none allowed
}

}  // namespace
}  // namespace geompm

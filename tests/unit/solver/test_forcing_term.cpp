// The inexact Newton forcing term (solver/forcing_term.hpp, docs/theory.md eqs. 4.12-4.14),
// against values worked by hand.
#include <gtest/gtest.h>

#include "geompm/solver/forcing_term.hpp"

namespace geompm {
namespace {

TEST(ForcingTerm, FirstSolveTightThenLooseThenTighteningWithTheContraction) {
  const ForcingSettings s;  // first 1e-6, maximum 1e-3, gamma 0.9, alpha 2, floor 1e-10
  EXPECT_DOUBLE_EQ(forcing_term(s, {1.0}, -1.0, 1e-8), 1e-6);
  // r drops by 10: 0.9 * 0.1^2 = 0.009, capped at 1e-3.
  EXPECT_DOUBLE_EQ(forcing_term(s, {1.0, 0.1}, 1e-6, 1e-8), 1e-3);
  // r drops by 1000: 0.9e-6.
  EXPECT_NEAR(forcing_term(s, {1.0, 0.1, 1e-4}, 1e-3, 1e-12), 0.9e-6, 1e-18);
}

TEST(ForcingTerm, KeepsALooseLastTermAfterALuckyDrop) {
  ForcingSettings s;
  s.maximum = 0.9;
  // eta_{k-1} = 0.5: 0.9 * 0.25 = 0.225 > 0.1, so eta_k >= 0.225 although r fell by 100.
  EXPECT_NEAR(forcing_term(s, {1.0, 0.01}, 0.5, 1e-12), 0.225, 1e-15);
  // eta_{k-1} = 0.3: 0.9 * 0.09 = 0.081 < 0.1, no safeguard: 0.9 * 1e-4.
  EXPECT_NEAR(forcing_term(s, {1.0, 0.01}, 0.3, 1e-12), 0.9e-4, 1e-16);
}

TEST(ForcingTerm, NeverTighterThanTheNewtonToleranceNeedsNorThanTheFloor) {
  ForcingSettings s;
  s.maximum = 0.1;
  // r = 1e-6 after r = 1: EW gives 0.9e-12, the floor 1e-10, Newton needs 0.5 * 1e-8 / 1e-6.
  EXPECT_NEAR(forcing_term(s, {1.0, 1e-6}, 0.1, 1e-8), 5e-3, 1e-15);
  EXPECT_DOUBLE_EQ(forcing_term(s, {1.0, 1e-6}, 0.1, 1e-20), 1e-10);
  ForcingSettings off;
  off.enabled = false;
  EXPECT_DOUBLE_EQ(forcing_term(off, {1.0}, -1.0, 1e-8), 1e-10);
}

}  // namespace
}  // namespace geompm

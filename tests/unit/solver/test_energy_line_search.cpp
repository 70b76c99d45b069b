// The energy line search (docs/theory.md §4.4, eq. 4.5a) on its own: on the steep ramp of
// test_newton.cpp the full correction from the soft branch jumps across the ramp, and the search
// lands on the ramp, where s(eta) = dx . R changes sign; it is not entered where the correction
// does not overshoot, does not descend an energy, or was searched already.
#include <gtest/gtest.h>

#include <cmath>

#include "geompm/solver/energy_line_search.hpp"

namespace geompm {
namespace {

// R(x) = f - r(x), r soft (slope 1) outside a steep ramp (slope 1000 on 0 <= x < 0.01), f =
// r(0.005); counts its evaluations.
class Ramp final : public NonlinearProblem {
 public:
  static double force(double x) { return x < 0.0 ? x : x < 0.01 ? 1000.0 * x : 10.0 + (x - 0.01); }
  bool evaluate(const Vector& x, Vector& residual, double& force_scale, SparseMatrix*) override {
    ++evaluations;
    residual = Vector::Constant(1, force(0.005) - force(x(0)));
    force_scale = 1.0;
    return true;
  }
  double increment_norm(const Vector& x) const override { return std::abs(x(0)); }
  int evaluations = 0;
};

// From x0 = -1 the soft tangent's correction is dx = R(x0) / 1 = 6: x1 = 5, beyond the ramp.
struct Jump {
  Vector start = Vector::Constant(1, -1.0), dx = Vector::Constant(1, 6.0);
  Vector x = Vector::Constant(1, 5.0);
  Vector residual_start = Vector::Constant(1, 6.0);
  Vector residual_full = Vector::Constant(1, Ramp::force(0.005) - Ramp::force(5.0));
};

TEST(EnergyLineSearch, LandsOnTheRampWhereTheFullCorrectionJumpedAcrossIt) {
  Ramp ramp;
  const Jump jump;
  const double s_start = jump.dx.dot(jump.residual_start), s_full = jump.dx.dot(jump.residual_full);
  ASSERT_LT(s_full, -0.1 * s_start);
  const double eta = energy_line_search(ramp, jump.start, jump.dx, s_start, s_full, 0.1);
  const double landed = jump.start(0) + eta * jump.dx(0);
  EXPECT_GE(landed, 0.0);
  EXPECT_LT(landed, 0.01);
  EXPECT_LE(ramp.evaluations, energy_search_evaluations);
}

TEST(EnergyLineSearch, ShortensAnOvershootingCorrectionOnce) {
  Ramp ramp;
  Jump jump;
  EnergyLineSearch search(0.1);
  search.start(jump.dx, jump.residual_start);
  const double eta = search.shorten(ramp, jump.x, jump.dx, jump.residual_full);
  EXPECT_LT(eta, 1.0);
  EXPECT_TRUE(search.searched());
  EXPECT_NEAR(jump.dx(0), 6.0 * eta, 1e-15);
  EXPECT_NEAR(jump.x(0), -1.0 + jump.dx(0), 1e-15);
  EXPECT_GE(jump.x(0), 0.0);
  EXPECT_LT(jump.x(0), 0.01);
  // Once per correction.
  const int evaluations = ramp.evaluations;
  EXPECT_EQ(search.shorten(ramp, jump.x, jump.dx, jump.residual_full), 1.0);
  EXPECT_EQ(ramp.evaluations, evaluations);
}

TEST(EnergyLineSearch, LeavesAloneWhatDoesNotOvershootOrDescend) {
  Ramp ramp;
  Jump jump;
  // Off.
  EnergyLineSearch off(0.0);
  off.start(jump.dx, jump.residual_start);
  EXPECT_EQ(off.shorten(ramp, jump.x, jump.dx, jump.residual_full), 1.0);
  // The correction does not descend an energy: s(0) = dx . R <= 0 (a saddle point's).
  EnergyLineSearch saddle(0.1);
  saddle.start(jump.dx, -jump.residual_start);
  EXPECT_EQ(saddle.shorten(ramp, jump.x, jump.dx, jump.residual_full), 1.0);
  // No overshoot beyond beta: s(1) = -0.05 s(0).
  EnergyLineSearch within(0.1);
  within.start(jump.dx, jump.residual_start);
  EXPECT_EQ(within.shorten(ramp, jump.x, jump.dx, -0.05 * jump.residual_start), 1.0);
  EXPECT_FALSE(within.searched());
  EXPECT_EQ(ramp.evaluations, 0);
  EXPECT_EQ(jump.x(0), 5.0);
}

}  // namespace
}  // namespace geompm

// The contact law's complementarity functions (docs/theory.md §18): their roots are the contact
// conditions, their derivatives are those Newton needs, and a problem solved with them does not
// depend on the scale that makes the multipliers lengths.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "geompm/contact/contact_law.hpp"

namespace geompm {
namespace {

ContactLaw friction(double mu, double cap = std::numeric_limits<double>::infinity()) {
  ContactLaw law;
  law.tangential = TangentialContact::Friction;
  law.friction = mu;
  law.cap = cap;
  return law;
}

TEST(ContactLaw, RootsAreTheNormalContactConditions) {
  const ContactLaw smooth;
  // Open: a gap (p < 0) and no pressure.
  ContactEquations e = contact_equations(smooth, 1.0, -0.1, 0.0, 0.0, 0.0);
  EXPECT_EQ(e.normal, 0.0);
  EXPECT_EQ(e.state, ContactState::Open);
  // Touching: no penetration and a compressive pressure.
  e = contact_equations(smooth, 1.0, 0.0, 0.3, 0.2, 0.0);
  EXPECT_EQ(e.normal, 0.0);
  EXPECT_EQ(e.tangential, 0.0);  // smooth: no shear
  // Not roots: a penetration, or a pressure with a gap, or tension.
  EXPECT_NE(contact_equations(smooth, 1.0, 0.1, 0.0, 0.0, 0.0).normal, 0.0);
  EXPECT_NE(contact_equations(smooth, 1.0, -0.1, 0.0, 0.05, 0.0).normal, 0.0);
  EXPECT_NE(contact_equations(smooth, 1.0, 0.0, 0.0, -0.05, 0.0).normal, 0.0);
}

TEST(ContactLaw, FrictionSticksBelowAndSlipsAtMuTimesThePressure) {
  const ContactLaw law = friction(0.3);
  // Touching with l_n = 1: a shear of 0.2 < 0.3 with no slip is a root (stick) ...
  ContactEquations e = contact_equations(law, 1.0, 0.0, 0.0, 1.0, 0.2);
  EXPECT_EQ(e.state, ContactState::Stick);
  EXPECT_EQ(e.tangential, 0.0);
  // ... slipping forward with the shear at mu l_n is a root, with less it is not.
  e = contact_equations(law, 1.0, 0.0, 0.05, 1.0, 0.3);
  EXPECT_EQ(e.state, ContactState::Slip);
  EXPECT_NEAR(e.tangential, 0.0, 1e-15);
  EXPECT_NE(contact_equations(law, 1.0, 0.0, 0.05, 1.0, 0.25).tangential, 0.0);
  // The cap (a stress) bounds the shear: with c = 2, l_t at most cap / c.
  const ContactLaw capped = friction(0.3, 0.4);
  EXPECT_NEAR(contact_equations(capped, 2.0, 0.0, 0.05, 1.0, 0.2).tangential, 0.0, 1e-15);
}

TEST(ContactLaw, DerivativesMatchFiniteDifferences) {
  const ContactLaw laws[] = {ContactLaw{}, ContactLaw{TangentialContact::Rough},
                             ContactLaw{TangentialContact::Adhesion, 0.7}, friction(0.4),
                             friction(0.4, 0.5)};
  // Points away from the kinks: open, stick, slip either way.
  const double at[][4] = {{-0.2, 0.1, 0.05, 0.1},
                          {0.01, 0.02, 1.0, 0.1},
                          {0.01, 0.3, 1.0, 0.2},
                          {0.02, -0.4, 2.0, -0.3}};
  const double h = 1e-7;
  for (const ContactLaw& law : laws)
    for (const auto& x : at) {
      const ContactEquations e = contact_equations(law, 1.3, x[0], x[1], x[2], x[3]);
      for (int k = 0; k < 4; ++k) {
        double y[4] = {x[0], x[1], x[2], x[3]};
        y[k] += h;
        const ContactEquations f = contact_equations(law, 1.3, y[0], y[1], y[2], y[3]);
        ASSERT_EQ(f.state, e.state);
        EXPECT_NEAR((f.normal - e.normal) / h, e.normal_d[k], 1e-6);
        EXPECT_NEAR((f.tangential - e.tangential) / h, e.tangential_d[k], 1e-6);
      }
    }
}

// The 3D law for a bounded shear (eq. 18.7a): a vector that sticks inside the bound and slips
// along the trial direction with the bound's size, so that dragging diagonally does not give
// sqrt(2) x mu (each tangent bounded on its own would).
TEST(ContactLaw, ThreeDimensionalShearSlipsAtTheBoundAlongTheTrialDirection) {
  const ContactLaw law = friction(0.3);
  const double slip[2] = {0.03, 0.04}, s0[2] = {0.0, 0.0};
  // Slipping diagonally with l_t = mu l_n along (3, 4) / 5 is a root ...
  const double along[2] = {0.3 * 0.6, 0.3 * 0.8};
  TangentialPair e = tangential_pair(law, 1.0, 0.0, slip, 1.0, along);
  EXPECT_EQ(e.state, ContactState::Slip);
  EXPECT_NEAR(e.residual[0], 0.0, 1e-15);
  EXPECT_NEAR(e.residual[1], 0.0, 1e-15);
  // ... mu l_n on each tangent (size sqrt(2) mu l_n) is not.
  const double each[2] = {0.3, 0.3};
  e = tangential_pair(law, 1.0, 0.0, slip, 1.0, each);
  EXPECT_GT(std::hypot(e.residual[0], e.residual[1]), 0.1);
  // A shear inside the bound with no slip sticks.
  const double inside[2] = {0.1, -0.2};
  e = tangential_pair(law, 1.0, 0.0, s0, 1.0, inside);
  EXPECT_EQ(e.state, ContactState::Stick);
  EXPECT_EQ(e.residual[0], 0.0);
  EXPECT_EQ(e.residual[1], 0.0);
  // Along one tangent it is the 2D law.
  const double s1[2] = {0.05, 0.0}, l1[2] = {0.25, 0.0};
  e = tangential_pair(law, 1.0, 0.0, s1, 1.0, l1);
  EXPECT_NEAR(e.residual[0], contact_equations(law, 1.0, 0.0, 0.05, 1.0, 0.25).tangential, 1e-15);
  EXPECT_EQ(e.residual[1], 0.0);
}

TEST(ContactLaw, ThreeDimensionalShearDerivativesMatchFiniteDifferences) {
  const ContactLaw laws[] = {ContactLaw{TangentialContact::Adhesion, 0.7}, friction(0.4),
                             friction(0.4, 0.5)};
  // (p, s_0, s_1, l_n, l_t0, l_t1): stick, and slip in several directions.
  const double at[][6] = {{0.01, 0.0, 0.0, 1.0, 0.1, -0.1},
                          {0.01, 0.3, 0.2, 1.0, 0.2, 0.1},
                          {0.02, -0.4, 0.1, 2.0, -0.3, 0.2},
                          {0.0, 0.05, -0.6, 1.5, 0.0, -0.4}};
  const double h = 1e-7;
  for (const ContactLaw& law : laws)
    for (const auto& x : at) {
      const TangentialPair e = tangential_pair(law, 1.3, x[0], &x[1], x[3], &x[4]);
      for (int k = 0; k < 6; ++k) {
        double y[6] = {x[0], x[1], x[2], x[3], x[4], x[5]};
        y[k] += h;
        const TangentialPair f = tangential_pair(law, 1.3, y[0], &y[1], y[3], &y[4]);
        ASSERT_EQ(f.state, e.state);
        for (int i = 0; i < 2; ++i)
          EXPECT_NEAR((f.residual[i] - e.residual[i]) / h, e.d[i][k], 1e-6)
              << "row " << i << " column " << k;
      }
    }
}

// A block on a rigid base, pressed down by N and pulled along by T, held by springs of
// stiffness k in both directions from where it starts a gap g above the base; its displacement
// (u, v) and the multipliers (l_n, l_t) solved by semi-smooth Newton with scale c. Penetration
// p = -(v + g) (down is negative v), slip s = u.
struct BlockResult {
  double u, v, pressure, shear;
  int iterations;
};

BlockResult solve_block(const ContactLaw& law, double c, double N, double T) {
  const double k = 100.0, g = 0.01;
  Eigen::Vector4d x = Eigen::Vector4d::Zero();  // u, v, l_n, l_t
  for (int it = 1; it <= 30; ++it) {
    const double p = -(x(1) + g), s = x(0);
    const ContactEquations e = contact_equations(law, c, p, s, x(2), x(3));
    // Energy 1/2 k (u^2 + v^2) - T u + N v + c l_n p + c l_t s: its gradient and the scaled
    // equations, with p' = (0, -1) and s' = (1, 0).
    Eigen::Vector4d r;
    r << k * x(0) - T + c * x(3), k * x(1) + N - c * x(2), c * e.normal, c * e.tangential;
    if (r.norm() < 1e-12 * (N + T)) return {x(0), x(1), c * x(2), c * x(3), it};
    Eigen::Matrix4d K = Eigen::Matrix4d::Zero();
    K(0, 0) = k;
    K(0, 3) = c;
    K(1, 1) = k;
    K(1, 2) = -c;
    const double dp[2] = {0.0, -1.0}, ds[2] = {1.0, 0.0};
    for (int j = 0; j < 2; ++j) {
      K(2, j) = c * (e.normal_d[0] * dp[j] + e.normal_d[1] * ds[j]);
      K(3, j) = c * (e.tangential_d[0] * dp[j] + e.tangential_d[1] * ds[j]);
    }
    K(2, 2) = c * e.normal_d[2];
    K(2, 3) = c * e.normal_d[3];
    K(3, 2) = c * e.tangential_d[2];
    K(3, 3) = c * e.tangential_d[3];
    x -= K.fullPivLu().solve(r);
  }
  return {x(0), x(1), c * x(2), c * x(3), -1};
}

TEST(ContactLaw, ABlockSlidingUnderFrictionCarriesMuTimesItsNormalForce) {
  const double N = 10.0, T = 5.0, k = 100.0, g = 0.01;
  for (double c : {10.0, 100.0, 1000.0}) {
    SCOPED_TRACE(c);
    // Pressed through the gap: the base carries N - k g; T above mu times it: it slips and the
    // shear is exactly mu (N - k g).
    const BlockResult slip = solve_block(friction(0.3), c, N, T);
    ASSERT_GT(slip.iterations, 0);
    EXPECT_NEAR(slip.v, -g, 1e-12);
    EXPECT_NEAR(slip.pressure, N - k * g, 1e-10);
    EXPECT_NEAR(slip.shear, 0.3 * (N - k * g), 1e-10);
    EXPECT_NEAR(slip.u, (T - 0.3 * (N - k * g)) / k, 1e-12);
    // Below the bound it sticks: no slip, the base carries all of T.
    const BlockResult stick = solve_block(friction(0.6), c, N, T);
    ASSERT_GT(stick.iterations, 0);
    EXPECT_NEAR(stick.u, 0.0, 1e-14);
    EXPECT_NEAR(stick.shear, T, 1e-10);
    // Pulled up off the base: open, no forces.
    const BlockResult open = solve_block(friction(0.3), c, -N, T);
    EXPECT_NEAR(open.pressure, 0.0, 1e-14);
    EXPECT_NEAR(open.shear, 0.0, 1e-14);
    EXPECT_NEAR(open.u, T / k, 1e-12);
  }
}

TEST(ContactLaw, AdhesionAndCapLimitTheShearToAStress) {
  const double N = 10.0, T = 5.0, k = 100.0, g = 0.01;
  const BlockResult adhesion =
      solve_block(ContactLaw{TangentialContact::Adhesion, 2.0}, 50.0, N, T);
  EXPECT_NEAR(adhesion.shear, 2.0, 1e-10);
  const BlockResult rough = solve_block(ContactLaw{TangentialContact::Rough}, 50.0, N, T);
  EXPECT_NEAR(rough.u, 0.0, 1e-14);
  EXPECT_NEAR(rough.shear, T, 1e-10);
  const BlockResult capped = solve_block(friction(0.5, 1.5), 50.0, N, T);
  EXPECT_NEAR(capped.shear, 1.5, 1e-10);
  EXPECT_NEAR(capped.pressure, N - k * g, 1e-10);
}

}  // namespace
}  // namespace geompm

// The time integration of the grid equations (physics/newmark.hpp, docs/theory.md §4.7) on a single
// degree of freedom m x'' + k x = 0, stepped exactly as the inertia contribution and the step's
// update use it: the trapezoidal rule keeps the energy; Bossak's scheme damps the highest
// frequencies to its closed-form spectral radius (1 + alpha_m) / (1 - alpha_m) (eq. 4.7d) and is
// second-order accurate at the low ones.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "geompm/physics/newmark.hpp"

namespace geompm {
namespace {

struct Oscillator {
  double x = 1.0, v = 0.0, a = -1.0;  // m = 1, k = omega^2 = 1: a0 in balance (eq. 4.7e)
  double energy(double k) const { return 0.5 * v * v + 0.5 * k * x * x; }
};

// One step: the balance m inertial(du) + k (x + du) = 0 is linear in du, with slope
// m mass_factor + k (the tangent), solved as Newton's first iterate solves it.
void step(const Newmark& scheme, double k, Oscillator& s) {
  Vector v0(1), a0(1), zero = Vector::Zero(1);
  v0 << s.v;
  a0 << s.a;
  const double at_zero = scheme.inertial_acceleration(zero, v0, a0)(0) + k * s.x;
  Vector du(1);
  du << -at_zero / (scheme.mass_factor() + k);
  const Vector a1 = scheme.acceleration(du, v0, a0);
  s.v = scheme.velocity(v0, a0, a1)(0);
  s.a = a1(0);
  s.x += du(0);
}

TEST(Newmark, TheTrapezoidalRuleKeepsTheEnergyAtEveryFrequency) {
  for (const double omega_dt : {0.1, 1.0, 100.0}) {
    const double k = omega_dt * omega_dt;  // dt = 1
    Oscillator s;
    s.a = -k * s.x;
    const double e0 = s.energy(k);
    for (int n = 0; n < 1000; ++n) step(Newmark{0.25, 0.5, 1.0, 0.0}, k, s);
    EXPECT_NEAR(s.energy(k) / e0, 1.0, 1e-10) << "omega dt = " << omega_dt;
  }
}

TEST(Newmark, BossakDampsTheHighestFrequenciesToItsSpectralRadius) {
  for (const double alpha_m : {-0.05, -0.1, -0.3}) {
    const double k = 1e8;  // omega dt = 10^4: the limit of eq. 4.7d to about 1e-7
    Oscillator s;
    s.a = -k * s.x;
    const Newmark scheme = Newmark::bossak(alpha_m, 1.0);
    std::vector<double> x;
    for (int n = 0; n < 44; ++n) {
      step(scheme, k, s);
      x.push_back(s.x);
    }
    // At infinite frequency the principal roots coincide at -rho: x_n = (c1 + c2 n)(-rho)^n, whose
    // D_n = x_{n+1}^2 - x_n x_{n+2} = c2^2 rho^(2n+2) falls by rho^2 a step exactly.
    const auto D = [&x](int n) { return x[n + 1] * x[n + 1] - x[n] * x[n + 2]; };
    EXPECT_NEAR(std::sqrt(D(41) / D(40)), (1 + alpha_m) / (1 - alpha_m), 1e-6)
        << "alpha_m = " << alpha_m;
  }
}

TEST(Newmark, BossakIsSecondOrderAccurate) {
  // x(t) = cos t: the error at t = 2 pi falls by 4 when the step is halved.
  const auto error_at_one_period = [](int steps) {
    const double dt = 2 * M_PI / steps;
    Oscillator s;  // x = 1, v = 0, a = -1
    const Newmark scheme = Newmark::bossak(-0.1, dt);
    for (int n = 0; n < steps; ++n) step(scheme, 1.0, s);
    return std::hypot(s.x - 1.0, s.v);
  };
  const double coarse = error_at_one_period(100), fine = error_at_one_period(200);
  EXPECT_NEAR(coarse / fine, 4.0, 0.1);
}

}  // namespace
}  // namespace geompm

// Newmark time integration of the grid equations (seed paper eqs. 8 and 11, which are the
// trapezoidal case beta = 1/4, gamma = 1/2), in the Bossak form (Wood, Bossak & Zienkiewicz 1980;
// docs/theory.md §4.7): with the displacement increment du of the step,
//   a1 = (du - dt v0 - dt^2 (1/2 - beta) a0) / (beta dt^2),            (4.7a)
//   v1 = v0 + dt ((1 - gamma) a0 + gamma a1),                          (4.7b)
// and the balance holds with the inertia of (1 - alpha_m) a1 + alpha_m a0 (eq. 4.7c), so the
// inertia term of the tangent is (1 - alpha_m) M / (beta dt^2). alpha_m = 0 is Newmark's method.
// With alpha_m in [-1/3, 0], gamma = 1/2 - alpha_m and beta = (1 - alpha_m)^2 / 4 the scheme is
// second-order accurate and damps the highest frequencies to the spectral radius
// (1 + alpha_m) / (1 - alpha_m) (eq. 4.7d), while the low ones, which carry the physics, lose
// almost nothing.
#pragma once

#include "geompm/core/linear_algebra.hpp"

namespace geompm {

struct Newmark {
  double beta = 0.25;
  double gamma = 0.5;
  double dt = 1.0;
  double alpha_m = 0.0;  // Bossak's weight of the old acceleration in the inertia (<= 0)

  /// The Bossak scheme of a given alpha_m with its second-order beta and gamma.
  static Newmark bossak(double alpha_m, double dt) {
    const double beta = 0.25 * (1.0 - alpha_m) * (1.0 - alpha_m);
    return Newmark{beta, 0.5 - alpha_m, dt, alpha_m};
  }

  Vector acceleration(const Vector& du, const Vector& v0, const Vector& a0) const {
    return (du - dt * v0 - dt * dt * (0.5 - beta) * a0) / (beta * dt * dt);
  }
  Vector velocity(const Vector& v0, const Vector& a0, const Vector& a1) const {
    return v0 + dt * ((1.0 - gamma) * a0 + gamma * a1);
  }
  /// The acceleration the mass multiplies in the balance of the step (eq. 4.7c).
  Vector inertial_acceleration(const Vector& du, const Vector& v0, const Vector& a0) const {
    return (1.0 - alpha_m) * acceleration(du, v0, a0) + alpha_m * a0;
  }
  /// d(inertial acceleration) / d(du): the factor of M on the tangent.
  double mass_factor() const { return (1.0 - alpha_m) / (beta * dt * dt); }
};

}  // namespace geompm

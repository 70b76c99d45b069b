// Newmark time integration of the grid equations (seed paper eqs. 8 and 11, which are the
// trapezoidal case beta = 1/4, gamma = 1/2): with the displacement increment du of the step,
//   a1 = (du - dt v0 - dt^2 (1/2 - beta) a0) / (beta dt^2),   v1 = v0 + dt ((1 - gamma) a0 + gamma
//   a1),
// and the inertia term of the tangent is M / (beta dt^2). beta = 1/2 (the seed's damped choice,
// §3.8) with gamma = 1/2 is stable and damps the highest frequencies.
#pragma once

#include "geompm/core/linear_algebra.hpp"

namespace geompm {

struct Newmark {
  double beta = 0.25;
  double gamma = 0.5;
  double dt = 1.0;

  Vector acceleration(const Vector& du, const Vector& v0, const Vector& a0) const {
    return (du - dt * v0 - dt * dt * (0.5 - beta) * a0) / (beta * dt * dt);
  }
  Vector velocity(const Vector& v0, const Vector& a0, const Vector& a1) const {
    return v0 + dt * ((1.0 - gamma) * a0 + gamma * a1);
  }
  double mass_factor() const { return 1.0 / (beta * dt * dt); }
};

}  // namespace geompm

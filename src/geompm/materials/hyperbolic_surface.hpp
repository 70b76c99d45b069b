// The smooth hyperbolic approximation of the Mohr-Coulomb surface of Abbo & Sloan (1995), "A
// smooth hyperbolic approximation to the Mohr-Coulomb yield criterion", Computers & Structures
// 54(3) 427-441 (docs/materials.md §3.6, eq. M.20):
//   F(tau) = p sin(phi) + sqrt(J^2 K(theta)^2 + a^2 sin^2(phi)) - c cos(phi),
// p the mean stress, J = sqrt(J2), theta the Lode angle (sin 3 theta = -3 sqrt(3)/2 J3 / J^3,
// +30 deg in triaxial compression, tension positive). With a = 0 and K the Mohr-Coulomb
// K(theta) = cos(theta) - sin(theta) sin(phi) / sqrt(3) it is the cone; a > 0 replaces the apex
// by a hyperbola whose tip, c / tan(phi) - a on the hydrostatic axis, has a hydrostatic normal;
// for |theta| above the transition angle theta_T, K = A - B sin 3 theta with A, B matching K and
// dK/dtheta at theta_T, so that the corners of the cone (triaxial compression and extension)
// are rounded too (dK/dtheta = 0 at +-30 deg). The surface is then smooth everywhere, and so is
// its plastic potential of the same form with psi: one surface, one return.
//
// Value, gradient and Hessian in principal stresses, from the invariants u = J2, v = J3 by the
// chain rule (eq. M.21); the Hessian of the potential makes the tangent consistent.
#pragma once

#include "geompm/core/tensor.hpp"

namespace geompm {

class HyperbolicSurface {
 public:
  /// angle, transition: degrees, 0 < angle < 90, 0 < transition < 30; rounding a >= 0 (stress).
  HyperbolicSurface(double angle, double cohesion, double rounding, double transition);

  struct Derivatives {
    double value;
    Vec3 gradient;
    Mat3 hessian;
  };
  double value(const Vec3& tau) const;
  Derivatives derivatives(const Vec3& tau) const;

  /// K(theta) as a function of x = sin 3 theta, with its first and second derivatives.
  struct LodeFactor {
    double k, dk, d2k;
  };
  LodeFactor lode_factor(double x) const;

  /// The hydrostatic stress of the tip, c / tan(phi) - a.
  double tip() const { return cohesion_ / tan_angle_ - rounding_; }

 private:
  double sin_angle_, tan_angle_, cohesion_, rounding_, strength_;  // strength_ = c cos(phi)
  double sin_3_transition_;
  double a_[2], b_[2];  // A, B for theta > theta_T [0] and theta < -theta_T [1]
};

}  // namespace geompm

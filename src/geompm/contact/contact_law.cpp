#include "geompm/contact/contact_law.hpp"

#include <algorithm>
#include <cmath>

namespace geompm {

namespace {
enum { kP = 0, kS = 1, kN = 2, kT = 3 };  // the derivatives' order: p, s, l_n, l_t
}

ContactEquations contact_equations(const ContactLaw& law, double scale, double p, double s,
                                   double l_n, double l_t, double closed) {
  ContactEquations e;
  // Normal (theory eq. 18.4): C_n = l_n - max(0, l_n + p), written as p where the max is active
  // and -l_n where it is not (the same root, with the sign that makes the tangent the symmetric
  // saddle point of the constrained energy where it touches).
  const double augmented = l_n + p;
  const bool touching = augmented > -closed;
  if (touching) {
    e.normal = p;
    e.normal_d[kP] = 1.0;
  } else {
    e.normal = -l_n;
    e.normal_d[kN] = -1.0;
  }
  if (law.tangential == TangentialContact::Smooth || !touching) {
    // No shear: l_t = 0 (eq. 18.5).
    e.tangential = -l_t;
    e.tangential_d[kT] = -1.0;
    e.state = touching ? ContactState::Slip : ContactState::Open;
    return e;
  }
  // The shear bound b over c (eq. 18.6): none for a bonded contact, a constant for adhesion,
  // mu times the augmented normal multiplier for friction (capped).
  double bound = std::numeric_limits<double>::infinity();
  double bound_d_normal = 0.0;  // d b / d(l_n + p)
  if (law.tangential == TangentialContact::Adhesion) {
    bound = law.adhesion / scale;
  } else if (law.tangential == TangentialContact::Friction) {
    bound = law.friction * std::max(augmented, 0.0);
    bound_d_normal = law.friction;
    if (bound > law.cap / scale) {
      bound = law.cap / scale;
      bound_d_normal = 0.0;
    }
  }
  const double trial = l_t + s;
  if (std::abs(trial) <= bound) {
    e.tangential = s;  // stick: no slip
    e.tangential_d[kS] = 1.0;
    e.state = ContactState::Stick;
    return e;
  }
  // Slip: l_t = b sign(l_t + s), i.e. C_t = -(l_t - b sign(trial)) (eq. 18.7).
  const double sign = trial > 0.0 ? 1.0 : -1.0;
  e.tangential = -(l_t - bound * sign);
  e.tangential_d[kT] = -1.0;
  e.tangential_d[kN] = sign * bound_d_normal;
  e.tangential_d[kP] = sign * bound_d_normal;
  e.state = ContactState::Slip;
  return e;
}

}  // namespace geompm

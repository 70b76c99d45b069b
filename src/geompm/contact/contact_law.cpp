#include "geompm/contact/contact_law.hpp"

#include <algorithm>
#include <cmath>

namespace geompm {

namespace {
enum { kP = 0, kS = 1, kN = 2, kT = 3 };  // the derivatives' order: p, s, l_n, l_t

struct Bound {
  double value, d_normal;  // b over c, and d b / d(l_n + p)
};

// The shear bound b over c (eq. 18.6): none for a bonded contact, a constant for adhesion,
// mu times the augmented normal multiplier for friction (capped).
Bound shear_bound(const ContactLaw& law, double scale, double augmented) {
  if (law.tangential == TangentialContact::Adhesion) return {law.adhesion / scale, 0.0};
  if (law.tangential == TangentialContact::Friction) {
    const double coulomb = law.friction * std::max(augmented, 0.0);
    if (coulomb > law.cap / scale) return {law.cap / scale, 0.0};
    return {coulomb, law.friction};
  }
  return {std::numeric_limits<double>::infinity(), 0.0};
}
}  // namespace

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
  const auto [bound, bound_d_normal] = shear_bound(law, scale, augmented);
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

TangentialPair tangential_pair(const ContactLaw& law, double scale, double p, const double s[2],
                               double l_n, const double l_t[2]) {
  enum { P = 0, S0 = 1, N = 3, T0 = 4 };  // the derivatives' order: p, s_0, s_1, l_n, l_t0, l_t1
  TangentialPair e;
  const Bound bound = shear_bound(law, scale, l_n + p);
  const double trial[2] = {l_t[0] + s[0], l_t[1] + s[1]};
  const double size = std::hypot(trial[0], trial[1]);
  if (size <= bound.value) {
    for (int i = 0; i < 2; ++i) {  // stick: no slip
      e.residual[i] = s[i];
      e.d[i][S0 + i] = 1.0;
    }
    return e;
  }
  // Slip (eq. 18.7a): C_i = -(l_ti - b g_i / |g|), g = l_t + s; d(g_i / |g|) / d g_j =
  // (delta_ij - g_i g_j / |g|^2) / |g|.
  e.state = ContactState::Slip;
  const double direction[2] = {trial[0] / size, trial[1] / size};
  for (int i = 0; i < 2; ++i) {
    e.residual[i] = -(l_t[i] - bound.value * direction[i]);
    for (int j = 0; j < 2; ++j) {
      const double turn = bound.value / size * ((i == j ? 1.0 : 0.0) - direction[i] * direction[j]);
      e.d[i][S0 + j] = turn;
      e.d[i][T0 + j] = turn - (i == j ? 1.0 : 0.0);
    }
    e.d[i][P] = e.d[i][N] = direction[i] * bound.d_normal;
  }
  return e;
}

}  // namespace geompm

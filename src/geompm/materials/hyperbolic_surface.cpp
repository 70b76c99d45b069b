#include "geompm/materials/hyperbolic_surface.hpp"

#include <cmath>
#include <numbers>

namespace geompm {

namespace {

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// The Mohr-Coulomb K(theta) and its derivative in theta (eq. M.20).
double mohr_coulomb_k(double theta, double sin_angle) {
  return std::cos(theta) - std::sin(theta) * sin_angle / std::numbers::sqrt3;
}
double mohr_coulomb_dk(double theta, double sin_angle) {
  return -std::sin(theta) - std::cos(theta) * sin_angle / std::numbers::sqrt3;
}

// sin 3 theta = -3 sqrt(3) / 2 J3 / J^3.
constexpr double lode_coefficient = -1.5 * std::numbers::sqrt3;

}  // namespace

HyperbolicSurface::HyperbolicSurface(double angle, double cohesion, double rounding,
                                     double transition)
    : sin_angle_(std::sin(radians(angle))),
      tan_angle_(std::tan(radians(angle))),
      cohesion_(cohesion),
      rounding_(rounding),
      strength_(cohesion * std::cos(radians(angle))),
      sin_3_transition_(std::sin(3.0 * radians(transition))) {
  // K = A - B sin 3 theta beyond +-theta_T, with K and dK/dtheta continuous there:
  // dK/dtheta = -3 B cos 3 theta_T gives B, then A from K (as Abbo & Sloan 1995 do).
  const double t = radians(transition);
  for (int side = 0; side < 2; ++side) {
    const double theta = side == 0 ? t : -t;
    b_[side] = -mohr_coulomb_dk(theta, sin_angle_) / (3.0 * std::cos(3.0 * t));
    a_[side] = mohr_coulomb_k(theta, sin_angle_) + b_[side] * std::sin(3.0 * theta);
  }
}

HyperbolicSurface::LodeFactor HyperbolicSurface::lode_factor(double x) const {
  if (std::abs(x) > sin_3_transition_) {
    const int side = x > 0 ? 0 : 1;
    return {a_[side] - b_[side] * x, -b_[side], 0.0};
  }
  // theta = asin(x) / 3 and its derivatives in x; d2K/dtheta2 = -K.
  const double theta = std::asin(x) / 3.0;
  const double root = std::sqrt(1.0 - x * x);
  const double dtheta = 1.0 / (3.0 * root), d2theta = x / (3.0 * root * root * root);
  const double k = mohr_coulomb_k(theta, sin_angle_), dk = mohr_coulomb_dk(theta, sin_angle_);
  return {k, dk * dtheta, -k * dtheta * dtheta + dk * d2theta};
}

double HyperbolicSurface::value(const Vec3& tau) const { return derivatives(tau).value; }

HyperbolicSurface::Derivatives HyperbolicSurface::derivatives(const Vec3& tau) const {
  // Eq. M.21: Q = J^2 K^2 as a function of u = J2 = s.s / 2 and v = J3 = s1 s2 s3, whose
  // derivatives in principal stresses are du = s, d2u = P, dv = P t, d2v = P W P, with P the
  // deviatoric projection, t_a the product of the other two s_b and W_ab = s_c (a, b, c distinct).
  const double p = tau.sum() / 3.0;
  const Vec3 s = tau - Vec3::Constant(p);
  const Mat3 projection = Mat3::Identity() - Mat3::Constant(1.0 / 3.0);
  const double u = 0.5 * s.squaredNorm();
  double q;
  Vec3 dq;
  Mat3 d2q;
  if (!(u > 1e-24 * tau.squaredNorm())) {
    // On the hydrostatic axis theta is undefined and Q = u K(0)^2 = u to second order
    // (K(0) = cos 0 = 1: theta = 0 lies below any transition angle).
    q = u;
    dq = s;
    d2q = projection;
  } else {
    const double v = s(0) * s(1) * s(2);
    const Vec3 dv = projection * Vec3(s(1) * s(2), s(0) * s(2), s(0) * s(1));
    Mat3 w;
    w << 0, s(2), s(1), s(2), 0, s(0), s(1), s(0), 0;
    const Mat3 d2v = projection * w * projection;
    const double j = std::sqrt(u);
    const double x = lode_coefficient * v / (u * j);
    const double x_u = -1.5 * x / u, x_v = lode_coefficient / (u * j);
    const LodeFactor k = lode_factor(x);
    const double curvature = k.dk * k.dk + k.k * k.d2k;  // d2(K^2 / 2) / dx2
    q = u * k.k * k.k;
    const double q_u = k.k * k.k - 3.0 * x * k.k * k.dk;
    const double q_v = 2.0 * u * k.k * k.dk * x_v;
    const double q_uu = x_u * (-k.k * k.dk - 3.0 * x * curvature);
    const double q_uv = x_v * (-k.k * k.dk - 3.0 * x * curvature);
    const double q_vv = 2.0 * u * x_v * x_v * curvature;
    dq = q_u * s + q_v * dv;
    d2q = q_uu * s * s.transpose() + q_uv * (s * dv.transpose() + dv * s.transpose()) +
          q_vv * dv * dv.transpose() + q_u * projection + q_v * d2v;
  }
  const double a = rounding_ * sin_angle_;
  const double r = std::sqrt(q + a * a);
  Derivatives out;
  out.value = p * sin_angle_ + r - strength_;
  out.gradient = Vec3::Constant(sin_angle_ / 3.0);
  out.hessian = Mat3::Zero();
  if (r > 0) {
    out.gradient += dq / (2.0 * r);
    out.hessian = d2q / (2.0 * r) - dq * dq.transpose() / (4.0 * r * r * r);
  }
  return out;
}

}  // namespace geompm

#include "geompm/materials/hyperbolic_return.hpp"

#include <Eigen/LU>
#include <cmath>

namespace geompm {

namespace {

// Newton's method stops when f and the strain residual, as a stress, are below this fraction of
// the largest stress in play: well below the Kuhn-Tucker tolerance, above round-off.
constexpr double newton_tolerance = 1e-12;
constexpr int newton_iterations = 50;

using Mat4 = Eigen::Matrix4d;
using Vec4 = Eigen::Vector4d;

// Eq. M.23: with Xi = (D^-1 + dgamma d2G)^-1, d tau / d eps_tr = Xi - Xi m n^T Xi / (n^T Xi m),
// n = dF and m = dG at the returned stress.
Mat3 hyperbolic_tangent(const Mat3& xi, const Vec3& normal, const Vec3& flow) {
  const Vec3 xi_flow = xi * flow;
  const Vec3 xi_normal = xi.transpose() * normal;
  return xi - xi_flow * xi_normal.transpose() / normal.dot(xi_flow);
}

// Eq. M.22: Newton's method on r = D^-1 (tau - tau_tr) + dgamma dG(tau) = 0 and F(tau) = 0 from
// the given (tau, dgamma), with backtracking on the residual as stresses (D r and F): near a tip
// of small radius the full step of the linearised hyperbola can overshoot far along its
// asymptote, and the Newton step is a descent direction of the squared residual. True when it
// converges, with the solution in (tau, dgamma).
struct HyperbolicNewton {
  const Mat3& compliance;
  const Mat3& elasticity;
  const HyperbolicSurface& yield;
  const HyperbolicSurface& potential;
  double tolerance;

  double merit(const Vec3& trial, const Vec3& tau, double dgamma, Vec4& residual,
               HyperbolicSurface::Derivatives& f, HyperbolicSurface::Derivatives& g) const {
    f = yield.derivatives(tau);
    g = potential.derivatives(tau);
    residual.head<3>() = compliance * (tau - trial) + dgamma * g.gradient;
    residual(3) = f.value;
    return (elasticity * residual.head<3>()).squaredNorm() + f.value * f.value;
  }

  bool solve(const Vec3& trial, Vec3& tau, double& dgamma) const {
    Vec4 residual;
    HyperbolicSurface::Derivatives f, g;
    double m = merit(trial, tau, dgamma, residual, f, g);
    for (int iteration = 0; iteration < newton_iterations; ++iteration) {
      if (!std::isfinite(m)) return false;
      if (m <= tolerance * tolerance) return true;
      Mat4 jacobian = Mat4::Zero();
      jacobian.topLeftCorner<3, 3>() = compliance + dgamma * g.hessian;
      jacobian.block<3, 1>(0, 3) = g.gradient;
      jacobian.block<1, 3>(3, 0) = f.gradient.transpose();
      const Vec4 step = jacobian.partialPivLu().solve(-residual);
      if (!step.allFinite()) return false;
      Vec4 r_next;
      HyperbolicSurface::Derivatives f_next, g_next;
      double length = 1.0, next = m;
      for (int cut = 0; cut < 12; ++cut, length *= 0.5) {
        next = merit(trial, tau + length * step.head<3>(), dgamma + length * step(3), r_next,
                     f_next, g_next);
        if (next < m) break;
      }
      if (!(next < m)) return false;
      tau += length * step.head<3>();
      dgamma += length * step(3);
      residual = r_next;
      f = f_next;
      g = g_next;
      m = next;
    }
    return m <= tolerance * tolerance;
  }
};

}  // namespace

PrincipalReturn return_to_hyperbolic_surface(const Vec3& trial_strain, const Mat3& elasticity,
                                             const HyperbolicSurface& yield,
                                             const HyperbolicSurface& potential,
                                             SurfaceTangent surface_tangent) {
  PrincipalReturn out;
  const Vec3 trial = elasticity * trial_strain;
  const double scale = std::max(trial.cwiseAbs().maxCoeff(), std::abs(yield.tip()));
  const HyperbolicSurface::Derivatives f_trial = yield.derivatives(trial);
  out.stress = trial;
  out.tangent = elasticity;
  if (f_trial.value <= kkt_tolerance * scale) {
    // On the surface the plastic side's tangent if asked for: eq. M.23 with dgamma = 0
    // (docs/materials.md §1.7).
    if (surface_tangent == SurfaceTangent::plastic && f_trial.value >= -kkt_tolerance * scale) {
      out.tangent =
          hyperbolic_tangent(elasticity, f_trial.gradient, potential.derivatives(trial).gradient);
      out.active = 1;
    }
    return out;
  }

  // Eq. M.22 from tau = tau_tr, dgamma = 0; should Newton's method not converge from there (a
  // trial state far beyond a tip of small radius), by continuation along the trial states
  // s tau_tr from where they cross the surface: each solution is the exact return of its own
  // trial state and starts the next one (the return is continuous in the trial state).
  const Mat3 compliance = elasticity.inverse();
  const double tolerance = newton_tolerance * scale;
  HyperbolicNewton newton{compliance, elasticity, yield, potential, tolerance};
  Vec3 tau = trial;
  double dgamma = 0;
  if (!newton.solve(trial, tau, dgamma)) {
    // Stress-free soil is inside the surface (a < c / tan(phi)): bisect for the crossing.
    double inside = 0, outside = 1;
    for (int k = 0; k < 60; ++k) {
      const double mid = 0.5 * (inside + outside);
      (yield.value(mid * trial) <= 0 ? inside : outside) = mid;
    }
    double s = inside, ds = (1 - s) / 8;
    tau = s * trial;
    dgamma = 0;
    while (s < 1 && ds > 1e-10) {
      const double next = std::min(1.0, s + ds);
      Vec3 t = tau;
      double g = dgamma;
      if (newton.solve(next * trial, t, g)) {
        s = next;
        tau = t;
        dgamma = g;
        ds *= 2;
      } else {
        ds *= 0.5;
      }
    }
    // The continuation stalled short of the trial state: what it holds is the return of another
    // trial state, so it is reported as a failure rather than used.
    out.converged = s >= 1;
  }
  const HyperbolicSurface::Derivatives f = yield.derivatives(tau), g = potential.derivatives(tau);
  out.active = 1;
  out.stress = tau;
  const Mat3 xi = (compliance + dgamma * g.hessian).inverse();
  out.tangent = hyperbolic_tangent(xi, f.gradient, g.gradient);
  out.plastic_strain = dgamma * g.gradient;
  return out;
}

}  // namespace geompm

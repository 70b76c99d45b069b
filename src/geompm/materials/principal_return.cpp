#include "geompm/materials/principal_return.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace geompm {

namespace {

// At most three planes are active at once: a vertex of a surface in 3D principal space.
using SmallMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, 3, 3>;
using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, 3, 1>;

// Kuhn-Tucker conditions are checked to this fraction of the largest stress in play: far above
// the round-off of the linear solves, far below any stress that matters.
constexpr double kkt_tolerance = 1e-9;

struct ActiveSetReturn {
  std::array<int, 3> plane{};
  int count = 0;
  SmallVector multiplier;
  Vec3 stress;
  double violation = std::numeric_limits<double>::infinity();
};

// Eq. M.4: with the planes of `mask` active, f_i(tau) = 0 gives A dgamma = f(tau_tr) with
// A_ij = n_i . D^e g_j, and tau = tau_tr - sum_j dgamma_j D^e g_j. Returns false when A is singular
// (planes that do not meet in an edge or a vertex, or flows that cannot reach it).
bool solve_active_set(unsigned mask, const Vec3& trial, const Mat3& de,
                      std::span<const YieldPlane> planes, ActiveSetReturn& r) {
  r.count = 0;
  for (int k = 0; k < static_cast<int>(planes.size()); ++k)
    if (mask & (1u << k)) r.plane[r.count++] = k;
  SmallMatrix a(r.count, r.count);
  SmallVector f(r.count);
  for (int i = 0; i < r.count; ++i) {
    const YieldPlane& pi = planes[r.plane[i]];
    f(i) = pi.normal.dot(trial) - pi.limit;
    for (int j = 0; j < r.count; ++j) a(i, j) = pi.normal.dot(de * planes[r.plane[j]].flow);
  }
  const Eigen::FullPivLU<SmallMatrix> lu(a);
  if (!lu.isInvertible()) return false;
  r.multiplier = lu.solve(f);
  r.stress = trial;
  for (int j = 0; j < r.count; ++j) r.stress -= r.multiplier(j) * (de * planes[r.plane[j]].flow);
  return true;
}

// Eq. M.5, scaled to a stress: the largest of a negative multiplier (as the stress it relaxes),
// a violated plane and a broken order tau_1 >= tau_2 >= tau_3. Zero (or round-off) when the
// return is admissible.
double kkt_violation(const ActiveSetReturn& r, const Mat3& de, std::span<const YieldPlane> planes) {
  double v = std::max(r.stress(1) - r.stress(0), r.stress(2) - r.stress(1));
  for (int j = 0; j < r.count; ++j)
    v = std::max(v, -r.multiplier(j) * (de * planes[r.plane[j]].flow).norm());
  for (const YieldPlane& p : planes) v = std::max(v, p.normal.dot(r.stress) - p.limit);
  return v;
}

}  // namespace

SymmetricEigen principal_descending(const Mat3& a) {
  const SymmetricEigen ascending = symmetric_eigen(a);
  SymmetricEigen e;
  for (int k = 0; k < 3; ++k) {
    e.values(k) = ascending.values(2 - k);
    e.vectors.col(k) = ascending.vectors.col(2 - k);
  }
  return e;
}

Mat3 principal_elasticity(double lambda, double mu) {
  return lambda * Mat3::Ones() + 2.0 * mu * Mat3::Identity();
}

std::vector<unsigned> active_sets_up_to_three(int plane_count) {
  std::vector<unsigned> sets;
  for (int size = 1; size <= 3; ++size)
    for (unsigned mask = 1; mask < (1u << plane_count); ++mask)
      if (std::popcount(mask) == size) sets.push_back(mask);
  return sets;
}

PrincipalReturn return_to_yield_planes(const Vec3& trial_strain, const Mat3& de,
                                       std::span<const YieldPlane> planes,
                                       std::span<const unsigned> candidates) {
  PrincipalReturn out;
  const Vec3 trial = de * trial_strain;
  double scale = trial.cwiseAbs().maxCoeff();
  for (const YieldPlane& p : planes) scale = std::max(scale, std::abs(p.limit));
  const double tolerance = kkt_tolerance * scale;

  bool elastic = true;
  for (const YieldPlane& p : planes) elastic = elastic && p.normal.dot(trial) - p.limit <= tolerance;
  if (elastic) {
    out.stress = trial;
    out.tangent = de;
    return out;
  }

  ActiveSetReturn best, candidate;
  unsigned best_mask = 0;
  for (unsigned mask : candidates) {
    if (!solve_active_set(mask, trial, de, planes, candidate)) continue;
    candidate.violation = kkt_violation(candidate, de, planes);
    if (candidate.violation < best.violation) {
      best = candidate;
      best_mask = mask;
    }
    if (best.violation <= tolerance) break;
  }

  if (best_mask == 0) {  // every face singular: not possible for a surface with a plane
    out.stress = trial;
    out.tangent = de;
    return out;
  }
  out.active = best_mask;
  out.stress = best.stress;
  // Eq. M.6: tau = tau_tr - D^e G A^-1 (N^T tau_tr - k), so
  // d tau / d eps_tr = D^e - D^e G A^-1 N^T D^e, with N, G the normals and flows of the face.
  Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::ColMajor, 3, 3> n(3, best.count),
      g(3, best.count);
  for (int j = 0; j < best.count; ++j) {
    n.col(j) = planes[best.plane[j]].normal;
    g.col(j) = planes[best.plane[j]].flow;
    out.plastic_strain += best.multiplier(j) * planes[best.plane[j]].flow;
  }
  const SmallMatrix a = n.transpose() * de * g;
  const SmallMatrix a_inverse = a.fullPivLu().inverse();
  out.tangent = de - (de * g) * a_inverse * (n.transpose() * de);
  return out;
}

double equivalent_plastic_strain(const Vec3& plastic_strain_increment) {
  return std::sqrt(2.0 / 3.0) * plastic_strain_increment.norm();
}

void assemble_principal_update(const SymmetricEigen& trial, const PrincipalReturn& r,
                               StressUpdate& out) {
  const Mat3& q = trial.vectors;
  out.kirchhoff = q * r.stress.asDiagonal() * q.transpose();
  out.elastic_strain = q * (trial.values - r.plastic_strain).asDiagonal() * q.transpose();
  out.tangent = principal_function_derivative4(trial, r.stress, r.tangent);
}

}  // namespace geompm

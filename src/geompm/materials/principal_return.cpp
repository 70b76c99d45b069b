#include "geompm/materials/principal_return.hpp"

#include <Eigen/LU>  // the closed-form 3x3 inverse and determinant
#include <algorithm>
#include <array>
#include <bit>
#include <cassert>
#include <cmath>
#include <limits>

namespace geompm {

namespace {

// The inverse of the leading k x k block (k <= 3: at most three planes meet at a vertex of a
// surface in principal space) in closed form; false when the block is singular relative to the
// Hadamard bound |det| <= product of the row norms (planes that do not meet in an edge or a
// vertex, or flows that cannot reach it).
bool invert_leading_block(const Mat3& a, int k, Mat3& inverse) {
  inverse.setZero();
  double bound = 1.0;
  for (int i = 0; i < k; ++i) bound *= a.row(i).head(k).norm();
  constexpr double singular = 1e-12;
  if (k == 1) {
    if (!(std::abs(a(0, 0)) > 0)) return false;
    inverse(0, 0) = 1.0 / a(0, 0);
    return true;
  }
  if (k == 2) {
    const double det = a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0);
    if (!(std::abs(det) > singular * bound)) return false;
    inverse(0, 0) = a(1, 1) / det;
    inverse(0, 1) = -a(0, 1) / det;
    inverse(1, 0) = -a(1, 0) / det;
    inverse(1, 1) = a(0, 0) / det;
    return true;
  }
  const double det = a.determinant();
  if (!(std::abs(det) > singular * bound)) return false;
  inverse = a.inverse();
  return true;
}

// One candidate face: its planes, the multipliers and the returned stress.
struct ActiveSetReturn {
  std::array<int, 3> plane{};
  int count = 0;
  Mat3 a_inverse;
  Vec3 multiplier = Vec3::Zero();
  Vec3 stress;
  double violation = std::numeric_limits<double>::infinity();
};

// What every candidate of one trial state shares: f_i(tau_tr) and D^e g_j for each plane.
struct TrialState {
  Vec3 stress;
  std::array<double, max_yield_planes> f{};
  std::array<Vec3, max_yield_planes> elastic_flow;
};

// Eq. M.4: with the planes of `mask` active, f_i(tau) = 0 gives A dgamma = f(tau_tr) with
// A_ij = n_i . D^e g_j, and tau = tau_tr - sum_j dgamma_j D^e g_j.
bool solve_active_set(unsigned mask, const TrialState& t, std::span<const YieldPlane> planes,
                      ActiveSetReturn& r) {
  r.count = 0;
  for (int k = 0; k < static_cast<int>(planes.size()) && r.count < 3; ++k)
    if (mask & (1u << k)) r.plane[r.count++] = k;
  Mat3 a = Mat3::Identity();
  Vec3 f = Vec3::Zero();
  for (int i = 0; i < r.count; ++i) {
    f(i) = t.f[r.plane[i]];
    for (int j = 0; j < r.count; ++j)
      a(i, j) = planes[r.plane[i]].normal.dot(t.elastic_flow[r.plane[j]]);
  }
  if (!invert_leading_block(a, r.count, r.a_inverse)) return false;
  r.multiplier = r.a_inverse * f;
  r.stress = t.stress;
  for (int j = 0; j < r.count; ++j) r.stress -= r.multiplier(j) * t.elastic_flow[r.plane[j]];
  return true;
}

// Eq. M.5, scaled to a stress: the largest of a negative multiplier (as the stress it relaxes),
// a violated plane and a broken order tau_1 >= tau_2 >= tau_3. Zero (or round-off) when the
// return is admissible.
double kkt_violation(const ActiveSetReturn& r, const TrialState& t,
                     std::span<const YieldPlane> planes) {
  double v = std::max(r.stress(1) - r.stress(0), r.stress(2) - r.stress(1));
  for (int j = 0; j < r.count; ++j)
    v = std::max(v, -r.multiplier(j) * t.elastic_flow[r.plane[j]].norm());
  for (const YieldPlane& p : planes) v = std::max(v, p.normal.dot(r.stress) - p.limit);
  return v;
}

// Eq. M.6: tau = tau_tr - D^e G A^-1 (N^T tau_tr - k), so
// d tau / d eps_tr = D^e - D^e G A^-1 N^T D^e, with N, G the normals and flows of the face.
void subtract_plastic_stiffness(const ActiveSetReturn& r, const TrialState& t,
                                std::span<const YieldPlane> planes, const Mat3& de, Mat3& tangent) {
  for (int i = 0; i < r.count; ++i) {
    const Vec3 normal_de = de * planes[r.plane[i]].normal;  // D^e symmetric: (n^T D^e)^T
    for (int j = 0; j < r.count; ++j)
      tangent -= r.a_inverse(j, i) * t.elastic_flow[r.plane[j]] * normal_de.transpose();
  }
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
                                       std::span<const unsigned> candidates,
                                       SurfaceTangent surface_tangent) {
  assert(planes.size() <= static_cast<std::size_t>(max_yield_planes));
  PrincipalReturn out;
  TrialState t;
  t.stress = de * trial_strain;
  double scale = t.stress.cwiseAbs().maxCoeff();
  bool elastic = true;
  for (std::size_t k = 0; k < planes.size(); ++k) {
    t.f[k] = planes[k].normal.dot(t.stress) - planes[k].limit;
    t.elastic_flow[k] = de * planes[k].flow;
    scale = std::max(scale, std::abs(planes[k].limit));
  }
  const double tolerance = kkt_tolerance * scale;
  for (std::size_t k = 0; k < planes.size(); ++k) elastic = elastic && t.f[k] <= tolerance;
  ActiveSetReturn best, candidate;
  if (elastic) {
    out.stress = t.stress;
    out.tangent = de;
    // On the surface (the stress of a converged plastic step, met again by a zero increment):
    // the update is not differentiable there, and either side's derivative is a valid Newton
    // tangent (a generalised Jacobian). The plastic side's, the tangent of eq. M.6 with the
    // multipliers zero on the largest face of planes at the surface, lets the first iterate of
    // a step from a zero start flow plastically where the last step did, instead of loading the
    // whole plastic zone elastically (docs/materials.md §1.7).
    if (surface_tangent == SurfaceTangent::elastic) return out;
    unsigned on_surface = 0;
    for (std::size_t k = 0; k < planes.size(); ++k)
      if (t.f[k] >= -tolerance) on_surface |= 1u << k;
    if (on_surface == 0) return out;
    for (auto face = candidates.rbegin(); face != candidates.rend(); ++face) {
      if ((*face & ~on_surface) != 0 || !solve_active_set(*face, t, planes, candidate)) continue;
      out.active = *face;
      subtract_plastic_stiffness(candidate, t, planes, de, out.tangent);
      break;
    }
    return out;
  }

  unsigned best_mask = 0;
  for (unsigned mask : candidates) {
    if (!solve_active_set(mask, t, planes, candidate)) continue;
    candidate.violation = kkt_violation(candidate, t, planes);
    if (candidate.violation < best.violation) {
      best = candidate;
      best_mask = mask;
    }
    if (best.violation <= tolerance) break;
  }
  if (best_mask == 0) {  // every face singular: not possible for a surface with a plane
    out.stress = t.stress;
    out.tangent = de;
    return out;
  }

  out.active = best_mask;
  out.stress = best.stress;
  out.tangent = de;
  subtract_plastic_stiffness(best, t, planes, de, out.tangent);
  for (int i = 0; i < best.count; ++i)
    out.plastic_strain += best.multiplier(i) * planes[best.plane[i]].flow;
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

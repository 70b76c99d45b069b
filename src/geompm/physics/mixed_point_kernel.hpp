// The mixed displacement-pressure (p-u) kernel at one point (docs/theory.md §11; after Brezzi &
// Fortin 1991, as in the seed paper's Introduction): the point's mean stress is replaced by an
// independent, continuous pressure field p^ = N p (compression positive), and the material's own
// pressure is tied to it only weakly, so that a nearly incompressible material does not lock.
//
//   equilibrium   f_u = v B^T sigma~,   sigma~ = dev sigma - p^ I              (eq. 11.1)
//   pressure      g   = v N (p^ - p_mat) / K,   p_mat = -tr(sigma) / 3          (eq. 11.2)
//   or its change over the step
//                 g   = v N ((p^ - p_mat) / K - m_n),                          (eq. 11.8)
//   m_n = (p^ - p_mat) / K of the point at the end of the last step
//
// with sigma, p_mat from the material at the point's full deformation, K the point's elastic bulk
// modulus and v its current volume. The cell-wise pressure stabilisation (eq. 11.5) is added by
// the grid, not here: it couples the points of a cell.
#pragma once

#include <algorithm>
#include <cmath>

#include "geompm/physics/point_kernel.hpp"

namespace geompm {

/// eq. 14.1: the stiffness kappa, as a fraction of the bulk modulus, that keeps the volume a mixed
/// material sees near its kinematic one where its pressure does not change with the volume.
inline constexpr double field_pressure_volume_stiffness = 1e-3;

/// eq. 14.4: the pressure stabilisation (eq. 11.5) at the field's pressure, as a multiple of the
/// 1/G of the material's own: with 1 or 3 a node-to-node checkerboard of the accumulated pressure
/// grows in the plastic zone of the stiff c-phi strip (validation.md §8) and stops it; 10 and 30
/// carry it through with loads 0.6 % apart (theory §14).
inline constexpr double field_pressure_stabilisation = 10.0;

template <int NS, int Dim>
struct MixedKernelResult {
  using Base = KernelResult<NS, Dim>;
  static constexpr int n = Base::n;
  Base u;  // internal force f_u and the block K_uu = d f_u / d u
  Eigen::Matrix<double, NS, 1> pressure_residual;  // g
  Eigen::Matrix<double, n, NS> K_up;               // d f_u / d p
  Eigen::Matrix<double, NS, n> K_pu;               // d g / d u
  Eigen::Matrix<double, NS, NS> K_pp;              // d g / d p
  Mat3 total_stress;                               // sigma~
  // At the field's pressure: ln J_k - ln R at the end of the step (eq. 14.2); with the
  // incremental pressure equation, (p^ - p_mat) / K (eq. 11.8); otherwise 0.
  double volume_mismatch = 0.0;
};

/// The mixed spatial tangent (eqs. 11.3-11.4). a = a_mat - sigma_il delta_jk (eq. 3.9); its
/// material part a_bar = a + sigma_il delta_jk is the rate of tau / J, whose trace rows give the
/// rate of the material pressure. With the field carrying the mean stress,
///   a~_ijkl = a_bar_ijkl - 1/3 delta_ij a_bar_mmkl - p^ delta_ij delta_kl - sigma~_il delta_jk.
template <int Dim>
struct MixedTangent {
  using GC = GradientComponents<Dim>;
  static constexpr int nc = GC::count;
  ComponentMatrix<Dim> a;                   // a~
  Eigen::Matrix<double, 1, nc> trace_rows;  // a_bar_mmkl
  Eigen::Matrix<double, 1, nc> identity;    // delta_kl
  MixedTangent(const ComponentMatrix<Dim>& a_bar, const Mat3& total_stress, double p_hat)
      : a(a_bar),
        trace_rows(Eigen::Matrix<double, 1, nc>::Zero()),
        identity(Eigen::Matrix<double, 1, nc>::Zero()) {
    for (int c = 0; c < nc; ++c)
      if (GC::row[c] == GC::col[c]) {
        trace_rows += a_bar.row(c);
        identity(c) = 1.0;
      }
    for (int c = 0; c < nc; ++c) {
      if (GC::row[c] == GC::col[c]) a.row(c) -= trace_rows / 3.0 + p_hat * identity;
      for (int d = 0; d < nc; ++d)
        if (GC::col[c] == GC::row[d]) a(c, d) -= total_stress(GC::row[c], GC::col[d]);
    }
  }
};

template <int NS, int Dim>
bool integrate_field_pressure_point(const Stencil<NS, Dim>& s, const PointStartState& p,
                                    const Eigen::Matrix<double, NS, Dim>& du,
                                    const Eigen::Matrix<double, NS, 1>& p_nodes, bool axisymmetric,
                                    bool want_tangent, MixedKernelResult<NS, Dim>& out,
                                    const AveragedVolumeChange<NS, Dim>* average);

/// p_nodes: the stencil's nodal pressures; average: the volume change averaged over the point's
/// cell (F-bar, theory §12), or null for the point's own. field_pressure: the material is
/// evaluated at the volume whose pressure is p^ (theory §14), not at the kinematic one.
/// incremental_pressure: the pressure equation ties the step's change of p^ - p_mat, not its
/// total (eq. 11.8), so that a mismatch a point carries from earlier steps (and into another
/// cell) does not force the field. Other arguments as integrate_point.
template <int NS, int Dim>
bool integrate_mixed_point(const Stencil<NS, Dim>& s, const PointStartState& p,
                           const Eigen::Matrix<double, NS, Dim>& du,
                           const Eigen::Matrix<double, NS, 1>& p_nodes, bool axisymmetric,
                           bool want_tangent, MixedKernelResult<NS, Dim>& out,
                           const AveragedVolumeChange<NS, Dim>* average = nullptr,
                           bool field_pressure = false, bool incremental_pressure = false) {
  using GC = GradientComponents<Dim>;
  constexpr int nc = GC::count;
  constexpr int n_dofs = KernelResult<NS, Dim>::n;
  if (field_pressure)
    return integrate_field_pressure_point(s, p, du, p_nodes, axisymmetric, want_tangent, out,
                                          average);
  GradientOperator<NS, Dim> B;
  out.volume_mismatch = 0.0;
  if (!deform_point(s, p, du, axisymmetric, want_tangent, out.u, B, average)) return false;

  const Mat3& sigma = out.u.state.cauchy_stress;
  const double p_mat = -sigma.trace() / 3.0;
  const double p_hat = s.N.dot(p_nodes);
  const double bulk = p.material->elastic_moduli(out.u.state.internal).bulk;
  const double v = out.u.volume;

  out.total_stress = sigma + (p_mat - p_hat) * Mat3::Identity();  // eq. 11.1
  Eigen::Matrix<double, nc, 1> sigma_total;
  for (int c = 0; c < nc; ++c) sigma_total(c) = out.total_stress(GC::row[c], GC::col[c]);
  out.u.internal_force.noalias() = v * (B.transpose() * sigma_total);
  const double carried = incremental_pressure ? p.volume_mismatch : 0.0;
  out.volume_mismatch = incremental_pressure ? (p_hat - p_mat) / bulk : 0.0;
  if (incremental_pressure)
    out.pressure_residual = (v * (out.volume_mismatch - carried)) * s.N;  // eq. 11.8
  else
    out.pressure_residual = (v * (p_hat - p_mat) / bulk) * s.N;  // eq. 11.2
  if (!want_tangent) return true;

  const ComponentMatrix<Dim> a_bar = material_part_of_tangent<Dim>(out.u.state);
  const MixedTangent<Dim> m(a_bar, out.total_stress, p_hat);
  const Eigen::Matrix<double, 1, nc>& trace_rows = m.trace_rows;
  const Eigen::Matrix<double, 1, nc>& identity = m.identity;
  const Eigen::Matrix<double, nc, n_dofs> AB = m.a.lazyProduct(B);
  out.u.stiffness.noalias() = v * B.transpose().lazyProduct(AB);

  const Eigen::Matrix<double, 1, n_dofs> div = divergence_operator<NS, Dim>(B);
  out.K_up.noalias() = -v * div.transpose() * s.N.transpose();
  // d(v p^ - v p_mat) = v p^ div du + v/3 a_bar_mmkl grad(du)_kl  (p^ held); eq. 11.8 adds
  // d(-v K m_n) = -K m_n v div du.
  Eigen::Matrix<double, 1, n_dofs> dg = (p_hat - bulk * carried) * div + (trace_rows * B) / 3.0;

  if (average) {
    // F-bar (theory eqs. 12.5-12.6): d(v sigma) += v q (D^ - D_in) du with q the
    // volume_average_stress_rate; its deviator enters the equilibrium (the field carries the
    // mean stress), and its trace the material pressure:
    //   d(v dev sigma)   += v dev q (D^ - D_in) du
    //   d(v p_mat)       -= v tr q / 3 (D^ - D_in) du
    Eigen::Matrix<double, nc, 1> q = volume_average_stress_rate<Dim>(a_bar, sigma);
    const double q_trace = identity.dot(q);
    q -= (q_trace / 3.0) * identity.transpose();  // dev
    const Eigen::Matrix<double, 1, n_dofs> excess =
        average->divergence - divergence_operator<NS, Dim>(B, true);
    out.u.stiffness.noalias() += (v * (B.transpose() * q)) * excess;
    dg += (q_trace / 3.0) * excess;  // g holds -v p_mat
  }
  out.K_pu.noalias() = (v / bulk) * s.N * dg;
  out.K_pp.noalias() = (v / bulk) * s.N * s.N.transpose();
  return true;
}

/// The mixed kernel whose material sees the field's pressure (docs/theory.md §14). The material
/// is evaluated at dF^ = (R / j)^(1/dim) dF on the grid's directions (as F-bar, eq. 12.2), with
/// the volume ratio R solved at the point so that its pressure is the field's,
///   p_mat(R) - kappa (ln R - ln j_k) = p^                                        (eq. 14.1)
/// so that a pressure-dependent yield condition (Mohr-Coulomb) holds at the pressure equilibrium
/// uses. j_k is the kinematic volume ratio (the point's own or its cell's average); kappa, a
/// small fraction of the bulk modulus, makes the solution unique where p_mat does not change
/// with the volume (at the apex of a cone, which cannot carry a p^ beyond its tension). The
/// pressure equation ties R to j_k in the mean over each node's support, over all steps so far,
///   g = v N (m_n + ln j_k - ln R)                                                (eq. 14.2)
/// with m_n the point's mismatch ln J_k - ln R at the start of the step.
/// which for an elastic material is eq. 11.2 to first order. Other arguments as
/// integrate_mixed_point.
template <int NS, int Dim>
bool integrate_field_pressure_point(const Stencil<NS, Dim>& s, const PointStartState& p,
                                    const Eigen::Matrix<double, NS, Dim>& du,
                                    const Eigen::Matrix<double, NS, 1>& p_nodes, bool axisymmetric,
                                    bool want_tangent, MixedKernelResult<NS, Dim>& out,
                                    const AveragedVolumeChange<NS, Dim>* average) {
  using GC = GradientComponents<Dim>;
  constexpr int nc = GC::count;
  constexpr int n_dofs = KernelResult<NS, Dim>::n;
  double radius = 0.0;
  const Mat3 dF = incremental_deformation_gradient(s, p, du, axisymmetric, radius);
  if (!(dF.determinant() > 0.0)) return false;
  const double j_own = dF.template topLeftCorner<Dim, Dim>().determinant();
  const double j_kin = average ? average->ratio : j_own;
  if (!(j_own > 0.0) || !(j_kin > 0.0)) return false;
  const double x_kin = std::log(j_kin);
  const double p_hat = s.N.dot(p_nodes);
  const double bulk = p.material->elastic_moduli(p.internal).bulk;
  const double kappa = field_pressure_volume_stiffness * bulk;

  // Eq. 14.1 by a safeguarded Newton iteration on x = ln R: its left side falls as x grows, at
  // the rate t + kappa, t = tr q / 3 (q the volume_average_stress_rate, the stress rate per
  // d ln R, eq. 12.5); bracketed, so that a kink of the return (a point turning elastic or
  // plastic) cannot make it cycle.
  GradientOperator<NS, Dim> B;
  AveragedVolumeChange<NS, Dim> trial;
  double x = x_kin, lo = -HUGE_VAL, hi = HUGE_VAL, t = bulk, p_mat = 0.0;
  const double tolerance = 1e-14 * bulk + 1e-13 * std::abs(p_hat);
  Eigen::Matrix<double, nc, 1> q;
  ComponentMatrix<Dim> a_bar;
  bool solved = false;
  for (int iteration = 0; iteration < 100; ++iteration) {
    trial.ratio = std::exp(x);
    if (!deform_point(s, p, du, axisymmetric, true, out.u, B, &trial)) return false;
    p_mat = -out.u.state.cauchy_stress.trace() / 3.0;
    a_bar = material_part_of_tangent<Dim>(out.u.state);
    q = volume_average_stress_rate<Dim>(a_bar, out.u.state.cauchy_stress);
    t = 0.0;
    for (int c = 0; c < nc; ++c)
      if (GC::row[c] == GC::col[c]) t += q(c) / 3.0;
    const double residual = p_mat - kappa * (x - x_kin) - p_hat;
    if (std::abs(residual) <= tolerance) {
      solved = true;
      break;
    }
    if (residual > 0)
      lo = std::max(lo, x);
    else
      hi = std::min(hi, x);
    const double rate = std::max(t, 0.0) + kappa;
    // Newton, inside the bracket (bisection otherwise); not beyond 0.1 in ln R in one go.
    double next = std::clamp(x + residual / rate, x - 0.1, x + 0.1);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (!std::isfinite(next) || next == x) break;
    x = next;
  }
  // Unsolved, or a material whose pressure rises with its volume (softening beyond kappa): no
  // unique R, and Newton cuts the step back.
  if (!solved || !(t + kappa > 0.0)) return false;

  const double v = out.u.volume;
  out.total_stress = out.u.state.cauchy_stress + (p_mat - p_hat) * Mat3::Identity();
  Eigen::Matrix<double, nc, 1> sigma_total;
  for (int c = 0; c < nc; ++c) sigma_total(c) = out.total_stress(GC::row[c], GC::col[c]);
  out.u.internal_force.noalias() = v * (B.transpose() * sigma_total);
  // Eq. 14.2 holds the mismatch accumulated over all steps, not the step's alone: with the step's,
  // the stabilisation of a pressure that varies within a cell (self-weight) would be balanced by
  // a new mismatch in every step, and the points' pressure would drift at rest (theory §14).
  const double mismatch = p.volume_mismatch + x_kin - x;
  out.volume_mismatch = mismatch;
  out.pressure_residual = (v * mismatch) * s.N;
  if (!want_tangent) return true;

  // Eq. 14.3: x = ln R follows u and p^ so that eq. 14.1 stays satisfied,
  //   dx = D_R du - N^T dp / (t + kappa),
  //   D_R = (t D_in + kappa D_k - tr(a_bar B) / 3 - p_mat div) / (t + kappa),
  // D_in, D_k the rates of ln j and ln j_k; the stress's rate is that of eq. 11.3 at R held plus
  // dev q (dx - D_in du) (eq. 12.5: the field carries the mean stress).
  const MixedTangent<Dim> m(a_bar, out.total_stress, p_hat);
  const Eigen::Matrix<double, 1, n_dofs> div = divergence_operator<NS, Dim>(B);
  const Eigen::Matrix<double, 1, n_dofs> div_in = divergence_operator<NS, Dim>(B, true);
  const Eigen::Matrix<double, 1, n_dofs> d_kin = average ? average->divergence : div_in;
  const double rate = t + kappa;
  const Eigen::Matrix<double, 1, n_dofs> d_x =
      (t * div_in + kappa * d_kin - (m.trace_rows * B) / 3.0 - p_mat * div) / rate;
  const Eigen::Matrix<double, nc, 1> dev_q = q - t * m.identity.transpose();
  const Eigen::Matrix<double, nc, n_dofs> AB = m.a.lazyProduct(B);
  const Eigen::Matrix<double, n_dofs, 1> B_dev_q = B.transpose() * dev_q;
  out.u.stiffness.noalias() = v * B.transpose().lazyProduct(AB);
  out.u.stiffness.noalias() += (v * B_dev_q) * (d_x - div_in);
  out.K_up.noalias() = -v * div.transpose() * s.N.transpose();
  out.K_up.noalias() -= (v / rate) * B_dev_q * s.N.transpose();
  out.K_pu.noalias() = v * s.N * (d_kin - d_x + mismatch * div);
  out.K_pp.noalias() = (v / rate) * s.N * s.N.transpose();
  return true;
}

}  // namespace geompm

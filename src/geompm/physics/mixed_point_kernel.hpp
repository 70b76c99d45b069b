// The mixed displacement-pressure (p-u) kernel at one point (docs/theory.md §11; after Brezzi &
// Fortin 1991, as in the seed paper's Introduction): the point's mean stress is replaced by an
// independent, continuous pressure field p^ = N p (compression positive), and the material's own
// pressure is tied to it only weakly, so that a nearly incompressible material does not lock.
//
//   equilibrium   f_u = v B^T sigma~,   sigma~ = dev sigma - p^ I              (eq. 11.1)
//   pressure      g   = v N (p^ - p_mat) / K,   p_mat = -tr(sigma) / 3          (eq. 11.2)
//
// with sigma, p_mat from the material at the point's full deformation, K the point's elastic bulk
// modulus and v its current volume. The cell-wise pressure stabilisation (eq. 11.5) is added by
// the grid, not here: it couples the points of a cell.
#pragma once

#include "geompm/physics/point_kernel.hpp"

namespace geompm {

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
};

/// p_nodes: the stencil's nodal pressures; average: the volume change averaged over the point's
/// cell (F-bar, theory §12), or null for the point's own. Other arguments as integrate_point.
template <int NS, int Dim>
bool integrate_mixed_point(const Stencil<NS, Dim>& s, const PointStartState& p,
                           const Eigen::Matrix<double, NS, Dim>& du,
                           const Eigen::Matrix<double, NS, 1>& p_nodes, bool axisymmetric,
                           bool want_tangent, MixedKernelResult<NS, Dim>& out,
                           const AveragedVolumeChange<NS, Dim>* average = nullptr) {
  using GC = GradientComponents<Dim>;
  constexpr int nc = GC::count;
  constexpr int n_dofs = KernelResult<NS, Dim>::n;
  GradientOperator<NS, Dim> B;
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
  out.pressure_residual = (v * (p_hat - p_mat) / bulk) * s.N;  // eq. 11.2
  if (!want_tangent) return true;

  // Tangent (eqs. 11.3-9.4). a = a_mat - sigma_il delta_jk (eq. 3.9); its material part
  // a_bar = a + sigma_il delta_jk is the rate of tau / J, whose trace rows give the rate of the
  // material pressure. The mixed spatial tangent is
  //   a~_ijkl = a_bar_ijkl - 1/3 delta_ij a_bar_mmkl - p^ delta_ij delta_kl - sigma~_il delta_jk.
  const ComponentMatrix<Dim> a_bar = material_part_of_tangent<Dim>(out.u.state);
  Eigen::Matrix<double, 1, nc> trace_rows = Eigen::Matrix<double, 1, nc>::Zero();
  Eigen::Matrix<double, 1, nc> identity = Eigen::Matrix<double, 1, nc>::Zero();
  for (int c = 0; c < nc; ++c)
    if (GC::row[c] == GC::col[c]) {
      trace_rows += a_bar.row(c);
      identity(c) = 1.0;
    }
  Eigen::Matrix<double, nc, nc> a_mixed = a_bar;
  for (int c = 0; c < nc; ++c) {
    if (GC::row[c] == GC::col[c]) a_mixed.row(c) -= trace_rows / 3.0 + p_hat * identity;
    for (int d = 0; d < nc; ++d)
      if (GC::col[c] == GC::row[d]) a_mixed(c, d) -= out.total_stress(GC::row[c], GC::col[d]);
  }
  const Eigen::Matrix<double, nc, n_dofs> AB = a_mixed.lazyProduct(B);
  out.u.stiffness.noalias() = v * B.transpose().lazyProduct(AB);

  const Eigen::Matrix<double, 1, n_dofs> div = divergence_operator<NS, Dim>(B);
  out.K_up.noalias() = -v * div.transpose() * s.N.transpose();
  // d(v p^ - v p_mat) = v p^ div du + v/3 a_bar_mmkl grad(du)_kl  (p^ held).
  Eigen::Matrix<double, 1, n_dofs> dg = p_hat * div + (trace_rows * B) / 3.0;

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

}  // namespace geompm

// The integration-point kernel of the Lagrangian phase (seed paper eqs. 5 and 10): from the
// nodal displacement increments of one cell to the point's stress, its internal-force
// contribution and its tangent-stiffness contribution. Templated on the element so that all
// sizes are compile-time and the small matrices live on the stack (docs/architecture.md).
//
// One code path for plane strain, axisymmetry and 3D: the gradient of a nodal shape function is
// written as a 3x3 tensor G^{a,i} = e_i (x) grad N_a, and in axisymmetry the radial degree of
// freedom adds the hoop part (N_a / r) e_z (x) e_z (docs/theory.md eq. 2.7). Only the components
// that can be non-zero are kept: (xx, xy, yx, yy, zz) in 2D and all nine in 3D.
#pragma once

#include <Eigen/LU>
#include <cmath>

#include "geompm/mesh/element.hpp"
#include "geompm/physics/finite_strain.hpp"

namespace geompm {

template <int Dim>
struct GradientComponents;
template <>
struct GradientComponents<2> {
  static constexpr int count = 5;
  static constexpr int row[5] = {0, 0, 1, 1, 2};
  static constexpr int col[5] = {0, 1, 0, 1, 2};
  static constexpr int pairs[5] = {0, 1, 3, 4, 8};  // 3 row + col
};
template <>
struct GradientComponents<3> {
  static constexpr int count = 9;
  static constexpr int row[9] = {0, 0, 0, 1, 1, 1, 2, 2, 2};
  static constexpr int col[9] = {0, 1, 2, 0, 1, 2, 0, 1, 2};
  static constexpr int pairs[9] = {0, 1, 2, 3, 4, 5, 6, 7, 8};
};

/// What a point knows of the grid during a step: shape values and reference gradients at the
/// point's nodes, on the grid as it was at the start of the step (fixed within the step, so
/// computed once per step). NS nodes: the cell's (standard MPM, compile-time size) or a wider,
/// run-time sized stencil (DDMP, where N is zero at nodes outside the point's cell; GIMP, where
/// N and its gradient are averages over the point's domain, docs/theory.md §9).
template <int NS, int Dim>
struct Stencil {
  Eigen::Matrix<double, NS, 1> N;
  Eigen::Matrix<double, NS, Dim> dN_dX;
};
template <class E>
using PointStencil = Stencil<E::nodes, E::dim>;

/// The start-of-step state a point brings into the kernel.
struct PointStartState {
  const Material* material;
  Vec3 position;  // at the start of the step (the radius is position.x() in axisymmetry)
  double volume;  // at the start of the step
  Mat3 F;
  Mat3 be;
  InternalVariables internal;
  double volume_mismatch = 0.0;  // MaterialPoints::volume_mismatch at the start of the step
};

template <int NS, int Dim>
struct KernelResult {
  static constexpr int n = NS == Eigen::Dynamic ? Eigen::Dynamic : NS * Dim;
  Eigen::Matrix<double, n, 1> internal_force;
  Eigen::Matrix<double, n, n> stiffness;
  FiniteStrainState state;
  double volume;        // current, v = v_n det dF: the volume the forces are integrated over
  double state_volume;  // v_n det dF of the state's deformation (differs with a volume average)
};
template <class E>
using PointKernelResult = KernelResult<E::nodes, E::dim>;

/// The point's gradient operator: row c = component (row[c], col[c]) of G^{a,i}, column a*dim + i
/// (docs/theory.md eq. 2.7), on the current (trial) configuration.
template <int NS, int Dim>
using GradientOperator =
    Eigen::Matrix<double, GradientComponents<Dim>::count, KernelResult<NS, Dim>::n>;

/// The volume change of a step averaged over the points of a cell (F-bar; docs/theory.md §12):
/// the ratio dJ^ = sum_q v_q,n j_q / sum_q v_q,n (eq. 12.1), j_q the volume ratio of dF_q in the
/// grid's directions, and its rate d(dJ^)/dJ^ = D^ du, D^ = sum_q v_q,n j_q D_q / sum_q v_q,n j_q,
/// with D_q the in-plane divergence operator of point q on the current configuration (eq. 12.4).
template <int NS, int Dim>
struct AveragedVolumeChange {
  double ratio = 1.0;
  Eigen::Matrix<double, 1, KernelResult<NS, Dim>::n> divergence;
};

/// The components a volume average scales: the normal stretches of the grid's directions (in
/// 2D the out-of-plane stretch, 1 in plane strain and r/R in axisymmetry, is the point's own).
template <int Dim>
constexpr bool scaled_by_volume_average(int c) {
  using GC = GradientComponents<Dim>;
  return GC::row[c] == GC::col[c] && GC::row[c] < Dim;
}

/// The incremental deformation gradient dF = I + d(du)/dX of the step, with the hoop stretch r/R
/// in axisymmetry (the out-of-plane stretch is 1 in plane strain); `radius` = r.
template <int NS, int Dim>
Mat3 incremental_deformation_gradient(const Stencil<NS, Dim>& s, const PointStartState& p,
                                      const Eigen::Matrix<double, NS, Dim>& du, bool axisymmetric,
                                      double& radius) {
  Mat3 dF = Mat3::Identity();
  dF.template topLeftCorner<Dim, Dim>() += du.transpose() * s.dN_dX;
  radius = 0.0;
  if (axisymmetric) {
    const double R = p.position.x();
    radius = R + s.N.dot(du.col(0));
    dF(2, 2) = radius / R;
  }
  return dF;
}

/// The gradient operator B of a point on the configuration reached by dF: row c = component
/// (row[c], col[c]) of G^{a,i}, column a*dim + i (docs/theory.md eq. 2.7).
template <int NS, int Dim>
void current_gradient_operator(const Stencil<NS, Dim>& s, const Mat3& dF, double radius,
                               bool axisymmetric, GradientOperator<NS, Dim>& B) {
  using GC = GradientComponents<Dim>;
  constexpr int nc = GC::count;
  const int nen = static_cast<int>(s.N.size());
  const Eigen::Matrix<double, Dim, Dim> dF_inplane = dF.template topLeftCorner<Dim, Dim>();
  const Eigen::Matrix<double, NS, Dim> dN_dx = s.dN_dX * dF_inplane.inverse();
  B.setZero(nc, nen * Dim);
  for (int a = 0; a < nen; ++a)
    for (int c = 0; c < nc; ++c) {
      const int i = GC::row[c], j = GC::col[c];
      if (i < Dim && j < Dim) B(c, a * Dim + i) = dN_dx(a, j);
    }
  if (axisymmetric)
    for (int a = 0; a < nen; ++a) B(nc - 1, a * Dim + 0) = s.N(a) / radius;
}

/// The divergence operator of a point: the trace rows of B (theory eq. 11.4); `in_plane`: only
/// the grid's directions (without the hoop term of axisymmetry), the rate of the volume average.
template <int NS, int Dim>
Eigen::Matrix<double, 1, KernelResult<NS, Dim>::n> divergence_operator(
    const GradientOperator<NS, Dim>& B, bool in_plane = false) {
  using GC = GradientComponents<Dim>;
  Eigen::Matrix<double, 1, KernelResult<NS, Dim>::n> div =
      Eigen::Matrix<double, 1, KernelResult<NS, Dim>::n>::Zero(1, B.cols());
  for (int c = 0; c < GC::count; ++c)
    if (in_plane ? scaled_by_volume_average<Dim>(c) : GC::row[c] == GC::col[c]) div += B.row(c);
  return div;
}

/// The kinematics and stress update of one point: from the stencil's nodal displacement
/// increments du (row a = node a) to the point's trial state, current volume and gradient
/// operator B. With a cell's volume average, the material sees dF^ = (dJ^ / j)^(1/dim) dF on the
/// grid's directions, j their volume ratio (F-bar, theory eq. 12.2), while B and the volume of the
/// forces are those of dF itself. Returns false if the point's deformation is inadmissible (det dF
/// <= 0) or its material's update failed (out.state.stress_update_failed): Newton then cuts the
/// step back. Shared by the displacement and the mixed kernels.
template <int NS, int Dim>
bool deform_point(const Stencil<NS, Dim>& s, const PointStartState& p,
                  const Eigen::Matrix<double, NS, Dim>& du, bool axisymmetric, bool want_tangent,
                  KernelResult<NS, Dim>& out, GradientOperator<NS, Dim>& B,
                  const AveragedVolumeChange<NS, Dim>* average = nullptr) {
  using GC = GradientComponents<Dim>;
  constexpr int nc = GC::count;
  double radius = 0.0;
  out.state.stress_update_failed = false;
  const Mat3 dF = incremental_deformation_gradient(s, p, du, axisymmetric, radius);
  const double dJ = dF.determinant();
  if (!(dJ > 0.0)) return false;
  Mat3 dF_state = dF;
  double state_ratio = dJ;
  if (average) {
    if (!(average->ratio > 0.0)) return false;
    // The grid's directions take the averaged volume change (eq. 12.2); in 2D the out-of-plane
    // stretch stays the point's own.
    const double j = dF.template topLeftCorner<Dim, Dim>().determinant();
    dF_state.template topLeftCorner<Dim, Dim>() *= std::pow(average->ratio / j, 1.0 / Dim);
    state_ratio = dF_state.determinant();
  }
  if (!finite_strain_update(*p.material, dF_state, p.F, p.be, p.internal, want_tangent, out.state,
                            GC::pairs, nc))
    return false;
  out.volume = p.volume * dJ;
  out.state_volume = p.volume * state_ratio;
  current_gradient_operator(s, dF, radius, axisymmetric, B);
  return true;
}

/// The volume ratio of a point's step in the grid's directions (det of dF's dim x dim block; det
/// dF in plane strain and 3D) and its rate operator, for a cell's volume average
/// (AveragedVolumeChange). False if det dF <= 0.
template <int NS, int Dim>
bool point_volume_change(const Stencil<NS, Dim>& s, const PointStartState& p,
                         const Eigen::Matrix<double, NS, Dim>& du, bool axisymmetric, double& dJ,
                         Eigen::Matrix<double, 1, KernelResult<NS, Dim>::n>& divergence) {
  double radius = 0.0;
  const Mat3 dF = incremental_deformation_gradient(s, p, du, axisymmetric, radius);
  if (!(dF.determinant() > 0.0)) return false;
  dJ = dF.template topLeftCorner<Dim, Dim>().determinant();
  GradientOperator<NS, Dim> B;
  current_gradient_operator(s, dF, radius, axisymmetric, B);
  divergence = divergence_operator<NS, Dim>(B, true);
  return true;
}

template <int Dim>
using ComponentMatrix =
    Eigen::Matrix<double, GradientComponents<Dim>::count, GradientComponents<Dim>::count>;

/// The material part of the spatial tangent a (theory eq. 3.9), a_bar_ijkl = a_ijkl +
/// sigma_il delta_jk: the rate of tau / J, whose trace rows give the rate of the material's
/// pressure (eq. 11.3).
template <int Dim>
ComponentMatrix<Dim> material_part_of_tangent(const FiniteStrainState& state) {
  using GC = GradientComponents<Dim>;
  constexpr int nc = GC::count;
  ComponentMatrix<Dim> a_bar = state.spatial_tangent.template topLeftCorner<nc, nc>();
  for (int c = 0; c < nc; ++c)
    for (int d = 0; d < nc; ++d)
      if (GC::col[c] == GC::row[d]) a_bar(c, d) += state.cauchy_stress(GC::row[c], GC::col[d]);
  return a_bar;
}

/// a_bar : P_k / k - sigma (theory eqs. 12.5-12.6): the rate of the stress of a point that sees
/// its cell's volume change, v sigma(dF^) with v its own volume, per unit excess (D^ - D_p) du of
/// the averaged over its own in-plane divergence. dF^ = alpha dF on the grid's k = dim directions,
/// alpha = (dJ^ / j)^(1/k), so d alpha / alpha = (1/k) (D^ - D_p) du stretches the k normal
/// components (P_k; a_bar : P_k the sum of a_bar's columns over them), and the stress is scaled by
/// j / dJ^ against v: d(v sigma) += v (a_bar : P_k / k - sigma) (D^ - D_p) du.
template <int Dim>
Eigen::Matrix<double, GradientComponents<Dim>::count, 1> volume_average_stress_rate(
    const ComponentMatrix<Dim>& a_bar, const Mat3& sigma) {
  using GC = GradientComponents<Dim>;
  constexpr int nc = GC::count;
  Eigen::Matrix<double, nc, 1> rate = Eigen::Matrix<double, nc, 1>::Zero();
  for (int d = 0; d < nc; ++d)
    if (scaled_by_volume_average<Dim>(d)) rate += a_bar.col(d) / Dim;
  for (int c = 0; c < nc; ++c) rate(c) -= sigma(GC::row[c], GC::col[c]);
  return rate;
}

/// The displacement formulation at one point: internal force  v B^T sigma  (seed eq. 5) and
/// tangent  v B^T a B  (seed eq. 10, theory eq. 3.9). With a cell's volume average (F-bar, theory
/// §12) sigma is the material's at dF^ and the tangent gains v B^T q (D^ - D_p), q the
/// volume_average_stress_rate (eq. 12.5). du as in deform_point.
template <int NS, int Dim>
bool integrate_point(const Stencil<NS, Dim>& s, const PointStartState& p,
                     const Eigen::Matrix<double, NS, Dim>& du, bool axisymmetric, bool want_tangent,
                     KernelResult<NS, Dim>& out,
                     const AveragedVolumeChange<NS, Dim>* average = nullptr) {
  using GC = GradientComponents<Dim>;
  constexpr int nc = GC::count;
  constexpr int n_dofs = KernelResult<NS, Dim>::n;
  GradientOperator<NS, Dim> B;
  if (!deform_point(s, p, du, axisymmetric, want_tangent, out, B, average)) return false;

  Eigen::Matrix<double, nc, 1> sigma;
  for (int c = 0; c < nc; ++c) sigma(c) = out.state.cauchy_stress(GC::row[c], GC::col[c]);
  out.internal_force.noalias() = out.volume * (B.transpose() * sigma);

  if (want_tangent) {
    const Eigen::Matrix<double, nc, nc> A =
        out.state.spatial_tangent.template topLeftCorner<nc, nc>();
    const Eigen::Matrix<double, nc, n_dofs> AB = A.lazyProduct(B);
    out.stiffness.noalias() = out.volume * B.transpose().lazyProduct(AB);
    if (average) {
      const Eigen::Matrix<double, nc, 1> q = volume_average_stress_rate<Dim>(
          material_part_of_tangent<Dim>(out.state), out.state.cauchy_stress);
      const Eigen::Matrix<double, 1, n_dofs> excess =
          average->divergence - divergence_operator<NS, Dim>(B, true);
      out.stiffness.noalias() += (out.volume * (B.transpose() * q)) * excess;
    }
  }
  return true;
}

/// Reference gradients of the shape functions at xi in a cell whose nodes are `X` (row a = node
/// a, the grid at the start of the step): dN/dX = dN/dxi (dX/dxi)^-1.
template <class E>
PointStencil<E> make_stencil(const Eigen::Matrix<double, E::nodes, E::dim>& X,
                             const typename E::Local& xi) {
  PointStencil<E> s;
  s.N = E::shape(xi);
  const typename E::Gradients dN_dxi = E::shape_gradients(xi);
  const Eigen::Matrix<double, E::dim, E::dim> J = X.transpose() * dN_dxi;  // dX/dxi
  s.dN_dX = dN_dxi * J.inverse();
  return s;
}

}  // namespace geompm

// The member templates of PointIntegrator that integrate the points of a cell type (theory
// eqs. 3.9, 11.1-11.7, 12.1-12.4), included only by the translation units that instantiate them:
// point_integrator_tri.cpp, _quad.cpp and _3d.cpp (one cell family each, so that no unit
// compiles every cell type's kernels) and point_integrator_wide.cpp (wide stencils).
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <type_traits>

#include "geompm/mesh/cell_geometry.hpp"
#include "geompm/mesh/element.hpp"
#include "geompm/physics/exact_pressure_projection.hpp"
#include "geompm/physics/mixed_point_kernel.hpp"
#include "geompm/physics/point_integrator.hpp"
#include "geompm/physics/point_kernel.hpp"

namespace geompm {

template <class E>
void PointIntegrator::pressure_stabilisation(Index ci,
                                             Eigen::Matrix<double, E::nodes, E::nodes>& S) const {
  // Polynomial pressure projection (Dohrmann & Bochev 2004; theory eq. 11.5): the pressure's
  // departure from its mean over the cell, p - Pi p, is penalised with 1/G,
  //   S = sum_p (v_p / G_p) (N_p - m)(N_p - m)^T,   m = sum_p v_p N_p / sum_p v_p,
  // over the cell's mixed points with their start-of-step volumes (so S does not depend on the
  // unknowns). It removes the checkerboard modes equal-order u-p cells allow and vanishes for a
  // pressure constant over the cell. At the field's pressure it is made stronger (eq. 14.4), point
  // by point: a cell may hold materials at their own pressure and at the field's.
  const auto strength = [&](Index p) {
    return grid_.is_field_pressure(points_, p) ? field_pressure_stabilisation : 1.0;
  };
  constexpr int nen = E::nodes;
  using Values = Eigen::Matrix<double, nen, 1>;
  S.setZero();
  Values mean = Values::Zero();
  double volume = 0.0;
  for (Index p = grid_.cell_point_begin(ci); p < grid_.cell_point_end(ci); ++p)
    if (grid_.is_mixed(points_, p)) {
      mean += points_.volume[p] * Eigen::Map<const Values>(grid_.cell_shape(p));
      volume += points_.volume[p];
    }
  if (volume <= 0.0) return;
  mean /= volume;
  double compliance = 0.0;  // sum of the points' v / G
  for (Index p = grid_.cell_point_begin(ci); p < grid_.cell_point_end(ci); ++p)
    if (grid_.is_mixed(points_, p)) {
      const double shear =
          grid_.materials()[points_.material[p]]->elastic_moduli(points_.internal[p]).shear;
      const Values d = Eigen::Map<const Values>(grid_.cell_shape(p)) - mean;
      S.noalias() += (strength(p) * points_.volume[p] / shear) * (d * d.transpose());
      compliance += strength(p) * points_.volume[p] / shear;
    }
  // Eq. 11.10: a share of the exactly integrated projection, with the points' v / G, so that
  // only the cell's constant pressures escape it however its points cluster.
  if (const double floor = grid_.settings().pressure_stabilisation_floor; floor > 0.0)
    S.noalias() += (floor * compliance) * exact_pressure_projection<E>();
}

template <class E>
Stencil<E::nodes, E::dim> PointIntegrator::cell_stencil(Index p) const {
  PointStencil<E> s;
  s.N = Eigen::Map<const typename E::Values>(grid_.cell_shape(p));
  s.dN_dX = Eigen::Map<const Eigen::Matrix<double, E::nodes, E::dim>>(grid_.cell_gradients(p));
  return s;
}

template <int NS, int Dim, class StencilOf>
bool PointIntegrator::average_volume_change(Index ci, const Eigen::Matrix<double, NS, Dim>& du,
                                            StencilOf&& stencil_of,
                                            AveragedVolumeChange<NS, Dim>& average) const {
  // Eq. 12.1 and 12.4 over the cell's averaged points: volume ratios weighted by the start-of-step
  // volumes (so the cell's volume is kept exactly: sum_q v_q,n dJ^ = sum_q v_q), divergence
  // operators by the current ones. stencil_of(p): point p's weights over the rows of du.
  const bool axisymmetric = grid_.axisymmetric();
  const Index n = du.rows() * Dim;
  Eigen::Matrix<double, 1, KernelResult<NS, Dim>::n> divergence(1, n);
  double start_volume = 0.0, volume = 0.0;
  average.divergence.setZero(1, n);
  for (Index p = grid_.cell_point_begin(ci); p < grid_.cell_point_end(ci); ++p) {
    if (!grid_.is_averaged(points_, p)) continue;
    double dJ = 1.0;
    if (!point_volume_change(stencil_of(p), start_state(p), du, axisymmetric, dJ, divergence)) {
      note_inadmissible(p);
      return false;
    }
    const double v_n = points_.volume[p];
    start_volume += v_n;
    volume += v_n * dJ;
    average.divergence += (v_n * dJ) * divergence;
  }
  average.ratio = start_volume > 0.0 ? volume / start_volume : 1.0;
  if (volume > 0.0) average.divergence /= volume;
  return true;
}

template <int NS, int Dim, class Force, class Stiffness>
void PointIntegrator::add_point_terms(Index p, const Eigen::Matrix<double, NS, 1>& N,
                                      const Eigen::Matrix<double, NS, Dim>& du, bool with_tangent,
                                      Force& f, Stiffness& K) const {
  // A force F(u) at the point whose derivative is D = dF/du enters f_int as F N_a and the
  // tangent as N_a N_b D (a prescribed motion's spring, docs/theory.md eq. 5.1).
  const int nodes = static_cast<int>(N.size());
  for (PointTerm* term : point_terms_) {
    if (!term->acts(p)) continue;
    Vec3 u = Vec3::Zero(), force;
    Mat3 stiffness;
    u.template head<Dim>() = du.transpose() * N;
    term->force(p, u, force, stiffness);
    for (int a = 0; a < nodes; ++a)
      for (int i = 0; i < Dim; ++i) f(a * Dim + i) += force(i) * N(a);
    if (!with_tangent) continue;
    for (int a = 0; a < nodes; ++a)
      for (int b = 0; b < nodes; ++b) {
        const double w = N(a) * N(b);
        for (int i = 0; i < Dim; ++i)
          for (int k = 0; k < Dim; ++k)
            if (stiffness(i, k) != 0.0) K(a * Dim + i, b * Dim + k) += w * stiffness(i, k);
      }
  }
}

template <class E, bool Mixed>
bool PointIntegrator::add_cells(const Vector& du, Vector& f_int, SparseMatrix* tangent) {
  std::atomic<bool> admissible{true};
  const Mesh& mesh = grid_.mesh();
  const bool mixed_mesh = mesh.mixed();  // then only this type's cells
  for (const auto& colour : grid_.colours()) {
    const Index count = static_cast<Index>(colour.size());
#pragma omp parallel for schedule(dynamic, 8) if (count > 64)
    for (Index k = 0; k < count; ++k) {
      if (mixed_mesh && mesh.type_of(grid_.active_cells()[colour[k]]) != cell_type_of<E>) continue;
      if (!add_cell<E, Mixed>(colour[k], du, f_int, tangent)) admissible = false;
    }
  }
  return admissible;
}

template <class E, bool Mixed>
bool PointIntegrator::add_cell(Index ci, const Vector& du, Vector& f_int, SparseMatrix* tangent) {
  constexpr int nen = E::nodes, dim = E::dim, n = nen * dim, m = n + (Mixed ? nen : 0);
  // In a distributed run another process holds the points of a cell it owns, and adds it.
  if (!grid_.owns_cell(grid_.active_cells()[ci])) return true;
  const double s_p = pressure_ ? pressure_->scale() : 1.0;
  const auto nodes = grid_.mesh().cell_nodes(grid_.active_cells()[ci]);
  std::array<Index, nen> active;
  for (int a = 0; a < nen; ++a) active[a] = grid_.node_to_active()[nodes[a]];
  Eigen::Matrix<double, nen, dim> du_local;
  Eigen::Matrix<double, m, 1> x_flat;  // the cell's unknowns, local order (local_dof)
  for (int l = 0; l < m; ++l) x_flat(l) = du(local_dof(active, nen, l));
  for (int a = 0; a < nen; ++a) du_local.row(a) = x_flat.template segment<dim>(a * dim);
  Eigen::Matrix<double, nen, 1> p_local;  // nodal pressures (eq. 11.6)
  if constexpr (Mixed)
    for (int a = 0; a < nen; ++a) p_local(a) = pressure_->start()(active[a]) + s_p * x_flat(n + a);

  Eigen::Matrix<double, m, 1> f_cell = Eigen::Matrix<double, m, 1>::Zero();
  Eigen::Matrix<double, m, m> K_cell = Eigen::Matrix<double, m, m>::Zero();
  for (const auto& term : cell_terms_)
    if (const double* block = term->cell_block(ci)) {
      const Eigen::Map<const Eigen::Matrix<double, m, m>> K_term(block);
      f_cell.noalias() += K_term * x_flat;
      K_cell += K_term;
    }
  if constexpr (Mixed) {
    Eigen::Matrix<double, nen, nen> S;
    pressure_stabilisation<E>(ci, S);
    // Eq. 11.5 on the pressure, or eq. 11.9 on its change over the step (s_p x, eq. 11.6).
    if (grid_.settings().mixed_incremental_pressure)
      f_cell.template tail<nen>().noalias() += (s_p * s_p) * (S * x_flat.template tail<nen>());
    else
      f_cell.template tail<nen>().noalias() += s_p * (S * p_local);
    K_cell.template bottomRightCorner<nen, nen>() += (s_p * s_p) * S;
  }
  // Points with a wide stencil are assembled one by one (add_wide_stencil_points).
  const Index point_end =
      grid_.wide_stencil() ? grid_.cell_point_begin(ci) : grid_.cell_point_end(ci);
  AveragedVolumeChange<nen, dim> average;
  if (grid_.averaging() && point_end > grid_.cell_point_begin(ci) &&
      !average_volume_change(
          ci, du_local, [&](Index q) { return cell_stencil<E>(q); }, average))
    return false;
  const bool admissible = integrate_cell_points<E, Mixed>(ci, point_end, du_local, p_local, average,
                                                          tangent != nullptr, f_cell, K_cell);
  for (int l = 0; l < m; ++l) f_int(local_dof(active, nen, l)) += f_cell(l);
  if (tangent) {
    // The scatter map's stride is m, or on a mixed mesh that of its largest cell: known at compile
    // time on a mesh of one type (the loop unrolls as before).
    const auto scatter = [&](auto stride) {
      const int* map = scatter_.data() + std::size_t(ci) * stride * stride;
      double* values = tangent->valuePtr();
      for (int lc = 0; lc < m; ++lc)
        for (int lr = 0; lr < m; ++lr) {
          const int at = map[lc * stride + lr];
          if (at >= 0) values[at] += K_cell(lr, lc);
        }
    };
    if (const int stride = cell_unknowns(); stride == m)
      scatter(std::integral_constant<int, m>{});
    else
      scatter(stride);
  }
  return admissible;
}

template <class E, bool Mixed, class Displacements, class Pressures, class Average, class CellForce,
          class CellStiffness>
bool PointIntegrator::integrate_cell_points(Index ci, Index point_end,
                                            const Displacements& du_local, const Pressures& p_local,
                                            const Average& average, bool with_tangent,
                                            CellForce& f_cell, CellStiffness& K_cell) const {
  constexpr int nen = E::nodes, n = nen * E::dim;
  const bool axisymmetric = grid_.axisymmetric();
  const double s_p = pressure_ ? pressure_->scale() : 1.0;
  PointStencil<E> s;
  PointKernelResult<E> r;
  [[maybe_unused]] MixedKernelResult<E::nodes, E::dim> rm;
  bool admissible = true;
  for (Index p = grid_.cell_point_begin(ci); p < point_end; ++p) {
    s = cell_stencil<E>(p);
    const PointStartState start = start_state(p);
    const Average* cell_average = grid_.is_averaged(points_, p) ? &average : nullptr;
    // The point's forces and stiffness by its formulation; then, shared, its state.
    const FiniteStrainState* state = &r.state;
    const Mat3* stress = &r.state.cauchy_stress;
    double volume = 0.0, own_volume = 0.0, volume_mismatch = 0.0;
    bool ok = false;
    if constexpr (Mixed) {
      if (grid_.is_mixed(points_, p)) {
        ok = integrate_mixed_point(s, start, du_local, p_local, axisymmetric, with_tangent, rm,
                                   cell_average, grid_.is_field_pressure(points_, p),
                                   grid_.settings().mixed_incremental_pressure);
        if (ok) {
          f_cell.template head<n>() += rm.u.internal_force;
          f_cell.template tail<nen>() += s_p * rm.pressure_residual;
          if (with_tangent) {
            K_cell.template topLeftCorner<n, n>() += rm.u.stiffness;
            K_cell.template topRightCorner<n, nen>() += s_p * rm.K_up;
            K_cell.template bottomLeftCorner<nen, n>() += s_p * rm.K_pu;
            K_cell.template bottomRightCorner<nen, nen>() += (s_p * s_p) * rm.K_pp;
          }
          state = &rm.u.state;
          stress = &rm.total_stress;
          volume = rm.u.state_volume;
          own_volume = rm.u.volume;
          volume_mismatch = rm.volume_mismatch;
        }
      }
    }
    if (!(Mixed && grid_.is_mixed(points_, p))) {
      ok = integrate_point(s, start, du_local, axisymmetric, with_tangent, r, cell_average);
      if (ok) {
        f_cell.template head<n>() += r.internal_force;
        if (with_tangent) K_cell.template topLeftCorner<n, n>() += r.stiffness;
        volume = r.state_volume;
        own_volume = r.volume;
      }
    }
    if (!ok) {
      note_inadmissible(p, Mixed && grid_.is_mixed(points_, p) ? rm.u.state.stress_update_failed
                                                               : r.state.stress_update_failed);
      admissible = false;
      continue;
    }
    if (!point_terms_.empty()) add_point_terms(p, s.N, du_local, with_tangent, f_cell, K_cell);
    commit(p, *state, volume, *stress, own_volume, volume_mismatch);
  }
  return admissible;
}

}  // namespace geompm

/// Instantiates PointIntegrator's cell kernels for the cell type `T` (a CellType enumerator),
/// displacement-only and mixed.
#define GEOMPM_POINT_INTEGRATOR_CELLS(T)                                                        \
  template bool PointIntegrator::add_cells<Element<CellType::T>, false>(const Vector&, Vector&, \
                                                                        SparseMatrix*);         \
  template bool PointIntegrator::add_cells<Element<CellType::T>, true>(const Vector&, Vector&,  \
                                                                       SparseMatrix*);

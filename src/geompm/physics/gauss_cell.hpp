// The Gauss points of one finite element (docs/theory.md §17.7, §19): the material points' kernel
// (physics/point_kernel.hpp, theory eqs. 3.9, 17.12) at each of the cell's quadrature points,
// with the Gauss point's volume v_q = w_q det J (times r in axisymmetry) on the configuration at
// the start of the step in place of a point's. Shared by deformable structures and by the FEM
// regions of the background mesh, whose Gauss points carry their state from step to step.
#pragma once

#include "geompm/dofs/sparsity.hpp"
#include "geompm/mesh/element.hpp"
#include "geompm/physics/point_kernel.hpp"

namespace geompm {

/// Internal force sum_q v_q B^T sigma and tangent sum_q v_q B^T a B of one cell at its nodal
/// increments du (row a = node a), its nodes X at the start of the step (row a = node a).
/// start_of(q): Gauss point q's start-of-step state (material, F, b_e, internal variables; its
/// position and volume are set here); on_state(q, result): its updated state. With
/// `volume_average` every point sees the cell's mean volume change (F-bar, theory eq. 12.1-12.4,
/// weighted by the start-of-step volumes as for material points). False where a point's
/// deformation is inadmissible or its stress update failed.
template <class E, class StartOf, class OnState>
bool integrate_gauss_cell(const Eigen::Matrix<double, E::nodes, E::dim>& X,
                          const Eigen::Matrix<double, E::nodes, E::dim>& du, bool axisymmetric,
                          bool want_tangent, bool volume_average, StartOf&& start_of,
                          PointKernelResult<E>& cell, OnState&& on_state) {
  // At most 8 Gauss points a cell (hex8's rule; tri6 has 6).
  constexpr int max_points = 8;
  const int nq = E::quadrature_size();
  if (nq > max_points) return false;
  PointStencil<E> stencil[max_points];
  PointStartState start[max_points];
  for (int q = 0; q < nq; ++q) {
    const typename E::Local xi = E::quadrature_point(q);
    stencil[q] = make_stencil<E>(X, xi);
    const Eigen::Matrix<double, E::dim, E::dim> J = X.transpose() * E::shape_gradients(xi);
    start[q] = start_of(q);
    start[q].position.setZero();
    start[q].position.template head<E::dim>() = X.transpose() * stencil[q].N;
    start[q].volume =
        E::quadrature_weight(q) * J.determinant() * (axisymmetric ? start[q].position.x() : 1.0);
  }
  AveragedVolumeChange<E::nodes, E::dim> average;
  if (volume_average) {
    // Eq. 12.1 and 12.4 over the cell's Gauss points.
    double start_volume = 0.0, volume = 0.0, dJ = 1.0;
    Eigen::Matrix<double, 1, E::nodes * E::dim> divergence;
    average.divergence.setZero();
    for (int q = 0; q < nq; ++q) {
      if (!point_volume_change(stencil[q], start[q], du, axisymmetric, dJ, divergence))
        return false;
      start_volume += start[q].volume;
      volume += start[q].volume * dJ;
      average.divergence += (start[q].volume * dJ) * divergence;
    }
    average.ratio = volume / start_volume;
    average.divergence /= volume;
  }
  cell.internal_force.setZero();
  if (want_tangent) cell.stiffness.setZero();
  PointKernelResult<E> r;
  for (int q = 0; q < nq; ++q) {
    if (!integrate_point<E::nodes, E::dim>(stencil[q], start[q], du, axisymmetric, want_tangent, r,
                                           volume_average ? &average : nullptr))
      return false;
    cell.internal_force += r.internal_force;
    if (want_tangent) cell.stiffness += r.stiffness;
    on_state(q, r);
  }
  return true;
}

/// Adds a cell's internal force to `internal` and its stiffness to `tangent` (either may be null)
/// at the cell's unknowns `dofs` (node-major, E::nodes * E::dim of them); through `slots`
/// (dofs/sparsity.hpp, block_slots over `dofs`) where given, else by searching for each entry.
template <class E>
void scatter_cell(const PointKernelResult<E>& cell, const Index* dofs, const DofMap& map,
                  Vector* internal, SparseMatrix* tangent, const int* slots = nullptr) {
  constexpr int n = E::nodes * E::dim;
  if (internal)
    for (int i = 0; i < n; ++i) (*internal)(dofs[i]) += cell.internal_force(i);
  if (tangent && slots) {
    double* values = tangent->valuePtr();
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        if (slots[j * n + i] >= 0) values[slots[j * n + i]] += cell.stiffness(i, j);
    return;
  }
  if (tangent)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        if (cell.stiffness(i, j) != 0.0)
          add_to_tangent(*tangent, map, dofs[i], dofs[j], cell.stiffness(i, j));
}

}  // namespace geompm

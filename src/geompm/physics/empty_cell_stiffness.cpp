#include "geompm/physics/empty_cell_stiffness.hpp"

#include "geompm/core/tensor.hpp"
#include "geompm/mesh/cell_dispatch.hpp"
#include "geompm/mesh/cell_geometry.hpp"
#include "geompm/mesh/element.hpp"
#include "geompm/physics/point_kernel.hpp"

namespace geompm {

EmptyCellStiffness::EmptyCellStiffness(const GridSystem& grid, const DofMap& dofs,
                                       const PressureField* pressure)
    : grid_(grid),
      pressure_(pressure_field(dofs) >= 0 ? pressure : nullptr),
      m_(grid.nodes_per_cell() * (grid.dim() + (pressure_ ? 1 : 0))) {
  build();
}

void EmptyCellStiffness::build() {
  // A small linear elastic stiffness in empty and partly filled cells keeps the system regular
  // (seed §3.2). It is scaled by the empty fraction (1 - fill) of the cell, so full cells get
  // none and it fades in as a cell empties. Small strain on the grid of the step, nu = 0.3.
  // In a mixed system the pressure unknowns of empty space need the same: the pressure block a
  // full cell of the stiffest mixed soil would have (v N N^T / K, eq. 11.2), scaled by the
  // fraction of the cell not covered by mixed points (theory eq. 11.7). Like the displacement
  // part it acts on the change over the step, holding it as weakly as the soil's own
  // compressibility would.
  const int m = cell_unknowns();
  const Index n_active = static_cast<Index>(grid_.active_cells().size());
  // Stored only for the cells that get some (full cells are most of a body).
  offset_.assign(n_active, -1);
  std::size_t stored = 0;
  // In a distributed run each cell's term is added by the process that owns the cell.
  for (Index ci = 0; ci < n_active; ++ci)
    if ((displacement_weight(ci) > 0.0 || pressure_weight(ci) > 0.0) &&
        grid_.owns_cell(grid_.active_cells()[ci]))
      offset_[ci] = static_cast<std::int64_t>(stored++);
  stiffness_.assign(stored * m * m, 0.0);
  if (stored == 0) return;
  const double E_empty = grid_.settings().empty_cell_modulus, nu = 0.3;
  const Tensor4 C =
      isotropic_elasticity4(E_empty * nu / ((1 + nu) * (1 - 2 * nu)), E_empty / (2 * (1 + nu)));
  const double pressure_factor =
      pressure_ ? pressure_->scale() * pressure_->scale() / pressure_->reference_bulk() : 0.0;
  for_each_cell_typed(
      grid_.mesh(), n_active, [&](Index ci) { return grid_.active_cells()[ci]; },
      [&](auto e, Index ci) {
        // Full cells whose point volumes sum to a hair below the cell's get none (round-off).
        if (offset_[ci] >= 0) build_cell<decltype(e)>(ci, C, pressure_factor);
      },
      n_active > 256);
}

double EmptyCellStiffness::displacement_weight(Index ci) const {
  const double empty = 1.0 - grid_.cell_fill()[ci];
  return grid_.settings().empty_cell_modulus > 0.0 && empty > 1e-9 ? empty : 0.0;
}

double EmptyCellStiffness::pressure_weight(Index ci) const {
  const double empty = 1.0 - grid_.cell_mixed_fill()[ci];
  return pressure_ && empty > 1e-9 ? empty : 0.0;
}

template <class E>
void EmptyCellStiffness::build_cell(Index ci, const Tensor4& C, double pressure_factor) {
  constexpr int nen = E::nodes, dim = E::dim, n = nen * dim;
  using GC = GradientComponents<dim>;
  constexpr int nc = GC::count;
  const int m = nen * (dim + (pressure_ ? 1 : 0));  // this cell's unknowns
  Eigen::Matrix<double, nc, nc> A;
  for (int c = 0; c < nc; ++c)
    for (int d = 0; d < nc; ++d)
      A(c, d) = C(pair_index(GC::row[c], GC::col[c]), pair_index(GC::row[d], GC::col[d]));
  const bool axisymmetric = grid_.axisymmetric();
  const double w_u = displacement_weight(ci), w_p = pressure_weight(ci);
  {
    const Eigen::Matrix<double, E::nodes, E::dim> X =
        cell_node_coordinates<cell_type_of<E>>(grid_.mesh(), grid_.active_cells()[ci]).transpose();
    Eigen::Map<Eigen::MatrixXd> K(stiffness_.data() + std::size_t(offset_[ci]) * m_ * m_, m, m);
    for (int q = 0; q < E::quadrature_size(); ++q) {
      const auto xi = E::quadrature_point(q);
      const auto s = make_stencil<E>(X, xi);
      const Eigen::Matrix<double, dim, dim> J = X.transpose() * E::shape_gradients(xi);
      double dv = E::quadrature_weight(q) * std::abs(J.determinant());
      const double r = s.N.dot(X.col(0));
      if (axisymmetric) dv *= r;
      Eigen::Matrix<double, nc, n> B = Eigen::Matrix<double, nc, n>::Zero();
      for (int a = 0; a < nen; ++a)
        for (int c = 0; c < nc; ++c)
          if (GC::row[c] < dim && GC::col[c] < dim)
            B(c, a * dim + GC::row[c]) = s.dN_dX(a, GC::col[c]);
      if (axisymmetric)
        for (int a = 0; a < nen; ++a) B(nc - 1, a * dim) = s.N(a) / r;
      if (w_u > 0.0) K.topLeftCorner(n, n).noalias() += w_u * dv * (B.transpose() * A * B);
      if (w_p > 0.0)
        K.bottomRightCorner(m - n, m - n).noalias() +=
            (w_p * dv * pressure_factor) * (s.N * s.N.transpose());
    }
  }
}

}  // namespace geompm

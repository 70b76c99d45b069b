// The pressure projection of Dohrmann & Bochev (theory eq. 11.5) integrated exactly over a cell,
// per unit volume, for the floor that `numerics.pressure_stabilisation_floor` adds to the
// points' sum (theory §11, eq. 11.10).
//
// Eq. 11.5 is integrated at the cell's material points. After points cross cells they may
// cluster in a cell, and the point sum then hardly sees some pressure variations within it: an
// isolated node can move against its neighbours almost freely. The exact operator
//   P = (1/V) ∫_cell (N - m)(N - m)^T dV,   m = (1/V) ∫_cell N dV,
// has exactly the cell's constant pressures as its null space whatever the points do.
#pragma once

#include <Eigen/Core>

#include "geompm/mesh/element.hpp"

namespace geompm {

/// P of the reference cell of E (exact for affine cells, and for rectangles and boxes), by E's
/// quadrature rule, which is exact for the mass matrix.
template <class E>
const Eigen::Matrix<double, E::nodes, E::nodes>& exact_pressure_projection() {
  using Matrix = Eigen::Matrix<double, E::nodes, E::nodes>;
  static const Matrix projection = [] {
    Matrix mass = Matrix::Zero();
    typename E::Values mean = E::Values::Zero();
    double volume = 0.0;
    for (int q = 0; q < E::quadrature_size(); ++q) {
      const typename E::Values N = E::shape(E::quadrature_point(q));
      const double w = E::quadrature_weight(q);
      mass.noalias() += w * N * N.transpose();
      mean += w * N;
      volume += w;
    }
    mean /= volume;
    return Matrix(mass / volume - mean * mean.transpose());
  }();
  return projection;
}

}  // namespace geompm

// The Gauss points of one cell of the background mesh (coupling/fem_region.hpp).
#pragma once

#include <Eigen/LU>

#include "geompm/mesh/cell_geometry.hpp"
#include "geompm/mesh/element.hpp"

namespace geompm {

template <class F>
void for_each_gauss_point(const Mesh& mesh, Index c, bool axisymmetric, F&& f) {
  dispatch_cell_type(mesh.type_of(c), [&](auto element) {
    using E = decltype(element);
    constexpr CellType T = cell_type_of<E>;
    const NodeCoordinates<T> nodes = cell_node_coordinates<T>(mesh, c);
    for (int q = 0; q < E::quadrature_size(); ++q) {
      const typename E::Local xi = E::quadrature_point(q);
      Vec3 x = Vec3::Zero(), local = Vec3::Zero();
      x.head<E::dim>() = map_to_physical<T>(nodes, xi);
      local.head<E::dim>() = xi;
      double v = jacobian<T>(nodes, xi).determinant() * E::quadrature_weight(q);
      if (axisymmetric) v *= x.x();
      f(q, local, x, v);
    }
  });
}

}  // namespace geompm

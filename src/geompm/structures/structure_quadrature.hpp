// The Gauss points of a structure's mesh in its current configuration (docs/theory.md §17): each
// cell's own rule, with weights in the measure the structure's integrals use.
#pragma once

#include <Eigen/LU>

#include "geompm/mesh/cell_geometry.hpp"
#include "geompm/mesh/element.hpp"
#include "geompm/structures/structure_mesh.hpp"

namespace geompm {

// Calls f(c, q, x, w) for Gauss point q of every cell c: its position x and weight w = the rule's
// weight times det J (times r, per radian, in axisymmetry), in the mesh's current configuration.
template <class F>
inline void for_each_gauss_point(const StructureMesh& structure, F&& f) {
  const Mesh& mesh = structure.mesh();
  const bool radial = structure.kinematics() == Kinematics::Axisymmetric;
  dispatch_cell_type(mesh.cell_type, [&](auto element) {
    using E = decltype(element);
    constexpr CellType T = cell_type_of<E>;
    for (Index c = 0; c < mesh.num_cells(); ++c) {
      const NodeCoordinates<T> nodes = cell_node_coordinates<T>(mesh, c);
      for (int q = 0; q < E::quadrature_size(); ++q) {
        const typename E::Local xi = E::quadrature_point(q);
        Vec3 x = Vec3::Zero();
        x.head<E::dim>() = map_to_physical<T>(nodes, xi);
        double w = jacobian<T>(nodes, xi).determinant() * E::quadrature_weight(q);
        if (radial) w *= x.x();
        f(c, q, x, w);
      }
    }
  });
}

}  // namespace geompm

// Reference elements: shape functions N(xi) and their gradients dN/dxi on the reference cell,
// templated on the cell type so that hot loops have compile-time sizes (docs/architecture.md).
//
// Reference cells (node order follows Gmsh, so imported meshes need no renumbering):
//   Tri3, Tri6: (0,0) (1,0) (0,1) [+ mid-sides 0-1, 1-2, 2-0]
//   Quad4:      [-1,1]^2, counter-clockwise from (-1,-1)
//   Tet4:       (0,0,0) (1,0,0) (0,1,0) (0,0,1)
//   Hex8:       [-1,1]^3, bottom face counter-clockwise from (-1,-1,-1), then top face
//   Pyramid5:   base (-1,-1,0) (1,-1,0) (1,1,0) (-1,1,0), apex (0,0,1)
#pragma once

#include <Eigen/Core>

#include "geompm/mesh/cell_type.hpp"

namespace geompm {

template <CellType T>
struct Element;

#define GEOMPM_ELEMENT_COMMON(DIM, NODES)                                                        \
  static constexpr int dim = DIM;                                                                \
  static constexpr int nodes = NODES;                                                            \
  using Local = Eigen::Matrix<double, DIM, 1>;                                                   \
  using Values = Eigen::Matrix<double, NODES, 1>;                                                \
  using Gradients = Eigen::Matrix<double, NODES, DIM>; /* row a = dN_a/dxi */                    \
  static Values shape(const Local& xi);                                                          \
  static Gradients shape_gradients(const Local& xi);                                             \
  /* true if xi lies in the reference cell, within tol (in reference units) */                   \
  static bool contains(const Local& xi, double tol);                                             \
  static Local centroid();                                                                       \
  /* reference coordinates of node a, for tests and for seeding */                               \
  static Local node(int a);                                                                      \
  /* Gauss rule exact for the mass matrix of this cell (used in empty cells): points, weights */ \
  static int quadrature_size();                                                                  \
  static Local quadrature_point(int q);                                                          \
  static double quadrature_weight(int q);

template <>
struct Element<CellType::Tri3> {
  GEOMPM_ELEMENT_COMMON(2, 3)
};
template <>
struct Element<CellType::Tri6> {
  GEOMPM_ELEMENT_COMMON(2, 6)
};
template <>
struct Element<CellType::Quad4> {
  GEOMPM_ELEMENT_COMMON(2, 4)
};
template <>
struct Element<CellType::Tet4> {
  GEOMPM_ELEMENT_COMMON(3, 4)
};
template <>
struct Element<CellType::Hex8> {
  GEOMPM_ELEMENT_COMMON(3, 8)
};
template <>
struct Element<CellType::Pyramid5> {
  GEOMPM_ELEMENT_COMMON(3, 5)
};

#undef GEOMPM_ELEMENT_COMMON

/// Calls f(Element<T>{}) for the runtime cell type t: dispatch once per loop, not per point.
template <class F>
decltype(auto) dispatch_cell_type(CellType t, F&& f) {
  switch (t) {
    case CellType::Tri3:
      return f(Element<CellType::Tri3>{});
    case CellType::Tri6:
      return f(Element<CellType::Tri6>{});
    case CellType::Quad4:
      return f(Element<CellType::Quad4>{});
    case CellType::Tet4:
      return f(Element<CellType::Tet4>{});
    case CellType::Pyramid5:
      return f(Element<CellType::Pyramid5>{});
    case CellType::Hex8:
      break;
  }
  return f(Element<CellType::Hex8>{});
}

}  // namespace geompm

// Geometry of one cell of a mesh: the isoparametric map x(xi), its Jacobian, the inverse map
// (physical point -> reference coordinates), and measures. Every function dispatches on the
// cell type of the mesh; the templated versions are for hot loops.
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include <Eigen/LU>  // determinant, inverse

#include "geompm/mesh/element.hpp"
#include "geompm/mesh/mesh.hpp"

namespace geompm {

/// x(xi) = sum_a N_a(xi) x_a for cell c (xi has the cell's dimension; unused entries ignored).
Vec3 map_to_physical(const Mesh& mesh, Index c, const Vec3& xi);

/// Reference coordinates of the physical point x in cell c, by Newton on x(xi) = x (closed
/// form for the affine Tri3 and Tet4). nullopt if the iteration does not converge. The result
/// may lie outside the reference cell: check with cell_contains.
std::optional<Vec3> map_to_reference(const Mesh& mesh, Index c, const Vec3& x);

/// True if x lies in cell c (within a relative tolerance of the reference cell); fills xi.
bool cell_contains(const Mesh& mesh, Index c, const Vec3& x, Vec3& xi);

/// Area (2D) or volume (3D) of cell c; the integral of r dA (per radian) when `radial` is set.
double cell_measure(const Mesh& mesh, Index c, bool radial = false);

/// Smallest value of det(dx/dxi) over the cell's nodes and quadrature points, relative to the
/// cell's mean; <= 0 means an inverted or degenerate cell.
double cell_min_relative_jacobian(const Mesh& mesh, Index c);

/// Throws InputError (naming `source`, the first bad cell id and its node coordinates) if the
/// mesh is empty, has an inverted or degenerate cell, a node index out of range, or a
/// non-finite coordinate (also: a node off the plane z = 0 in 2D, a group id out of range).
void validate_mesh(const Mesh& mesh, const std::string& source);

/// Axis-aligned box (lower, upper corner) that encloses cell c. For a curved Tri6 it also
/// encloses the bulge of the edges, not only the nodes. In 2D the z extent is 0.
std::pair<Vec3, Vec3> cell_bounding_box(const Mesh& mesh, Index c);

// ---- Templated versions for hot loops: sizes known at compile time, no dispatch. ----

/// Tolerance of cell_contains in reference units: small enough to be geometrically exact, large
/// enough that a point on a face shared by two cells is found in (at least) one of them.
inline constexpr double reference_tolerance = 1e-10;

/// The CellType of an Element<T>, for code that receives the element from dispatch_cell_type.
template <class E>
struct CellTypeOf;  // defined for Element<T> only, so anything else fails to compile
template <CellType T>
struct CellTypeOf<Element<T>> {
  static constexpr CellType value = T;
};
template <class E>
inline constexpr CellType cell_type_of = CellTypeOf<E>::value;

/// Node coordinates of one cell, one column per node (only the cell's dimension is kept).
template <CellType T>
using NodeCoordinates = Eigen::Matrix<double, Element<T>::dim, Element<T>::nodes>;

/// The reference-to-physical Jacobian J(i, j) = dx_i / dxi_j.
template <CellType T>
using Jacobian = Eigen::Matrix<double, Element<T>::dim, Element<T>::dim>;

template <CellType T>
NodeCoordinates<T> cell_node_coordinates(const Mesh& mesh, Index c) {
  NodeCoordinates<T> coordinates;
  // A mesh of one type: the compile-time stride, as every cell has Element<T>::nodes.
  const Index* ids =
      mesh.connectivity.data() + (mesh.mixed() ? static_cast<std::size_t>(mesh.cell_offsets[c])
                                               : static_cast<std::size_t>(c) * Element<T>::nodes);
  for (int a = 0; a < Element<T>::nodes; ++a)
    coordinates.col(a) = mesh.nodes[ids[a]].template head<Element<T>::dim>();
  return coordinates;
}

template <CellType T>
typename Element<T>::Local map_to_physical(const NodeCoordinates<T>& nodes,
                                           const typename Element<T>::Local& xi) {
  return nodes * Element<T>::shape(xi);
}

template <CellType T>
Jacobian<T> jacobian(const NodeCoordinates<T>& nodes, const typename Element<T>::Local& xi) {
  return nodes * Element<T>::shape_gradients(xi);
}

/// Inverse of the isoparametric map of one cell; see map_to_reference above.
template <CellType T>
std::optional<typename Element<T>::Local> map_to_reference(const NodeCoordinates<T>& nodes,
                                                           const typename Element<T>::Local& x) {
  using Local = typename Element<T>::Local;
  if constexpr (T == CellType::Tri3 || T == CellType::Tet4) {
    // Affine simplex: x = x_0 + J xi with constant J, so xi = J^-1 (x - x_0).
    const Jacobian<T> J = nodes.template rightCols<Element<T>::dim>().colwise() - nodes.col(0);
    const double det = J.determinant();
    if (!(det != 0.0) || !std::isfinite(det)) return std::nullopt;
    return Local(J.inverse() * (x - nodes.col(0)));
  } else {
    // Newton from the centroid. It converges in one step for affine cells and in a few for
    // the usual distorted ones; a point far outside a distorted cell may have no preimage,
    // in which case xi runs away and we give up.
    constexpr int max_iterations = 30;
    constexpr double step_tolerance = 1e-12;  // reference units; convergence is quadratic
    constexpr double runaway = 1e3;
    Local xi = Element<T>::centroid();
    for (int iteration = 0; iteration < max_iterations; ++iteration) {
      const Local residual = map_to_physical<T>(nodes, xi) - x;
      const Jacobian<T> J = jacobian<T>(nodes, xi);
      const double det = J.determinant();
      if (!(det != 0.0) || !std::isfinite(det)) return std::nullopt;
      const Local step = J.inverse() * residual;
      xi -= step;
      if (!xi.allFinite() || xi.template lpNorm<Eigen::Infinity>() > runaway) return std::nullopt;
      if (step.template lpNorm<Eigen::Infinity>() < step_tolerance) return xi;
    }
    return std::nullopt;
  }
}

/// Encloses the cell: the nodes' box, widened for Tri6 by the Bezier control points of the
/// edges (a quadratic edge lies in the hull of its control points 2 m - (a + b) / 2).
template <CellType T>
std::pair<typename Element<T>::Local, typename Element<T>::Local> cell_bounding_box(
    const NodeCoordinates<T>& nodes) {
  using Local = typename Element<T>::Local;
  Local lower = nodes.rowwise().minCoeff(), upper = nodes.rowwise().maxCoeff();
  if constexpr (T == CellType::Tri6) {
    constexpr int edge_end[3][2] = {{0, 1}, {1, 2}, {2, 0}};
    for (int e = 0; e < 3; ++e) {
      const Local control =
          2.0 * nodes.col(3 + e) - 0.5 * (nodes.col(edge_end[e][0]) + nodes.col(edge_end[e][1]));
      lower = lower.cwiseMin(control);
      upper = upper.cwiseMax(control);
    }
  }
  return {lower, upper};
}

/// True if x lies in the cell (within reference_tolerance); fills xi.
template <CellType T>
bool cell_contains(const NodeCoordinates<T>& nodes, const typename Element<T>::Local& x,
                   typename Element<T>::Local& xi) {
  if constexpr (T != CellType::Tri3 && T != CellType::Tet4) {
    // Cheap rejection before Newton; the pad is far wider than reference_tolerance in
    // physical units, so it never rejects a point the reference test would accept.
    const auto [lower, upper] = cell_bounding_box<T>(nodes);
    const double pad = 1e-8 * (upper - lower).norm();
    if (((x - lower).array() < -pad).any() || ((x - upper).array() > pad).any()) return false;
  }
  const auto reference = map_to_reference<T>(nodes, x);
  if (!reference || !Element<T>::contains(*reference, reference_tolerance)) return false;
  xi = *reference;
  return true;
}

}  // namespace geompm

// Geometry of one cell of a mesh: the isoparametric map x(xi), its Jacobian, the inverse map
// (physical point -> reference coordinates), and measures. Every function dispatches on the
// cell type of the mesh; the templated versions are for hot loops.
#pragma once

#include <optional>

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
/// non-finite coordinate.
void validate_mesh(const Mesh& mesh, const std::string& source);

}  // namespace geompm

// The zero level set of the points' level set (seed §3.3; docs/theory.md §16.2) as facets: line
// segments in 2D, triangles in 3D, each inside one mesh cell, with its outward unit normal and a
// quadrature rule on it. It is the boundary surface loads are integrated on (seed §3.5) and that
// the output writes (boundary.pvd).
//
// Each cell is split into linear simplices in its reference coordinates, phi interpolated linearly
// on each (marching triangles and tetrahedra): tri3, tet4 as they are; tri6 into its four linear
// sub-triangles; quad4 into four triangles around its centre, hex8 into 24 tetrahedra (each face
// into four triangles around its centre, joined to the cell's centre). The centres take the cell's
// own interpolated phi (the mean of their nodes), so the split has no preferred diagonal, it is
// exact for a linear phi, and neighbouring cells cut their shared face alike: the facets join
// without gaps. A node belongs to the body if phi > 0, so a surface through nodes (on grid lines)
// is cut once, by the cell on the body's side.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "geompm/levelset/level_set.hpp"

namespace geompm {

/// A segment (2D: vertices 0, 1) or triangle (3D: 0, 1, 2) of the zero level set in one cell,
/// ordered so that its area vector is the outward normal: (x1 - x0) rotated clockwise in 2D,
/// (x1 - x0) x (x2 - x0) / 2 in 3D.
struct SurfaceFacet {
  Index cell = -1;             // mesh cell
  int vertices = 2;            // 2 or 3
  std::array<Vec3, 3> x;       // positions at the step's start
  std::array<Vec3, 3> xi;      // the same in the cell's reference coordinates
  Vec3 normal = Vec3::Zero();  // outward unit normal: -grad phi / |grad phi| on the facet
  /// Length (2D) or area (3D).
  double measure() const;
};

/// A quadrature point of a facet: its barycentric coordinates on the facet, its place and its
/// weight (length or area share; times the radius in axisymmetry, as loads are per radian).
struct FacetPoint {
  std::array<double, 3> lambda = {0, 0, 0};
  Vec3 x = Vec3::Zero();
  Vec3 xi = Vec3::Zero();
  double weight = 0.0;
};

/// Gauss rule of a facet: 2 points on a segment (exact to degree 3), 3 on a triangle (degree 2).
std::vector<FacetPoint> facet_quadrature(const SurfaceFacet& facet, bool axisymmetric);

/// An axis-aligned box, each side optional: where a surface load acts.
struct FacetBox {
  std::array<std::optional<std::array<double, 2>>, 3> range;  // [low, high] per axis
};

/// The zero level set of `phi` in the step's active cells whose nodes are all active, clipped to
/// `box` if given (exactly: a clipped triangle is split into triangles).
std::vector<SurfaceFacet> zero_level_set(const LevelSet& phi, const FacetBox* box = nullptr);

/// Moves the facets with a displacement of the grid's active nodes (`nodal`: dim per active node,
/// node-major): each vertex by its cell's shape functions; the normal becomes the moved facet's.
/// For output: the boundary of the step's start carried to its end.
void move_facets(std::vector<SurfaceFacet>& facets, const GridSystem& grid, const Vector& nodal);

/// As zero_level_set, from nodal values per mesh node (`node_phi`) on `mesh`: for tests and for
/// a level set given in closed form. `cells`: the cells to cut (all if empty).
std::vector<SurfaceFacet> zero_level_set(const Mesh& mesh, const std::vector<double>& node_phi,
                                         const std::vector<Index>& cells,
                                         const FacetBox* box = nullptr);

}  // namespace geompm

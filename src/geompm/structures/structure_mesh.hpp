// A structure's finite-element mesh (docs/theory.md §17): its nodes and cells (the background
// mesh's cell types: tri3, tri6, quad4 in 2D and axisymmetry, tet4, hex8 in 3D) and its boundary
// surface, the facets that no two cells share (segments in 2D, triangles and quadrilaterals in
// 3D), each with its outward unit normal. That surface is what contact sees of the structure; in
// axisymmetry the facets on the axis (x = 0) are left out of it, as the axis is no surface of the
// body of revolution.
#pragma once

#include <array>
#include <vector>

#include "geompm/core/types.hpp"
#include "geompm/mesh/mesh.hpp"

namespace geompm {

/// A facet of the boundary surface: its nodes (corners first, in an order that turns about the
/// outward normal in 3D; a tri6 edge's middle node last), the cell it bounds, its outward unit
/// normal and its size (length in 2D, area in 3D) in the current configuration.
struct Facet {
  std::array<Index, 4> nodes = {-1, -1, -1, -1};
  int corners = 0;    // 2 (segment), 3 (triangle), 4 (quadrilateral)
  int num_nodes = 0;  // corners, + 1 for a tri6 edge
  Index cell = -1;
  Vec3 normal = Vec3::Zero();
  double size = 0.0;
  /// The facet's centre (the mean of its corners).
  Vec3 centre(const std::vector<Vec3>& nodes) const;
};

class StructureMesh {
 public:
  StructureMesh() = default;
  /// The cells of `mesh` (2D in plane strain and axisymmetry, with x >= 0 in axisymmetry; 3D
  /// otherwise); finds the boundary surface. Throws std::invalid_argument for a mesh of the wrong
  /// dimension, or with nodes at x < 0 in axisymmetry.
  StructureMesh(Mesh mesh, Kinematics kinematics);

  const Mesh& mesh() const { return mesh_; }
  const std::vector<Vec3>& nodes() const { return mesh_.nodes; }
  Kinematics kinematics() const { return kinematics_; }
  int dim() const { return mesh_.dim(); }
  Index num_cells() const { return mesh_.num_cells(); }

  /// The contact surface: the boundary facets (in axisymmetry without those on the axis).
  const std::vector<Facet>& surface() const { return surface_; }
  /// Boundary facets on the axis (axisymmetry), not part of the surface.
  Index axis_facets() const { return axis_facets_; }

  /// Moves the nodes (same topology) and updates the facets' normals and sizes.
  void move_nodes(std::vector<Vec3> nodes);

  /// The body's area (plane strain: per unit thickness), volume (3D) or, in axisymmetry, volume
  /// per radian (the integral of r dA).
  double measure() const;
  /// The surface's length (plane strain: its area per unit thickness), area (3D) or, in
  /// axisymmetry, area per radian (the integral of r ds).
  double surface_measure() const;

 private:
  void update_facets();

  Mesh mesh_;
  Kinematics kinematics_ = Kinematics::PlaneStrain;
  std::vector<Facet> surface_;
  Index axis_facets_ = 0;
};

}  // namespace geompm

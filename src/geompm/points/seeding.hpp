// Seeding material points in a cell: the cell is split into equal sub-cells in reference
// coordinates and one point is placed at each sub-cell's centroid, carrying the sub-cell's
// volume (integrated exactly enough with a Gauss rule on the sub-cell, times the radius in
// axisymmetry, where volumes are per radian). Counts per cell type:
//   quad4: 1, 4, 9, 16 (k x k)          tri3, tri6: 1, 4, 9, 16 (k^2 sub-triangles), 3, 12
//   hex8: 1, 8, 27, 64 (k x k x k)                          (3 x 1 or 3 x 4: centroid splits)
//   tet4: 1, 4 (centroid split), 8 (mid-edge split)
#pragma once

#include <vector>

#include "geompm/mesh/mesh.hpp"

namespace geompm {

struct SeedPoint {
  Vec3 xi;        // reference coordinates in the cell
  Vec3 position;  // physical position
  double volume;  // per radian in axisymmetry
  /// The point's domain as GIMP sees it: half the sub-cell's extent along each axis, a box
  /// centred on the point (on triangles and tetrahedra, which GIMP does not take, the box of the
  /// sub-cell, which overlaps its neighbours').
  Vec3 half_size;
};

/// The allowed counts for a cell type (for messages and the model reader).
std::vector<int> allowed_points_per_cell(CellType type);
/// The count a body gets where it gives none: 2 x 2 in a quadrilateral (4, which triangles and
/// tetrahedra allow too), 2 x 2 x 2 in a hexahedron or pyramid (8; neither has a 4-point rule).
int default_points_per_cell(CellType type);

/// Seeds cell c with `count` points. Throws std::invalid_argument for a count the cell type
/// does not allow.
std::vector<SeedPoint> seed_cell(const Mesh& mesh, Index c, int count, bool axisymmetric);

}  // namespace geompm

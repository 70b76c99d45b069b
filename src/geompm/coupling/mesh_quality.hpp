// The shape of a mesh's cells (docs/theory.md §19.3), reported after each step of a model with an
// FEM region: the smallest interior angle of any cell (degrees; 90 for an undistorted rectangle,
// 60 for an equilateral triangle, 0 for a collapsed cell) and the largest aspect ratio (longest
// over shortest edge). In 3D the angles are those of the cells' faces.
#pragma once

#include <vector>

#include "geompm/mesh/mesh.hpp"

namespace geompm {

struct MeshQuality {
  double smallest_angle = 180.0;  // degrees
  double largest_aspect_ratio = 1.0;
};

/// The quality over the cells whose flag in `which` is set (every cell if `which` is empty).
MeshQuality mesh_quality(const Mesh& mesh, const std::vector<char>& which = {});

}  // namespace geompm

// Built-in generation of rectangle (2D) and box (3D) meshes with graded refinement: each axis is
// a list of segments, each with its own cell count and grading ratio (last cell size / first),
// so a mesh can be fine around a pile and coarse far from it.
//
// Named boundaries (node groups) of a generated mesh: 2D left/right (x min/max), bottom/top
// (y min/max); 3D left/right (x), front/back (y), bottom/top (z). A region "all" holds every cell.
#pragma once

#include <array>
#include <vector>

#include "geompm/mesh/mesh.hpp"

namespace geompm {

struct AxisSegment {
  double length = 1.0;
  int cells = 1;
  double ratio = 1.0;  // size of the last cell / size of the first cell in this segment
};

struct StructuredMeshSpec {
  CellType cell_type = CellType::Quad4;
  Vec3 origin = Vec3::Zero();
  std::array<std::vector<AxisSegment>, 3> axes;  // x, y (, z): only the first dim are used
};

/// Node coordinates along one axis, from `origin` (size = total cells + 1).
std::vector<double> axis_coordinates(double origin, const std::vector<AxisSegment>& segments);

/// Tri3/Tri6: each rectangle split in two triangles (alternating diagonals); Tet4: each hexahedron
/// split in six tetrahedra (conforming). Throws std::invalid_argument on bad sizes.
Mesh generate_structured_mesh(const StructuredMeshSpec& spec);

}  // namespace geompm

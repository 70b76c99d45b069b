// Built-in generation of rectangle (2D) and box (3D) meshes with graded refinement: each axis is
// a list of segments, each with its own cell count and grading ratio (last cell size / first),
// so a mesh can be fine around a pile and coarse far from it.
//
// Named boundaries (node groups) of a generated mesh: 2D left/right (x min/max), bottom/top
// (y min/max); 3D left/right (x), front/back (y), bottom/top (z). A region "all" holds every cell.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "geompm/mesh/mesh.hpp"

namespace geompm {

struct AxisSegment {
  double length = 1.0;
  int cells = 1;
  double ratio = 1.0;  // size of the last cell / size of the first cell in this segment
};

/// How a rectangle of a generated Tri3 mesh is split: in two triangles by one diagonal, the
/// diagonal alternating from rectangle to rectangle, or in four by both diagonals around a node
/// at its centre (the "crossed" or union-jack pattern). Both leave the linear triangles free of
/// volumetric locking (Nagtegaal, Parks & Rice 1974: of a union jack's constant-volume
/// constraints one is implied by the others; alternating diagonals make one of every 2 x 2
/// rectangles, crossed ones of every rectangle), so the displacement formulation carries nearly
/// incompressible and dilating plastic flow (docs/theory.md §15).
enum class Diagonals { Alternating, Crossed };

struct StructuredMeshSpec {
  CellType cell_type = CellType::Quad4;
  Diagonals diagonals = Diagonals::Alternating;  // Tri3 only
  Vec3 origin = Vec3::Zero();
  std::array<std::vector<AxisSegment>, 3> axes;  // x, y (, z): only the first dim are used
  /// 2D, quad4 or tri3 only: the type (quad4 or tri3) of the rectangle centred at a point, for a
  /// mesh of both (e.g. a quad4 MPM region over a tri3 FEM region, seed §3.4); they share their
  /// corner nodes, so the mesh is conforming. Empty: every rectangle is cell_type.
  std::function<CellType(const Vec3& centre)> cell_type_at;
};

/// Node coordinates along one axis, from `origin` (size = total cells + 1).
std::vector<double> axis_coordinates(double origin, const std::vector<AxisSegment>& segments);

/// Tri3/Tri6: each rectangle split in two triangles (alternating diagonals), or Tri3 in four
/// (crossed diagonals, a node at each rectangle's centre, numbered after the grid's nodes); Tet4:
/// each hexahedron split in six tetrahedra (conforming). Throws std::invalid_argument on bad
/// sizes, and on crossed diagonals for another cell type.
Mesh generate_structured_mesh(const StructuredMeshSpec& spec);

}  // namespace geompm

// The distance from a point to a structure's body (docs/user-guide.md, "regions": cells within or
// beyond a distance of a structure): zero inside it, else the distance to the nearest point of
// its boundary surface (segments in 2D, triangles and quadrilaterals in 3D).
#pragma once

#include "geompm/mesh/point_locator.hpp"
#include "geompm/structures/structure_mesh.hpp"

namespace geompm {

class StructureDistance {
 public:
  /// `mesh` must outlive this object.
  explicit StructureDistance(const StructureMesh& mesh);
  double operator()(const Vec3& x) const;

 private:
  const StructureMesh& mesh_;
  PointLocator inside_;
};

/// The distance from x to the segment ab.
double distance_to_segment(const Vec3& x, const Vec3& a, const Vec3& b);
/// The distance from x to the triangle abc (its closest point: Ericson 2005, §5.1.5).
double distance_to_triangle(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace geompm

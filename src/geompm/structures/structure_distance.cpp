#include "geompm/structures/structure_distance.hpp"

#include <algorithm>
#include <limits>

namespace geompm {

double distance_to_segment(const Vec3& x, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((x - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (x - (a + t * ab)).norm();
}

double distance_to_triangle(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c) {
  // The closest point is inside the triangle (its projection, where all three barycentric
  // coordinates are non-negative) or on one of its edges.
  const Vec3 ab = b - a, ac = c - a, ax = x - a;
  const double d00 = ab.dot(ab), d01 = ab.dot(ac), d11 = ac.dot(ac);
  const double d20 = ax.dot(ab), d21 = ax.dot(ac);
  const double det = d00 * d11 - d01 * d01;
  if (det > 0.0) {
    const double v = (d11 * d20 - d01 * d21) / det, w = (d00 * d21 - d01 * d20) / det;
    if (v >= 0.0 && w >= 0.0 && v + w <= 1.0) return (x - (a + v * ab + w * ac)).norm();
  }
  return std::min(
      {distance_to_segment(x, a, b), distance_to_segment(x, b, c), distance_to_segment(x, c, a)});
}

StructureDistance::StructureDistance(const StructureMesh& mesh)
    : mesh_(mesh), inside_(mesh.mesh()) {}

double StructureDistance::operator()(const Vec3& x) const {
  if (inside_.locate(x)) return 0.0;
  const auto& nodes = mesh_.nodes();
  double nearest = std::numeric_limits<double>::infinity();
  for (const Facet& facet : mesh_.surface()) {
    const auto corner = [&](int k) { return nodes[facet.nodes[k]]; };
    double d = 0.0;
    if (facet.corners == 2)
      d = distance_to_segment(x, corner(0), corner(1));
    else
      d = distance_to_triangle(x, corner(0), corner(1), corner(2));
    if (facet.corners == 4)
      d = std::min(d, distance_to_triangle(x, corner(0), corner(2), corner(3)));
    nearest = std::min(nearest, d);
  }
  return nearest;
}

}  // namespace geompm

#include "geompm/coupling/mesh_quality.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "geompm/mesh/cell_faces.hpp"

namespace geompm {
namespace {

// The corner polygons of a cell type's faces (the cell itself in 2D), as local nodes in order.
const std::vector<std::vector<int>>& corner_polygons(CellType type) {
  using Polygons = std::vector<std::vector<int>>;
  static const Polygons triangle = {{0, 1, 2}};
  static const Polygons quadrangle = {{0, 1, 2, 3}};
  if (cell_dimension(type) == 3) return cell_corner_faces(type);
  return type == CellType::Quad4 ? quadrangle : triangle;
}

}  // namespace

MeshQuality mesh_quality(const Mesh& mesh, const std::vector<char>& which) {
  MeshQuality quality;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    if (!which.empty() && !which[c]) continue;
    const auto& polygons = corner_polygons(mesh.type_of(c));
    const auto nodes = mesh.cell_nodes(c);
    double shortest = std::numeric_limits<double>::max(), longest = 0.0;
    for (const auto& polygon : polygons) {
      const int n = static_cast<int>(polygon.size());
      for (int k = 0; k < n; ++k) {
        const Vec3& prev = mesh.nodes[nodes[polygon[(k + n - 1) % n]]];
        const Vec3& here = mesh.nodes[nodes[polygon[k]]];
        const Vec3& next = mesh.nodes[nodes[polygon[(k + 1) % n]]];
        const Vec3 a = prev - here, b = next - here;
        const double length = b.norm();
        shortest = std::min(shortest, length);
        longest = std::max(longest, length);
        const double angle = std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / std::numbers::pi;
        quality.smallest_angle = std::min(quality.smallest_angle, angle);
      }
    }
    if (shortest > 0.0)
      quality.largest_aspect_ratio = std::max(quality.largest_aspect_ratio, longest / shortest);
  }
  return quality;
}

}  // namespace geompm

#include "geompm/structures/cross_section.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

namespace geompm {

namespace {

// The corner edges of a cell (corners numbered as in mesh/element.hpp).
std::vector<std::array<int, 2>> corner_edges(CellType type) {
  switch (type) {
    case CellType::Tri3:
    case CellType::Tri6:
      return {{0, 1}, {1, 2}, {2, 0}};
    case CellType::Quad4:
      return {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
    case CellType::Tet4:
      return {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
    case CellType::Pyramid5:
      return {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 4}, {2, 4}, {3, 4}};
    case CellType::Hex8:
      break;
  }
  return {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
          {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
}

// The measure of the convex cut of a cell through the points where its edges cross the plane: in
// 2D the distance between the two farthest, in 3D the area of the polygon they span (ordered by
// angle about their mean).
double cut_measure(std::vector<Vec3> x, const Vec3& n, int dim) {
  if (x.size() < 2) return 0.0;
  if (dim == 2) {
    double longest = 0.0;
    for (const Vec3& a : x)
      for (const Vec3& b : x) longest = std::max(longest, (a - b).norm());
    return longest;
  }
  if (x.size() < 3) return 0.0;
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : x) mean += p;
  mean /= static_cast<double>(x.size());
  const Vec3 e1 = (x.front() - mean).normalized(), e2 = n.cross(e1);
  std::sort(x.begin(), x.end(), [&](const Vec3& a, const Vec3& b) {
    return std::atan2((a - mean).dot(e2), (a - mean).dot(e1)) <
           std::atan2((b - mean).dot(e2), (b - mean).dot(e1));
  });
  double area = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k)
    area += 0.5 * (x[k] - mean).cross(x[(k + 1) % x.size()] - mean).dot(n);
  return std::abs(area);
}

}  // namespace

SectionStress section_stress(const DeformableStructure& structure, const Vec3& point,
                             const Vec3& normal) {
  const Vec3 n = normal.normalized();
  const Mesh& mesh = structure.mesh().mesh();
  const std::vector<Mat3> stress = structure.cell_stress();
  const auto edges = corner_edges(mesh.cell_type);
  const bool radial = structure.kinematics() == Kinematics::Axisymmetric;
  SectionStress out;
  double sum = 0.0;
  std::vector<Vec3> cut;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const auto nodes = mesh.cell_nodes(c);
    cut.clear();
    for (const auto& [i, j] : edges) {
      const Vec3 &a = mesh.nodes[nodes[i]], &b = mesh.nodes[nodes[j]];
      const double da = n.dot(a - point), db = n.dot(b - point);
      // A corner on the plane belongs to the cells on its negative side only, so that a section
      // along cell faces is counted once.
      if ((da >= 0) == (db >= 0)) continue;
      cut.push_back(a + (b - a) * (da / (da - db)));
    }
    double measure = cut_measure(cut, n, structure.dim());
    if (!(measure > 0)) continue;
    if (radial) {
      Vec3 mean = Vec3::Zero();
      for (const Vec3& p : cut) mean += p;
      measure *= mean.x() / static_cast<double>(cut.size());  // integral of r ds, r linear
    }
    sum += measure * n.dot(stress[c] * n);
    out.measure += measure;
  }
  out.mean_normal_stress =
      out.measure > 0 ? sum / out.measure : std::numeric_limits<double>::quiet_NaN();
  return out;
}

}  // namespace geompm

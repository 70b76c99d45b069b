#include "geompm/structures/structure_mesh.hpp"

#include <fmt/format.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <map>
#include <stdexcept>

#include "geompm/mesh/cell_faces.hpp"
#include "geompm/mesh/cell_geometry.hpp"

namespace geompm {

namespace {

// The faces of each cell type as local nodes: corners, then a tri6 edge's middle node (the
// node order of element.hpp, which is Gmsh's).
struct LocalFace {
  int corners;
  int nodes;
  std::array<int, 4> local;
};

std::vector<LocalFace> local_faces(CellType type) {
  if (type == CellType::Tri6) return {{2, 3, {0, 1, 3}}, {2, 3, {1, 2, 4}}, {2, 3, {2, 0, 5}}};
  std::vector<LocalFace> faces;
  for (const std::vector<int>& corners : cell_corner_faces(type)) {
    LocalFace face{static_cast<int>(corners.size()), static_cast<int>(corners.size()), {}};
    std::copy(corners.begin(), corners.end(), face.local.begin());
    faces.push_back(face);
  }
  return faces;
}

// The facet's normal times its size, from its ordered corners: in 2D the segment a -> b turned
// clockwise (outward for a counter-clockwise boundary), in 3D the cross product of the
// triangle's edges or of the quadrilateral's diagonals (twice its area for a planar one).
Vec3 scaled_normal(const Facet& f, const std::vector<Vec3>& x) {
  const Vec3& a = x[f.nodes[0]];
  const Vec3& b = x[f.nodes[1]];
  if (f.corners == 2) return Vec3(b.y() - a.y(), a.x() - b.x(), 0.0);
  if (f.corners == 3) return 0.5 * (b - a).cross(x[f.nodes[2]] - a);
  return 0.5 * (x[f.nodes[2]] - a).cross(x[f.nodes[3]] - b);
}

Vec3 cell_centre(const Mesh& mesh, Index c) {
  Vec3 sum = Vec3::Zero();
  const int corners = mesh.cell_type == CellType::Tri6 ? 3 : mesh.nodes_per_cell();
  const auto nodes = mesh.cell_nodes(c);
  for (int a = 0; a < corners; ++a) sum += mesh.nodes[nodes[a]];
  return sum / corners;
}

}  // namespace

Vec3 Facet::centre(const std::vector<Vec3>& x) const {
  Vec3 sum = Vec3::Zero();
  for (int a = 0; a < corners; ++a) sum += x[nodes[a]];
  return sum / corners;
}

StructureMesh::StructureMesh(Mesh mesh, Kinematics kinematics)
    : mesh_(std::move(mesh)), kinematics_(kinematics) {
  if (mesh_.dim() != spatial_dimension(kinematics))
    throw std::invalid_argument(fmt::format(
        "a structure of {} cells in a {} model: expected {}D cells", to_string(mesh_.cell_type),
        to_string(kinematics), spatial_dimension(kinematics)));
  // A structure's cells are integrated and located as one type (structure_quadrature.hpp).
  if (mesh_.mixed())
    throw std::invalid_argument(
        fmt::format("a structure's mesh mixes cell types ({}); expected cells of one type",
                    cell_type_names(mesh_)));
  Vec3 lower = mesh_.nodes.front(), upper = lower;
  for (const Vec3& x : mesh_.nodes) lower = lower.cwiseMin(x), upper = upper.cwiseMax(x);
  const double tolerance = 1e-9 * (upper - lower).norm();
  const bool axisymmetric = kinematics == Kinematics::Axisymmetric;
  if (axisymmetric && lower.x() < -tolerance)
    throw std::invalid_argument(fmt::format(
        "a structure in an axisymmetric model is its half-section at x >= 0 (x is the radius); "
        "found a node at x = {:g}",
        lower.x()));

  // A face is on the boundary if no other cell has it: count the faces by their sorted corners.
  const std::vector<LocalFace> faces = local_faces(mesh_.cell_type);
  std::map<std::array<Index, 4>, std::pair<int, Facet>> seen;
  for (Index c = 0; c < mesh_.num_cells(); ++c) {
    const auto nodes = mesh_.cell_nodes(c);
    for (const LocalFace& face : faces) {
      Facet f;
      f.corners = face.corners;
      f.num_nodes = face.nodes;
      f.cell = c;
      for (int a = 0; a < face.nodes; ++a) f.nodes[a] = nodes[face.local[a]];
      // The key: the corners in ascending order (an insertion sort of at most four).
      std::array<Index, 4> key = {-1, -1, -1, -1};
      for (int a = 0; a < face.corners; ++a) {
        int b = a;
        for (; b > 0 && key[b - 1] > f.nodes[a]; --b) key[b] = key[b - 1];
        key[b] = f.nodes[a];
      }
      auto [it, inserted] = seen.try_emplace(key, 0, f);
      ++it->second.first;
    }
  }
  for (auto& [key, entry] : seen) {
    auto& [count, f] = entry;
    if (count != 1) continue;
    // Outward: away from the centre of the cell it bounds (cells are convex); reversing the
    // corners turns the normal.
    if (scaled_normal(f, mesh_.nodes).dot(f.centre(mesh_.nodes) - cell_centre(mesh_, f.cell)) < 0)
      std::reverse(f.nodes.begin(), f.nodes.begin() + f.corners);
    if (axisymmetric && std::abs(mesh_.nodes[f.nodes[0]].x()) <= tolerance &&
        std::abs(mesh_.nodes[f.nodes[1]].x()) <= tolerance) {
      ++axis_facets_;
      continue;
    }
    surface_.push_back(f);
  }
  // In the order of the cells, so that the surface does not depend on the map's key order.
  std::stable_sort(surface_.begin(), surface_.end(),
                   [](const Facet& a, const Facet& b) { return a.cell < b.cell; });
  update_facets();
}

void StructureMesh::update_facets() {
  for (Facet& f : surface_) {
    const Vec3 n = scaled_normal(f, mesh_.nodes);
    f.size = n.norm();
    f.normal = n / f.size;
  }
}

void StructureMesh::move_nodes(std::vector<Vec3> nodes) {
  if (nodes.size() != mesh_.nodes.size())
    throw std::invalid_argument("StructureMesh::move_nodes: another number of nodes");
  mesh_.nodes = std::move(nodes);
  update_facets();
}

double StructureMesh::measure() const {
  double sum = 0.0;
  const bool radial = kinematics_ == Kinematics::Axisymmetric;
  for (Index c = 0; c < mesh_.num_cells(); ++c) sum += cell_measure(mesh_, c, radial);
  return sum;
}

double StructureMesh::surface_measure() const {
  double sum = 0.0;
  for (const Facet& f : surface_) {
    // In axisymmetry the integral of r ds over a straight segment: its length times the mean
    // radius of its ends.
    const double r = kinematics_ == Kinematics::Axisymmetric
                         ? 0.5 * (mesh_.nodes[f.nodes[0]].x() + mesh_.nodes[f.nodes[1]].x())
                         : 1.0;
    sum += f.size * r;
  }
  return sum;
}

}  // namespace geompm

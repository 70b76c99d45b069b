#include "geompm/physics/ghost_penalty.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>  // cross

#include "geompm/mesh/cell_geometry.hpp"
#include "geompm/mesh/element.hpp"

namespace geompm {
namespace {

/// A quadrature point of a face: its place, weight (length or area element) and unit normal.
struct FacePoint {
  Vec3 x;
  double weight;
  Vec3 normal;
};

/// Gauss rule on the face with corners `corners` (2D: a segment; 3D: a triangle or a quadrangle
/// in cyclic order), exact for the squared jump of linear cells' gradients: constant on
/// simplices, linear along a quadrangle's segment, bilinear on a hexahedron's face.
std::vector<FacePoint> face_quadrature(std::vector<Vec3> corners, int dim) {
  const double g = 1.0 / std::sqrt(3.0);
  std::vector<FacePoint> points;
  if (dim == 2) {
    const Vec3 edge = corners[1] - corners[0];
    const double length = edge.norm();
    const Vec3 normal = Vec3(-edge.y(), edge.x(), 0.0) / length;
    for (double t : {-g, g})
      points.push_back({0.5 * (corners[0] + corners[1]) + 0.5 * t * edge, 0.5 * length, normal});
    return points;
  }
  if (corners.size() == 3) {
    const Vec3 area = (corners[1] - corners[0]).cross(corners[2] - corners[0]);
    points.push_back(
        {(corners[0] + corners[1] + corners[2]) / 3.0, 0.5 * area.norm(), area.normalized()});
    return points;
  }
  // A hexahedron's face: its four shared nodes in cyclic order about their centre, then the
  // bilinear map over [-1, 1]^2.
  const Vec3 centre = 0.25 * (corners[0] + corners[1] + corners[2] + corners[3]);
  // Any three corners of a quadrangle span its plane, whatever their order.
  const Vec3 normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]).normalized();
  const Vec3 axis = (corners[0] - centre).normalized();
  const Vec3 other = normal.cross(axis);
  std::sort(corners.begin(), corners.end(), [&](const Vec3& a, const Vec3& b) {
    return std::atan2((a - centre).dot(other), (a - centre).dot(axis)) <
           std::atan2((b - centre).dot(other), (b - centre).dot(axis));
  });
  // One normal for the face, from its diagonals: exact for a flat face, the mean one of a warped.
  const Vec3 face_normal = (corners[2] - corners[0]).cross(corners[3] - corners[1]).normalized();
  for (double s : {-g, g})
    for (double t : {-g, g}) {
      const double N[4] = {0.25 * (1 - s) * (1 - t), 0.25 * (1 + s) * (1 - t),
                           0.25 * (1 + s) * (1 + t), 0.25 * (1 - s) * (1 + t)};
      Vec3 x = Vec3::Zero();
      for (int a = 0; a < 4; ++a) x += N[a] * corners[a];
      const Vec3 x_s =
          0.25 * ((1 - t) * (corners[1] - corners[0]) + (1 + t) * (corners[2] - corners[3]));
      const Vec3 x_t =
          0.25 * ((1 - s) * (corners[3] - corners[0]) + (1 + s) * (corners[2] - corners[1]));
      points.push_back({x, x_s.cross(x_t).norm(), face_normal});
    }
  return points;
}

/// n . grad N_a at x in cell c, per node of the cell.
template <class E>
Eigen::Matrix<double, E::nodes, 1> normal_derivatives(const Mesh& mesh, Index c, const Vec3& x,
                                                      const Vec3& normal) {
  constexpr CellType T = cell_type_of<E>;
  const NodeCoordinates<T> X = cell_node_coordinates<T>(mesh, c);
  const auto xi = map_to_reference<T>(X, x.head<E::dim>());
  if (!xi)  // cannot happen for a valid cell: the face point lies on its boundary
    throw std::runtime_error("ghost penalty: a point of a face of cell " + std::to_string(c) +
                             " has no reference coordinates in it");
  const typename E::Gradients dN_dxi = E::shape_gradients(*xi);
  const Jacobian<T> J = X * dN_dxi;
  return dN_dxi * J.inverse() * normal.head<E::dim>();
}

template <class E>
std::vector<NodeBlock> faces_typed(const Mesh& mesh, const MeshTopology& topology,
                                   const std::vector<Index>& active_cells,
                                   const std::vector<Index>& node_to_active,
                                   const GhostPenaltyCells& cells,
                                   const GhostPenaltySettings& settings) {
  constexpr int nen = E::nodes, dim = E::dim;
  std::vector<Index> active_of(mesh.num_cells(), -1);
  std::vector<char> holds_points(mesh.num_cells(), 0);
  for (std::size_t ci = 0; ci < active_cells.size(); ++ci) {
    active_of[active_cells[ci]] = static_cast<Index>(ci);
    holds_points[active_cells[ci]] = cells.fill[ci] > 0.0;
  }
  // Edge cells: occupied, sharing a node with a cell of the mesh that holds no point (active or
  // not, so that it works without buffer cells too), and filled at most to the limit. A node on
  // the mesh's boundary has no cell beyond it: a body filling the mesh has no edge there.
  std::vector<char> edge(active_cells.size(), 0);
  for (std::size_t ci = 0; ci < active_cells.size(); ++ci) {
    if (!(cells.fill[ci] > 0.0) || cells.fill[ci] > settings.fill_limit) continue;
    for (Index nb : topology.cell_neighbours.row(active_cells[ci]))
      if (!holds_points[nb]) edge[ci] = 1;
  }
  std::vector<NodeBlock> faces;
  for (std::size_t ci = 0; ci < active_cells.size(); ++ci) {
    if (!(cells.fill[ci] > 0.0)) continue;
    const Index a = active_cells[ci];
    for (Index b : topology.cell_neighbours.row(a)) {
      const Index cj = active_of[b];
      if (b <= a || cj < 0 || !(cells.fill[cj] > 0.0) || !(edge[ci] || edge[cj])) continue;
      const auto nodes_a = mesh.cell_nodes(a), nodes_b = mesh.cell_nodes(b);
      std::vector<Vec3> corners;
      for (Index node : nodes_a)
        if (std::find(nodes_b.begin(), nodes_b.end(), node) != nodes_b.end())
          corners.push_back(mesh.nodes[node]);
      // A face shares an edge's two nodes (2D), a triangle's three or a quadrangle's four (3D:
      // tet4, hex8, pyramid5); fewer are a corner or an edge only.
      if (static_cast<int>(corners.size()) < dim) continue;

      NodeBlock face;
      for (Index node : nodes_a) face.nodes.push_back(node_to_active[node]);
      for (Index node : nodes_b) face.nodes.push_back(node_to_active[node]);
      std::sort(face.nodes.begin(), face.nodes.end());
      face.nodes.erase(std::unique(face.nodes.begin(), face.nodes.end()), face.nodes.end());
      const auto at = [&](Index node) {
        return std::lower_bound(face.nodes.begin(), face.nodes.end(), node_to_active[node]) -
               face.nodes.begin();
      };
      const Index size = static_cast<Index>(face.nodes.size());
      face.weight = Eigen::MatrixXd::Zero(size, size);
      const double h =
          std::pow(0.5 * (cell_measure(mesh, a, false) + cell_measure(mesh, b, false)), 1.0 / dim);
      const double scale = settings.gamma * std::min(cells.modulus[ci], cells.modulus[cj]) * h;
      Eigen::VectorXd jump(size);
      for (const FacePoint& q : face_quadrature(corners, dim)) {
        // [grad N . n] over both cells' nodes: a node of both (on the face) takes the difference.
        const auto g_a = normal_derivatives<E>(mesh, a, q.x, q.normal);
        const auto g_b = normal_derivatives<E>(mesh, b, q.x, q.normal);
        jump.setZero();
        for (int k = 0; k < nen; ++k) {
          jump(at(nodes_a[k])) += g_a(k);
          jump(at(nodes_b[k])) -= g_b(k);
        }
        const double w = scale * q.weight * (settings.radial ? q.x.x() : 1.0);
        face.weight.noalias() += w * jump * jump.transpose();
      }
      faces.push_back(std::move(face));
    }
  }
  return faces;
}

}  // namespace

std::vector<NodeBlock> ghost_penalty_faces(const Mesh& mesh, const MeshTopology& topology,
                                           const std::vector<Index>& active_cells,
                                           const std::vector<Index>& node_to_active,
                                           const GhostPenaltyCells& cells,
                                           const GhostPenaltySettings& settings) {
  if (mesh.cell_type == CellType::Tri6)
    throw std::invalid_argument(
        "numerics.ghost_penalty: needs linear cells (tri3, quad4, tet4, hex8, pyramid5); the jump "
        "of a "
        "quadratic cell's second derivative is not penalised");
  if (mesh.mixed())
    throw std::invalid_argument(
        "numerics.ghost_penalty: needs a mesh of one cell type, but the mesh mixes cell types "
        "(its faces between a triangle and a quadrilateral are not penalised); set "
        "ghost_penalty: 0 or use one cell type");
  return dispatch_cell_type(mesh.cell_type, [&](auto e) {
    using E = decltype(e);
    if constexpr (E::nodes == 6) {  // refused above; not compiled for Tri6
      return std::vector<NodeBlock>{};
    } else {
      return faces_typed<E>(mesh, topology, active_cells, node_to_active, cells, settings);
    }
  });
}

std::vector<NodeBlock> ghost_penalty_blocks(const GridSystem& grid, const MaterialPoints& points) {
  if (grid.settings().ghost_penalty <= 0.0) return {};
  const Index n_active = static_cast<Index>(grid.active_cells().size());
  std::vector<double> modulus(n_active, 0.0);
  for (Index ci = 0; ci < n_active; ++ci)
    for (Index p = grid.cell_point_begin(ci); p < grid.cell_point_end(ci); ++p) {
      // The point's own Young's modulus E = 9 K G / (3 K + G): it varies in space where s_u does.
      const ElasticModuli m =
          grid.materials()[points.material[p]]->elastic_moduli(points.internal[p]);
      const double E =
          3.0 * m.bulk + m.shear > 0.0 ? 9.0 * m.bulk * m.shear / (3.0 * m.bulk + m.shear) : 0.0;
      modulus[ci] = std::max(modulus[ci], E);
    }
  // A cell's points are on the process that owns it: every process gets its modulus (and adds
  // the same faces; process 0 assembles them, as it does every term of no point).
  grid.communicator().max(modulus.data(), modulus.size());
  return ghost_penalty_faces(
      grid.mesh(), grid.topology(), grid.active_cells(), grid.node_to_active(),
      {modulus, grid.cell_fill()},
      {grid.settings().ghost_penalty, grid.settings().ghost_penalty_fill, grid.axisymmetric()});
}

}  // namespace geompm

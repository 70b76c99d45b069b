#include "geompm/levelset/level_set.hpp"

#include "geompm/mesh/cell_dispatch.hpp"
#include "geompm/mesh/cell_geometry.hpp"
#include "geompm/mesh/element.hpp"

namespace geompm {
namespace {

/// V_I of eq. 16.1 per active node: the integral of N_I over every mesh cell around the node
/// (active or not), in the plane (in axisymmetry: of the meridian plane, as the points' weights
/// are taken). The element's Gauss rule is exact for the mass matrix, so for N_I too. The same
/// integral over the FEM cells around the node is added to `filled`: an FEM cell is soil
/// throughout (docs/theory.md §19), though it holds no material points, so the nodes an FEM region
/// shares with the MPM region are inside the soil, not on a boundary between them.
std::vector<double> support_measure(const GridSystem& grid, std::vector<double>& filled) {
  const Mesh& mesh = grid.mesh();
  const auto& active = grid.active_nodes();
  const auto& node_to_active = grid.node_to_active();
  std::vector<char> around(mesh.num_cells(), 0);
  for (Index node : active)
    for (Index c : grid.topology().node_cells.row(node)) around[c] = 1;
  std::vector<double> measure(active.size(), 0.0);
  for_each_mesh_cell_typed(mesh, [&](auto e, Index c) {
    using E = decltype(e);
    constexpr CellType T = cell_type_of<E>;
    if (!around[c]) return;
    const NodeCoordinates<T> X = cell_node_coordinates<T>(mesh, c);
    const auto nodes = mesh.cell_nodes(c);
    for (int q = 0; q < E::quadrature_size(); ++q) {
      const typename E::Local xi = E::quadrature_point(q);
      const double w = E::quadrature_weight(q) * jacobian<T>(X, xi).determinant();
      const typename E::Values N = E::shape(xi);
      for (int a = 0; a < E::nodes; ++a) {
        const Index node = node_to_active[nodes[a]];
        if (node < 0) continue;
        measure[node] += w * N(a);
        if (grid.fem_cell(c)) filled[node] += w * N(a);
      }
    }
  });
  return measure;
}

}  // namespace

LevelSet::LevelSet(const GridSystem& grid, const MaterialPoints& points, std::vector<char> bodies)
    : grid_(grid) {
  const std::size_t n_nodes = grid.active_nodes().size();
  // Per node the volume the points map, sum_p N_I V_p = m_I / rho_I (eq. 16.1; the header says
  // why rho_I is the volume-weighted density). In axisymmetry a point's volume is per radian:
  // divided by its radius it is per unit area of the meridian plane, as V_I is.
  std::vector<double> filled(n_nodes, 0.0);
  for (Index p = 0; p < points.size(); ++p) {
    const Index b = points.body[p];
    if (!bodies.empty() && (b >= Index(bodies.size()) || !bodies[b])) continue;
    const double r = points.position[p](0);
    const double per = !grid.axisymmetric() ? 1.0 : (r > 0.0 ? 1.0 / r : 0.0);
    const double V = points.volume[p] * per;
    grid.for_each_weight(points, p, [&](Index node, double N) { filled[node] += N * V; });
  }
  // A node between processes is filled by the points of every process's cells around it.
  grid.communicator().sum(filled);
  const std::vector<double> support = support_measure(grid, filled);
  phi_.assign(n_nodes, outside);
  for (std::size_t a = 0; a < n_nodes; ++a)
    if (support[a] > 0.0) phi_[a] = filled[a] / support[a] - 0.5;
}

double LevelSet::node_value(Index node) const {
  const Index a = grid_.node_to_active()[node];
  return a >= 0 ? phi_[a] : outside;
}

double LevelSet::value(Index cell, const Vec3& xi) const {
  return dispatch_cell_type(grid_.mesh().type_of(cell), [&](auto e) {
    using E = decltype(e);
    const typename E::Values N = E::shape(xi.head<E::dim>());
    const auto nodes = grid_.mesh().cell_nodes(cell);
    double phi = 0.0;
    for (int a = 0; a < E::nodes; ++a) phi += N(a) * node_value(nodes[a]);
    return phi;
  });
}

Vec3 LevelSet::gradient(Index cell, const Vec3& xi) const {
  return dispatch_cell_type(grid_.mesh().type_of(cell), [&](auto e) {
    using E = decltype(e);
    constexpr CellType T = cell_type_of<E>;
    const typename E::Local local = xi.head<E::dim>();
    const NodeCoordinates<T> X = cell_node_coordinates<T>(grid_.mesh(), cell);
    // dN/dx = dN/dxi J^-1 on the mesh of the step's start.
    const typename E::Gradients dN_dx = E::shape_gradients(local) * jacobian<T>(X, local).inverse();
    const auto nodes = grid_.mesh().cell_nodes(cell);
    Vec3 g = Vec3::Zero();
    for (int a = 0; a < E::nodes; ++a)
      g.head<E::dim>() += node_value(nodes[a]) * dN_dx.row(a).transpose();
    return g;
  });
}

}  // namespace geompm

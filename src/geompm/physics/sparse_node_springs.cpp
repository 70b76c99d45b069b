#include "geompm/physics/sparse_node_springs.hpp"

#include <cmath>

#include "geompm/mesh/cell_geometry.hpp"
#include "geompm/mesh/element.hpp"

namespace geompm {
namespace {

std::vector<NodeBlock> springs_of_sparse_nodes(const GridSystem& grid,
                                               const MaterialPoints& points) {
  // A node whose support the points barely reach (a soil point at the far corner of its support,
  // the rest emptied, as beside a footing's edge) is held only by the empty-cell stiffness of its
  // cells: Newton's corrections move it by as much as the step's increment, and a contact or a
  // return nearby turns them back (docs/validation.md §7). Eq. 6.2: its support fill
  // s_a = sum_p N_a(x_p) v_p / sum_c |c| / nen (the points' volume it sees against the volume its
  // shape function covers) below s_min gives it a spring E_s (1 - s_a / s_min) |c| / (nen h_c^2)
  // from each of its cells, on the step's displacement like the empty-cell stiffness: one
  // diagonal block per such node, summed over its cells once a step.
  std::vector<NodeBlock> springs;
  const int dim = grid.dim();
  const Index n_nodes = static_cast<Index>(grid.active_nodes().size());
  const bool radial = grid.axisymmetric();
  const Mesh& mesh = grid.mesh();
  std::vector<double> seen(n_nodes, 0.0), covered(n_nodes, 0.0), spring_share(n_nodes, 0.0);
  for (Index ci = 0; ci < static_cast<Index>(grid.active_cells().size()); ++ci) {
    const Index c = grid.active_cells()[ci];
    const auto nodes = mesh.cell_nodes(c);
    const int nen = static_cast<int>(nodes.size());  // a mixed mesh's cells differ
    const double share = cell_measure(mesh, c, radial) / nen;
    const double spring = share / std::pow(cell_measure(mesh, c, false), 2.0 / dim);
    for (int a = 0; a < nen; ++a) {
      const Index na = grid.node_to_active()[nodes[a]];
      covered[na] += share;
      spring_share[na] += spring;
      if (grid.fem_cell(c)) seen[na] += share;  // an FEM cell's Gauss points fill it
      for (Index p = grid.cell_point_begin(ci); p < grid.cell_point_end(ci); ++p)
        seen[na] += grid.cell_shape(p)[a] * points.volume[p];
    }
  }
  // A node between processes sees the points of every process's cells around it.
  grid.communicator().sum(seen);
  const double fill_min = grid.settings().sparse_node_fill;
  for (Index na = 0; na < n_nodes; ++na) {
    const double fill = covered[na] > 0.0 ? seen[na] / covered[na] : 1.0;
    if (fill < fill_min)
      springs.push_back(
          {{na},
           Eigen::MatrixXd::Constant(
               1, 1,
               grid.settings().sparse_node_modulus * (1.0 - fill / fill_min) * spring_share[na])});
  }
  return springs;
}

}  // namespace

std::vector<NodeBlock> sparse_node_springs(const GridSystem& grid, const MaterialPoints& points) {
  if (grid.settings().sparse_node_modulus <= 0.0) return {};
  return springs_of_sparse_nodes(grid, points);
}

}  // namespace geompm

#include "geompm/coupling/fem_region.hpp"

#include "geompm/mesh/element.hpp"

namespace geompm {

FemRegion::FemRegion(const Mesh& mesh, const std::vector<CellKind>& kinds)
    : kinds_(kinds),
      fem_cell_(mesh.num_cells(), 0),
      fem_node_(mesh.num_nodes(), 0),
      initial_nodes_(mesh.nodes) {
  points_per_cell_ =
      dispatch_cell_type(mesh.cell_type, [](auto e) { return decltype(e)::quadrature_size(); });
  for (Index c = 0; c < mesh.num_cells(); ++c)
    if (kinds[c] == CellKind::Fem) {
      cells_.push_back(c);
      fem_cell_[c] = 1;
      for (Index a : mesh.cell_nodes(c)) fem_node_[a] = 1;
    }
}

}  // namespace geompm

#include "geompm/coupling/fem_region.hpp"

#include "geompm/mesh/element.hpp"

namespace geompm {

FemRegion::FemRegion(const Mesh& mesh, const std::vector<CellKind>& kinds)
    : kinds_(kinds),
      fem_cell_(mesh.num_cells(), 0),
      fem_node_(mesh.num_nodes(), 0),
      initial_nodes_(mesh.nodes) {
  gauss_start_.assign(1, 0);
  for (Index c = 0; c < mesh.num_cells(); ++c)
    if (kinds[c] == CellKind::Fem) {
      cells_.push_back(c);
      gauss_start_.push_back(gauss_start_.back() + dispatch_cell_type(mesh.type_of(c), [](auto e) {
                               return static_cast<Index>(decltype(e)::quadrature_size());
                             }));
      fem_cell_[c] = 1;
      for (Index a : mesh.cell_nodes(c)) fem_node_[a] = 1;
    }
  own_.assign(cells_.size(), 1);
}

void FemRegion::keep_own(const std::vector<int>& cell_part, int rank) {
  for (std::size_t k = 0; k < cells_.size(); ++k) own_[k] = cell_part[cells_[k]] == rank;
}

std::vector<Index> FemRegion::own_gauss_points() const {
  std::vector<Index> own;
  for (std::size_t k = 0; k < cells_.size(); ++k)
    if (own_[k])
      for (Index g = gauss_start_[k]; g < gauss_start_[k + 1]; ++g) own.push_back(g);
  return own;
}

}  // namespace geompm

// The background mesh: nodes, cells of one type, and named groups of cells (regions) and of
// nodes (boundaries), as generated or imported from Gmsh physical groups.
#pragma once

#include <map>
#include <span>
#include <string>
#include <vector>

#include "geompm/core/types.hpp"
#include "geompm/mesh/cell_type.hpp"

namespace geompm {

struct Mesh {
  CellType cell_type = CellType::Quad4;
  std::vector<Vec3> nodes;          // z = 0 in 2D
  std::vector<Index> connectivity;  // nodes_per_cell(cell_type) entries per cell
  std::map<std::string, std::vector<Index>> cell_groups;  // region name -> cell ids (sorted)
  std::map<std::string, std::vector<Index>> node_groups;  // boundary name -> node ids (sorted)

  int dim() const { return cell_dimension(cell_type); }
  int nodes_per_cell() const { return geompm::nodes_per_cell(cell_type); }
  Index num_nodes() const { return static_cast<Index>(nodes.size()); }
  Index num_cells() const { return static_cast<Index>(connectivity.size() / nodes_per_cell()); }
  std::span<const Index> cell_nodes(Index c) const {
    const int n = nodes_per_cell();
    return {connectivity.data() + static_cast<std::size_t>(c) * n, static_cast<std::size_t>(n)};
  }
};

}  // namespace geompm

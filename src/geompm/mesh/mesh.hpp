// The background mesh: nodes, cells, and named groups of cells (regions) and of nodes
// (boundaries), as generated or imported from Gmsh physical groups.
//
// Cells are of one type (`cell_type`, connectivity of fixed stride: the fast path every kernel
// takes) or of several of one dimension, e.g. a quad4 MPM region over a tri3 FEM region (seed
// §3.4): a mixed mesh keeps each cell's type in `cell_types` and where its nodes start in
// `cell_offsets`. Code that runs per cell asks type_of(c) and cell_nodes(c); kernels templated on
// the cell type dispatch once per loop on a uniform mesh and per cell on a mixed one
// (mesh/cell_dispatch.hpp).
#pragma once

#include <map>
#include <span>
#include <string>
#include <vector>

#include "geompm/core/types.hpp"
#include "geompm/mesh/cell_type.hpp"

namespace geompm {

struct Mesh {
  /// The type of every cell of a uniform mesh; of a mixed one, the type of its first cell.
  CellType cell_type = CellType::Quad4;
  std::vector<Vec3> nodes;          // z = 0 in 2D
  std::vector<Index> connectivity;  // the cells' nodes, cell after cell
  /// Mixed meshes only (both empty for a uniform mesh): the type of each cell, and where each
  /// cell's nodes start in the connectivity (num_cells() + 1 entries).
  std::vector<CellType> cell_types;
  std::vector<Index> cell_offsets;
  std::map<std::string, std::vector<Index>> cell_groups;  // region name -> cell ids (sorted)
  std::map<std::string, std::vector<Index>> node_groups;  // boundary name -> node ids (sorted)

  bool mixed() const { return !cell_types.empty(); }
  int dim() const { return cell_dimension(cell_type); }
  CellType type_of(Index c) const { return mixed() ? cell_types[c] : cell_type; }
  /// Nodes of a cell of a uniform mesh; the most any cell has in a mixed one.
  int nodes_per_cell() const;
  int nodes_of(Index c) const {
    return mixed() ? static_cast<int>(cell_offsets[c + 1] - cell_offsets[c]) : nodes_per_cell();
  }
  Index num_nodes() const { return static_cast<Index>(nodes.size()); }
  Index num_cells() const {
    return mixed() ? static_cast<Index>(cell_types.size())
                   : static_cast<Index>(connectivity.size() / nodes_per_cell());
  }
  std::span<const Index> cell_nodes(Index c) const {
    if (mixed())
      return {connectivity.data() + cell_offsets[c],
              static_cast<std::size_t>(cell_offsets[c + 1] - cell_offsets[c])};
    const int n = geompm::nodes_per_cell(cell_type);
    return {connectivity.data() + static_cast<std::size_t>(c) * n, static_cast<std::size_t>(n)};
  }
  /// The cell types present, in CellType order.
  std::vector<CellType> types_present() const;
  /// Appends a cell; a cell of another type than the ones before makes the mesh mixed.
  void add_cell(CellType type, std::span<const Index> cell);
  /// Back to the uniform layout if every cell has one type (import builds cells one by one).
  void compact();
};

/// The mesh's cell types for messages: "quad4", or "tri3 + quad4" for a mixed mesh.
std::string cell_type_names(const Mesh& mesh);

}  // namespace geompm

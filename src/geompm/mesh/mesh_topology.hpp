// Which cells touch each node, and which cells share a node with each cell (compressed rows).
// Built once per mesh; used to find the buffer layer around occupied cells and to colour cells
// for lock-free parallel assembly.
#pragma once

#include <span>
#include <vector>

#include "geompm/mesh/mesh.hpp"

namespace geompm {

struct CompressedRows {
  std::vector<Index> start{0};  // row r spans [start[r], start[r+1])
  std::vector<Index> entries;
  std::span<const Index> row(Index r) const {
    return {entries.data() + start[r], static_cast<std::size_t>(start[r + 1] - start[r])};
  }
};

struct MeshTopology {
  CompressedRows node_cells;       // node -> cells containing it
  CompressedRows cell_neighbours;  // cell -> other cells sharing at least one node
};

MeshTopology build_mesh_topology(const Mesh& mesh);

}  // namespace geompm

// The background mesh cut into one part per process of a distributed run (docs/architecture.md,
// "Distributed runs"): a cell is owned by one process, a node by the lowest-ranked owner of its
// cells, and a process sees, besides its own cells, a layer of ghost cells around them.
//
// The cut is a recursive coordinate bisection of the cells' centroids, weighted by the work in
// each cell (its material points): each cut halves the parts along the longest extent of the
// cells left, where the weight on either side is in proportion to the parts it gets. It is
// computed the same on every process from the replicated mesh, needs no communication, and does
// not depend on the order the points arrive in.
#pragma once

#include <vector>

#include "geompm/mesh/mesh.hpp"
#include "geompm/mesh/mesh_topology.hpp"

namespace geompm {

/// Per cell, the part (0 .. parts-1) that owns it. `weights` per cell (the points in it, say);
/// a cell of weight 0 still counts a little, so that empty cells are shared out too.
std::vector<int> partition_cells(const Mesh& mesh, const std::vector<double>& weights, int parts);

/// Per node, the lowest part among the owners of the cells that hold it.
std::vector<int> node_owners(const Mesh& mesh, const std::vector<int>& cell_part);

/// The cells within `layers` layers of part `part`'s own cells (sharing a node, layer by layer)
/// that it does not own, ascending: its ghost cells. One layer covers a point's cell and the
/// GIMP domain of a point in it, which reaches at most half a cell into the neighbours.
std::vector<Index> ghost_cells(const MeshTopology& topology, const std::vector<int>& cell_part,
                               int part, int layers);

}  // namespace geompm

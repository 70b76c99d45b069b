#include "geompm/mesh/mesh_topology.hpp"

#include <algorithm>

namespace geompm {

MeshTopology build_mesh_topology(const Mesh& mesh) {
  MeshTopology t;
  const Index n_nodes = mesh.num_nodes(), n_cells = mesh.num_cells();
  std::vector<Index> count(n_nodes + 1, 0);
  for (Index node : mesh.connectivity) ++count[node + 1];
  for (Index i = 0; i < n_nodes; ++i) count[i + 1] += count[i];
  t.node_cells.start = count;
  t.node_cells.entries.resize(mesh.connectivity.size());
  std::vector<Index> fill(count.begin(), count.end() - 1);
  for (Index c = 0; c < n_cells; ++c)
    for (Index node : mesh.cell_nodes(c)) t.node_cells.entries[fill[node]++] = c;

  t.cell_neighbours.start.assign(1, 0);
  std::vector<Index> scratch;
  for (Index c = 0; c < n_cells; ++c) {
    scratch.clear();
    for (Index node : mesh.cell_nodes(c))
      for (Index other : t.node_cells.row(node))
        if (other != c) scratch.push_back(other);
    std::sort(scratch.begin(), scratch.end());
    scratch.erase(std::unique(scratch.begin(), scratch.end()), scratch.end());
    t.cell_neighbours.entries.insert(t.cell_neighbours.entries.end(), scratch.begin(),
                                     scratch.end());
    t.cell_neighbours.start.push_back(static_cast<Index>(t.cell_neighbours.entries.size()));
  }
  return t;
}

}  // namespace geompm

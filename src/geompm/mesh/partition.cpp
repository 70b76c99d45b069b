#include "geompm/mesh/partition.hpp"

#include <algorithm>
#include <numeric>

namespace geompm {

namespace {

// The weight an empty cell counts for, against one point's 1: enough to share a mesh without
// points out evenly, too little to move a cut in a body.
constexpr double empty_cell_weight = 1e-3;

struct Bisection {
  const std::vector<Vec3>& centroid;
  const std::vector<double>& weight;
  std::vector<int>& part;

  // Cells [begin, end) of `cells` go to parts first .. first + parts - 1.
  void cut(std::vector<Index>& cells, std::size_t begin, std::size_t end, int first, int parts) {
    if (parts == 1 || end - begin <= 1) {
      for (std::size_t k = begin; k < end; ++k) part[cells[k]] = first;
      return;
    }
    Vec3 low = Vec3::Constant(1e300), high = Vec3::Constant(-1e300);
    for (std::size_t k = begin; k < end; ++k) {
      low = low.cwiseMin(centroid[cells[k]]);
      high = high.cwiseMax(centroid[cells[k]]);
    }
    int axis = 0;
    (high - low).maxCoeff(&axis);
    // Ties broken by the cell's number: the same cut on every process.
    std::sort(cells.begin() + begin, cells.begin() + end, [&](Index a, Index b) {
      const double xa = centroid[a](axis), xb = centroid[b](axis);
      return xa < xb || (xa == xb && a < b);
    });
    const int lower_parts = parts / 2;
    double total = 0.0;
    for (std::size_t k = begin; k < end; ++k) total += weight[cells[k]];
    const double target = total * lower_parts / parts;
    std::size_t split = begin;
    for (double below = 0.0; split < end - 1 && below + 0.5 * weight[cells[split]] < target;)
      below += weight[cells[split++]];
    split = std::clamp(split, begin + 1, end - 1);
    cut(cells, begin, split, first, lower_parts);
    cut(cells, split, end, first + lower_parts, parts - lower_parts);
  }
};

}  // namespace

std::vector<int> partition_cells(const Mesh& mesh, const std::vector<double>& weights, int parts) {
  const Index n = mesh.num_cells();
  std::vector<Vec3> centroid(n, Vec3::Zero());
  std::vector<double> weight(n, empty_cell_weight);
  for (Index c = 0; c < n; ++c) {
    const auto nodes = mesh.cell_nodes(c);
    for (Index node : nodes) centroid[c] += mesh.nodes[node];
    centroid[c] /= static_cast<double>(nodes.size());
    if (c < static_cast<Index>(weights.size())) weight[c] += weights[c];
  }
  std::vector<int> part(n, 0);
  std::vector<Index> cells(n);
  std::iota(cells.begin(), cells.end(), 0);
  Bisection{centroid, weight, part}.cut(cells, 0, cells.size(), 0, std::max(1, parts));
  return part;
}

std::vector<int> node_owners(const Mesh& mesh, const std::vector<int>& cell_part) {
  std::vector<int> owner(mesh.num_nodes(), -1);
  for (Index c = 0; c < mesh.num_cells(); ++c)
    for (Index node : mesh.cell_nodes(c))
      if (owner[node] < 0 || cell_part[c] < owner[node]) owner[node] = cell_part[c];
  return owner;
}

std::vector<Index> ghost_cells(const MeshTopology& topology, const std::vector<int>& cell_part,
                               int part, int layers) {
  const Index n = static_cast<Index>(cell_part.size());
  std::vector<char> seen(n, 0);
  std::vector<Index> frontier;
  for (Index c = 0; c < n; ++c)
    if (cell_part[c] == part) {
      seen[c] = 1;
      frontier.push_back(c);
    }
  std::vector<Index> ghosts;
  for (int layer = 0; layer < layers; ++layer) {
    std::vector<Index> next;
    for (Index c : frontier)
      for (Index nb : topology.cell_neighbours.row(c))
        if (!seen[nb]) {
          seen[nb] = 1;
          next.push_back(nb);
          ghosts.push_back(nb);
        }
    frontier.swap(next);
  }
  std::sort(ghosts.begin(), ghosts.end());
  return ghosts;
}

}  // namespace geompm

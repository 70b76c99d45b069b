#include "geompm/physics/pressure_start_fit.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>

namespace geompm {

void fit_pressure_start(const Mesh& mesh, std::span<const Index> active_cells,
                        std::span<const Index> active_nodes, std::span<const Index> node_to_active,
                        std::span<const double> last, std::span<const char> fit,
                        Eigen::VectorXd& start) {
  const int dim = mesh.dim();
  const Index n_active = static_cast<Index>(active_nodes.size());
  // Each active node's patch: the mesh nodes of the active cells it belongs to.
  std::vector<std::vector<Index>> patch(n_active);
  for (Index c : active_cells) {
    const auto nodes = mesh.cell_nodes(c);
    for (Index a : nodes) {
      auto& list = patch[node_to_active[a]];
      list.insert(list.end(), nodes.begin(), nodes.end());
    }
  }
  Eigen::MatrixXd A;
  Eigen::VectorXd b;
  for (Index a = 0; a < n_active; ++a) {
    const Index node = active_nodes[a];
    if (!fit[a] || !std::isfinite(last[node])) continue;
    auto& nodes = patch[a];
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    // p(x) = c0 + g . (x - x_a) by least squares over the patch: c0 is the fitted value at a.
    A.resize(Index(nodes.size()), dim + 1);
    b.resize(Index(nodes.size()));
    Index rows = 0;
    for (Index other : nodes) {
      if (!std::isfinite(last[other])) continue;
      A(rows, 0) = 1.0;
      for (int i = 0; i < dim; ++i) A(rows, 1 + i) = mesh.nodes[other](i) - mesh.nodes[node](i);
      b(rows++) = last[other];
    }
    start(a) = last[node];
    if (rows <= dim + 1) continue;
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A.topRows(rows));
    if (qr.rank() == dim + 1) start(a) = qr.solve(b.head(rows))(0);
  }
}

}  // namespace geompm

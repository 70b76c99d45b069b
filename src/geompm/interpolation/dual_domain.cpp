#include "geompm/interpolation/dual_domain.hpp"

#include <algorithm>
#include <stdexcept>

#include "geompm/core/byte_archive.hpp"
#include "geompm/mesh/element.hpp"

namespace geompm {
namespace {

// A bubble over the reference cell: 1 at the centre, 0 on the cell boundary (DDMP blending).
double cell_bubble(CellType type, const Vec3& xi) {
  switch (type) {
    case CellType::Tri3:
    case CellType::Tri6:
      return 27.0 * xi(0) * xi(1) * (1.0 - xi(0) - xi(1));
    case CellType::Quad4:
      return (1.0 - xi(0) * xi(0)) * (1.0 - xi(1) * xi(1));
    case CellType::Tet4:
      return 256.0 * xi(0) * xi(1) * xi(2) * (1.0 - xi(0) - xi(1) - xi(2));
    case CellType::Hex8:
      return (1.0 - xi(0) * xi(0)) * (1.0 - xi(1) * xi(1)) * (1.0 - xi(2) * xi(2));
    case CellType::Pyramid5: {
      // The product of the five faces' equations, 1 at its largest, (0, 0, 1/5) on the axis.
      const double s = 1.0 - xi(2);
      return 3125.0 / 256.0 * xi(2) * (s * s - xi(0) * xi(0)) * (s * s - xi(1) * xi(1));
    }
  }
  return 0.0;
}

// A distributed run: each process has summed eq. 8.1 over its own points; every process gets
// the sums over all of them (a node between processes sees the points of both sides), added in
// rank order so that the bits are the same on every process.
template <int Dim>
void share_node_sums(const Communicator& processes, std::vector<double>& weight,
                     std::vector<std::vector<std::pair<Index, Eigen::Matrix<double, Dim, 1>>>>& G) {
  processes.sum(weight);
  ByteWriter mine;
  for (std::size_t j = 0; j < G.size(); ++j)
    for (const auto& [i, g] : G[j]) {
      mine.put(static_cast<Index>(j));
      mine.put(i);
      mine.put(g);
    }
  for (auto& row : G) row.clear();
  for (const std::string& part : processes.all_gather(mine.take())) {
    ByteReader in(part, "DDMP node sums of another process");
    while (in.remaining() > 0) {
      const auto j = in.get<Index>();
      const auto i = in.get<Index>();
      const auto g = in.get<Eigen::Matrix<double, Dim, 1>>();
      auto& row = G[j];
      auto it = std::find_if(row.begin(), row.end(), [&](const auto& e) { return e.first == i; });
      if (it == row.end())
        row.emplace_back(i, g);
      else
        it->second += g;
    }
  }
}

template <class E>
void build(const MaterialPoints& points, const StencilInputs& in, WideStencils& out) {
  // Node-averaged gradients (Zhang, Ma & Giguere 2011, J. Comput. Phys. 230): for node j,
  //   G_ij = sum_q v_q N_j(x_q) grad N_i(x_q) / sum_q v_q N_j(x_q)      (theory eq. 8.1)
  // over the points q around j, and at a point p the gradient of N_i becomes
  //   grad~ N_i(x_p) = alpha grad N_i(x_p) + (1 - alpha) sum_j N_j(x_p) G_ij   (theory eq. 8.2)
  // with alpha a bubble of the cell (1 at its centre, 0 on its boundary): the cell's own gradient
  // keeps the smoothed field free of zero-energy (checkerboard) modes, and vanishes where a
  // point crosses into the next cell, so the point's forces change continuously. Exact for
  // linear fields.
  constexpr int nen = E::nodes, dim = E::dim;
  using Gradient = Eigen::Matrix<double, dim, 1>;
  const Index n_points = points.size();
  const Index n_nodes = in.active_nodes;
  std::vector<double> weight(n_nodes, 0.0);
  std::vector<std::vector<std::pair<Index, Gradient>>> G(n_nodes);
  for (Index q = 0; q < n_points; ++q) {
    const auto nodes = in.mesh.cell_nodes(points.cell[q]);
    const double* N = in.shape.data() + std::size_t(q) * nen;
    const Eigen::Map<const Eigen::Matrix<double, nen, dim>> dN(in.gradients.data() +
                                                               std::size_t(q) * nen * dim);
    for (int a = 0; a < nen; ++a) {
      const Index j = in.node_to_active[nodes[a]];
      const double w = points.volume[q] * N[a];
      weight[j] += w;
      auto& row = G[j];
      for (int b = 0; b < nen; ++b) {
        const Index i = in.node_to_active[nodes[b]];
        auto it = std::find_if(row.begin(), row.end(), [&](const auto& e) { return e.first == i; });
        if (it == row.end())
          row.emplace_back(i, w * dN.row(b).transpose());
        else
          it->second += w * dN.row(b).transpose();
      }
    }
  }

  if (in.processes.distributed()) share_node_sums<dim>(in.processes, weight, G);

  out.clear(n_points);
  std::vector<std::pair<Index, Gradient>> entries;
  for (Index p = 0; p < n_points; ++p) {
    const auto nodes = in.mesh.cell_nodes(points.cell[p]);
    const double* N = in.shape.data() + std::size_t(p) * nen;
    const Eigen::Map<const Eigen::Matrix<double, nen, dim>> dN(in.gradients.data() +
                                                               std::size_t(p) * nen * dim);
    entries.clear();
    const double alpha = std::clamp(cell_bubble(in.mesh.cell_type, points.local[p]), 0.0, 1.0);
    auto add = [&](Index i, const Gradient& g) {
      auto it =
          std::find_if(entries.begin(), entries.end(), [&](const auto& e) { return e.first == i; });
      if (it == entries.end())
        entries.emplace_back(i, g);
      else
        it->second += g;
    };
    for (int a = 0; a < nen; ++a) {
      const Index j = in.node_to_active[nodes[a]];
      if (weight[j] > 0.0) {
        for (const auto& [i, g] : G[j]) add(i, ((1.0 - alpha) * N[a] / weight[j]) * g);
      } else {
        // No point weighs on node j: its share falls back to the point's own gradient.
        for (int b = 0; b < nen; ++b)
          add(in.node_to_active[nodes[b]], (1.0 - alpha) * N[a] * dN.row(b).transpose());
      }
    }
    for (int b = 0; b < nen; ++b) add(in.node_to_active[nodes[b]], alpha * dN.row(b).transpose());
    std::sort(entries.begin(), entries.end(),
              [](const auto& x, const auto& y) { return x.first < y.first; });
    for (const auto& [i, g] : entries) {
      out.nodes.push_back(i);
      double value = 0.0;
      for (int a = 0; a < nen; ++a)
        if (in.node_to_active[nodes[a]] == i) value = N[a];
      out.N.push_back(value);
      for (int d = 0; d < dim; ++d) out.gradients.push_back(g(d));
    }
    out.start[p + 1] = static_cast<Index>(out.nodes.size());
  }
}

}  // namespace

void DualDomainInterpolation::after_activation(const MaterialPoints& points,
                                               const StencilInputs& in, WideStencils& out) const {
  // The smoothed gradients are built per cell type (the model refuses ddmp on a mixed mesh).
  if (in.mesh.mixed())
    throw std::invalid_argument("ddmp: needs a mesh of one cell type; use standard interpolation");
  dispatch_cell_type(in.mesh.cell_type, [&](auto e) { build<decltype(e)>(points, in, out); });
}

}  // namespace geompm

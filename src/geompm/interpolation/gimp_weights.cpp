#include "geompm/interpolation/gimp_weights.hpp"

#include <algorithm>
#include <numeric>

namespace geompm {

double clip_half_length(double centre, double half, double lo, double hi) {
  // Symmetric: the domain keeps its centre at the point, so the weights still reproduce linear
  // fields exactly (sum S_i x_i = x_p) and mapping, convect and the point's position agree.
  return std::max(0.0, std::min({half, centre - lo, hi - centre}));
}

void gimp_axis_weights(const std::vector<double>& lines, double centre, double half, int cell,
                       AxisWeights& out) {
  const int last_cell = static_cast<int>(lines.size()) - 2;
  const double a = centre - half, b = centre + half;
  out.S.clear();
  out.G.clear();
  cell = std::clamp(cell, 0, last_cell);
  const double h_cell = lines[cell + 1] - lines[cell];
  if (!(b - a > 1e-12 * h_cell)) {
    // Zero-length domain: the standard hat functions of the cell holding the point.
    const double t = std::clamp((centre - lines[cell]) / h_cell, 0.0, 1.0);
    out.first = cell;
    out.S = {1.0 - t, t};
    out.G = {-1.0 / h_cell, 1.0 / h_cell};
    return;
  }
  // Cells k0..k1 overlap (a, b).
  const int k0 = std::clamp(
      static_cast<int>(std::upper_bound(lines.begin(), lines.end(), a) - lines.begin()) - 1, 0,
      last_cell);
  const int k1 = std::clamp(
      static_cast<int>(std::lower_bound(lines.begin(), lines.end(), b) - lines.begin()) - 1, k0,
      last_cell);
  out.first = k0;
  out.S.assign(k1 - k0 + 2, 0.0);
  out.G.assign(k1 - k0 + 2, 0.0);
  // Eq. 9.2-9.3: on each overlap I_k = (c, d) of the domain with cell k the hat functions are
  // linear, so their integral is |I_k| times their value at the midpoint m, and their derivative
  // is -1/h_k (left node), +1/h_k (right node). Overlaps below 1e-12 of the domain (a domain
  // edge on a grid line up to round-off) are dropped, and the sum divided by the length kept,
  // so the weights still sum to 1 exactly and no node gets a round-off weight.
  double kept = 0.0;
  for (int k = k0; k <= k1; ++k) {
    const double c = std::max(a, lines[k]), d = std::min(b, lines[k + 1]);
    if (d - c <= 1e-12 * (b - a)) continue;
    const double h = lines[k + 1] - lines[k];
    const double t = (0.5 * (c + d) - lines[k]) / h;
    const double w = d - c;
    out.S[k - k0] += w * (1.0 - t);
    out.S[k - k0 + 1] += w * t;
    out.G[k - k0] -= w / h;
    out.G[k - k0 + 1] += w / h;
    kept += w;
  }
  for (std::size_t i = 0; i < out.S.size(); ++i) {
    out.S[i] /= kept;
    out.G[i] /= kept;
  }
  // Trim nodes left without a weight by dropped overlaps.
  std::size_t begin = 0, end = out.S.size();
  while (begin < end && out.S[begin] == 0.0 && out.G[begin] == 0.0) ++begin;
  while (end > begin && out.S[end - 1] == 0.0 && out.G[end - 1] == 0.0) --end;
  out.first += static_cast<int>(begin);
  out.S = std::vector<double>(out.S.begin() + begin, out.S.begin() + end);
  out.G = std::vector<double>(out.G.begin() + begin, out.G.begin() + end);
}

Vec3 particle_half_lengths(const Vec3& initial, const Mat3& F, int dim) {
  Vec3 half = Vec3::Zero();
  for (int d = 0; d < dim; ++d) half(d) = initial(d) * std::max(F(d, d), 0.0);
  return half;
}

void gimp_stencil(const RectilinearGrid& grid, const Vec3& centre, const Vec3& half, Index cell,
                  bool axisymmetric, GimpStencil& out) {
  const int dim = grid.dim;
  std::array<AxisWeights, 3> axis;
  std::array<int, 3> count{1, 1, 1};
  for (int d = 0; d < dim; ++d) {
    const auto& lines = grid.lines[d];
    const double lo = axisymmetric && d == 0 ? std::max(lines.front(), 0.0) : lines.front();
    const double l = clip_half_length(centre(d), half(d), lo, lines.back());
    gimp_axis_weights(lines, centre(d), l, grid.cell_index[cell][d], axis[d]);
    count[d] = static_cast<int>(axis[d].S.size());
    out.first_cell[d] = axis[d].first;
    out.last_cell[d] = std::max(axis[d].first, axis[d].first + count[d] - 2);
  }
  for (int d = dim; d < 3; ++d) {
    axis[d].first = 0;
    axis[d].S = {1.0};
    axis[d].G = {0.0};
    out.first_cell[d] = out.last_cell[d] = 0;
  }
  // Tensor product (eq. 9.1): N = prod_d S^d, dN/dx_d = G^d prod_{e != d} S^e.
  out.nodes.clear();
  out.N.clear();
  out.gradients.clear();
  struct Entry {
    Index node;
    double N;
    std::array<double, 3> g;
  };
  std::vector<Entry> entries;
  entries.reserve(std::size_t(count[0]) * count[1] * count[2]);
  for (int k = 0; k < count[2]; ++k)
    for (int j = 0; j < count[1]; ++j)
      for (int i = 0; i < count[0]; ++i) {
        const int at[3] = {i, j, k};
        Entry e{grid.node(axis[0].first + i, axis[1].first + j, axis[2].first + k), 1.0, {}};
        for (int d = 0; d < 3; ++d) e.N *= axis[d].S[at[d]];
        for (int d = 0; d < dim; ++d) {
          double g = axis[d].G[at[d]];
          for (int o = 0; o < dim; ++o)
            if (o != d) g *= axis[o].S[at[o]];
          e.g[d] = g;
        }
        entries.push_back(e);
      }
  std::sort(entries.begin(), entries.end(),
            [](const Entry& x, const Entry& y) { return x.node < y.node; });
  for (const Entry& e : entries) {
    out.nodes.push_back(e.node);
    out.N.push_back(e.N);
    for (int d = 0; d < dim; ++d) out.gradients.push_back(e.g[d]);
  }
}

}  // namespace geompm

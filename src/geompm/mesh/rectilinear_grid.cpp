#include "geompm/mesh/rectilinear_grid.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace geompm {

namespace {

// Distinct coordinates along one axis: sorted values merged when closer than tol.
std::vector<double> grid_lines(const Mesh& mesh, int d, double tol) {
  std::vector<double> values;
  values.reserve(mesh.nodes.size());
  for (const Vec3& x : mesh.nodes) values.push_back(x(d));
  std::sort(values.begin(), values.end());
  std::vector<double> lines;
  for (double v : values)
    if (lines.empty() || v - lines.back() > tol) lines.push_back(v);
  return lines;
}

// The grid lines along each axis, found within `tol`; false (with the reason) unless every node
// lies on a complete grid of them.
bool find_grid_lines(const Mesh& mesh, double tol, RectilinearGrid& grid, std::string& why) {
  const int dim = grid.dim;
  std::size_t expected_nodes = 1;
  for (int d = 0; d < 3; ++d) {
    grid.lines[d] = d < dim ? grid_lines(mesh, d, tol) : std::vector<double>{0.0};
    expected_nodes *= grid.lines[d].size();
  }
  if (expected_nodes != mesh.nodes.size()) {
    why = fmt::format(
        "the nodes do not lie on a complete grid of axis-aligned lines: {} nodes on {} distinct x "
        "and {} distinct y{} coordinates",
        mesh.nodes.size(), grid.lines[0].size(), grid.lines[1].size(),
        dim == 3 ? fmt::format(" and {} distinct z", grid.lines[2].size()) : std::string());
    return false;
  }
  return true;
}

// Grid index of every node, into `index` and grid.node_at; false (with the reason) for a node off
// the grid lines or two nodes at one grid point.
bool index_nodes(const Mesh& mesh, double tol, RectilinearGrid& grid,
                 std::vector<std::array<int, 3>>& index, std::string& why) {
  const int dim = grid.dim;
  const auto axis_names = "xyz";
  index.assign(mesh.nodes.size(), {0, 0, 0});
  grid.node_at.assign(mesh.nodes.size(), -1);
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    for (int d = 0; d < dim; ++d) {
      const auto& l = grid.lines[d];
      const double v = mesh.nodes[n](d);
      const auto it = std::lower_bound(l.begin(), l.end(), v - tol);
      if (it == l.end() || std::abs(*it - v) > tol) {  // only between merged lines: not a grid
        why = fmt::format("node {} at {} = {} is not on a grid line", n, axis_names[d], v);
        return false;
      }
      index[n][d] = static_cast<int>(it - l.begin());
    }
    Index& slot = grid.node_at[std::size_t(index[n][0]) +
                               grid.lines[0].size() *
                                   (std::size_t(index[n][1]) + grid.lines[1].size() * index[n][2])];
    if (slot >= 0) {
      why = fmt::format("nodes {} and {} are at the same grid point", slot, n);
      return false;
    }
    slot = n;
  }
  return true;
}

// Every cell must be one box between neighbouring grid lines, holding all its corners. Fills
// grid.cell_at and grid.cell_index from the nodes' grid indices; false (with the reason) if not.
bool index_cells(const Mesh& mesh, const std::vector<std::array<int, 3>>& index,
                 RectilinearGrid& grid, std::string& why) {
  const int dim = grid.dim;
  std::size_t expected_cells = 1;
  for (int d = 0; d < dim; ++d) expected_cells *= grid.lines[d].size() - 1;
  if (static_cast<std::size_t>(mesh.num_cells()) != expected_cells) {
    why = fmt::format("{} cells where a complete grid of these lines has {}", mesh.num_cells(),
                      expected_cells);
    return false;
  }
  grid.cell_at.assign(expected_cells, -1);
  grid.cell_index.assign(mesh.num_cells(), {0, 0, 0});
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const auto nodes = mesh.cell_nodes(c);
    std::array<int, 3> first{0, 0, 0};
    for (int d = 0; d < dim; ++d) {
      int lo_index = index[nodes[0]][d], hi_index = lo_index;
      for (Index n : nodes) {
        lo_index = std::min(lo_index, index[n][d]);
        hi_index = std::max(hi_index, index[n][d]);
      }
      if (hi_index - lo_index != 1) {
        why = fmt::format("cell {} is not an axis-aligned box between neighbouring grid lines", c);
        return false;
      }
      first[d] = lo_index;
    }
    unsigned corners = 0;
    for (Index n : nodes) {
      unsigned bit = 0;
      for (int d = 0; d < dim; ++d) bit |= unsigned(index[n][d] - first[d]) << d;
      corners |= 1u << bit;
    }
    if (corners != (1u << (1 << dim)) - 1u) {
      why = fmt::format("cell {} is not an axis-aligned box (its nodes miss a corner)", c);
      return false;
    }
    grid.cell_index[c] = first;
    Index& slot = grid.cell_at[std::size_t(first[0]) +
                               std::size_t(grid.cells_along(0)) *
                                   (std::size_t(first[1]) +
                                    std::size_t(std::max(grid.cells_along(1), 0)) * first[2])];
    if (slot >= 0) {
      why = fmt::format("cells {} and {} overlap", slot, c);
      return false;
    }
    slot = c;
  }
  return true;
}

}  // namespace

std::optional<RectilinearGrid> find_rectilinear_grid(const Mesh& mesh, std::string& why) {
  if (mesh.mixed() || (mesh.cell_type != CellType::Quad4 && mesh.cell_type != CellType::Hex8)) {
    why = fmt::format("the mesh has {} cells; a rectilinear grid has quad4 (2D) or hex8 (3D) cells",
                      cell_type_names(mesh));
    return std::nullopt;
  }
  RectilinearGrid grid;
  grid.dim = mesh.dim();
  const int dim = grid.dim;
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max()), hi = -lo;
  for (const Vec3& x : mesh.nodes) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  const double tol = 1e-9 * head_max(hi - lo, dim);
  if (!find_grid_lines(mesh, tol, grid, why)) return std::nullopt;
  std::vector<std::array<int, 3>> index;  // grid index of every node
  if (!index_nodes(mesh, tol, grid, index, why)) return std::nullopt;
  if (!index_cells(mesh, index, grid, why)) return std::nullopt;
  return grid;
}

}  // namespace geompm

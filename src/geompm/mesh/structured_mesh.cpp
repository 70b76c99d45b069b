#include "geompm/mesh/structured_mesh.hpp"

#include <cmath>
#include <numeric>
#include <span>
#include <stdexcept>
#include <string>

namespace geompm {

namespace {

/// `where` prefixes the message, e.g. "structured mesh, axis y".
void check_segments(const std::vector<AxisSegment>& segments, const std::string& axis) {
  const std::string where = axis + ": ";
  if (segments.empty()) throw std::invalid_argument(where + "no segments; expected at least one");
  for (std::size_t s = 0; s < segments.size(); ++s) {
    const AxisSegment& segment = segments[s];
    const std::string which = where + "segment " + std::to_string(s) + ": ";
    if (segment.cells < 1)
      throw std::invalid_argument(which + "cells = " + std::to_string(segment.cells) +
                                  "; expected at least 1");
    if (!(segment.length > 0.0) || !std::isfinite(segment.length))
      throw std::invalid_argument(which + "length = " + std::to_string(segment.length) +
                                  "; expected a positive length");
    if (!(segment.ratio > 0.0) || !std::isfinite(segment.ratio))
      throw std::invalid_argument(which + "ratio = " + std::to_string(segment.ratio) +
                                  "; expected a positive ratio (last cell / first cell)");
  }
}

/// Node ids of a (nx+1) x (ny+1) [x (nz+1)] grid of points, x fastest.
struct Grid {
  Index nx = 0, ny = 0, nz = 0;  // cells per axis
  Index id(Index i, Index j, Index k = 0) const { return i + (nx + 1) * (j + (ny + 1) * k); }
};

std::vector<Index> all_ids(Index count) {
  std::vector<Index> ids(count);
  std::iota(ids.begin(), ids.end(), 0);
  return ids;
}

/// Nodes of a grid, boundary groups by position on the grid, and the region "all".
void add_grid_nodes(Mesh& mesh, const Grid& grid, const std::vector<double>& x,
                    const std::vector<double>& y, const std::vector<double>& z) {
  const bool three_d = !z.empty();
  const Index nk = three_d ? grid.nz : 0;
  for (Index k = 0; k <= nk; ++k)
    for (Index j = 0; j <= grid.ny; ++j)
      for (Index i = 0; i <= grid.nx; ++i) {
        const Index n = static_cast<Index>(mesh.nodes.size());
        mesh.nodes.emplace_back(x[i], y[j], three_d ? z[k] : 0.0);
        if (i == 0) mesh.node_groups["left"].push_back(n);
        if (i == grid.nx) mesh.node_groups["right"].push_back(n);
        if (three_d) {
          if (j == 0) mesh.node_groups["front"].push_back(n);
          if (j == grid.ny) mesh.node_groups["back"].push_back(n);
          if (k == 0) mesh.node_groups["bottom"].push_back(n);
          if (k == grid.nz) mesh.node_groups["top"].push_back(n);
        } else {
          if (j == 0) mesh.node_groups["bottom"].push_back(n);
          if (j == grid.ny) mesh.node_groups["top"].push_back(n);
        }
      }
}

/// Points of the grid refined twice, so that Tri6 mid-side nodes (edge midpoints and the
/// rectangle centres on the diagonals) are grid points too and are shared by construction.
std::vector<double> with_midpoints(const std::vector<double>& coordinates) {
  std::vector<double> out;
  for (std::size_t i = 0; i + 1 < coordinates.size(); ++i) {
    out.push_back(coordinates[i]);
    out.push_back(0.5 * (coordinates[i] + coordinates[i + 1]));
  }
  out.push_back(coordinates.back());
  return out;
}

void add_cell(Mesh& mesh, std::initializer_list<Index> nodes) {
  mesh.connectivity.insert(mesh.connectivity.end(), nodes);
}

void add_cell(Mesh& mesh, CellType type, std::initializer_list<Index> nodes) {
  mesh.add_cell(type, std::span<const Index>(nodes.begin(), nodes.size()));
}

Mesh generate_2d(const StructuredMeshSpec& spec) {
  const std::vector<double> x = axis_coordinates(spec.origin[0], spec.axes[0]);
  const std::vector<double> y = axis_coordinates(spec.origin[1], spec.axes[1]);
  const Index nx = static_cast<Index>(x.size()) - 1, ny = static_cast<Index>(y.size()) - 1;
  Mesh mesh;
  mesh.cell_type = spec.cell_type;

  if (spec.cell_type == CellType::Tri6) {
    const Grid fine{2 * nx, 2 * ny, 0};
    add_grid_nodes(mesh, fine, with_midpoints(x), with_midpoints(y), {});
    for (Index j = 0; j < ny; ++j)
      for (Index i = 0; i < nx; ++i) {
        const auto at = [&](Index di, Index dj) { return fine.id(2 * i + di, 2 * j + dj); };
        const Index centre = at(1, 1);
        if ((i + j) % 2 == 0) {  // diagonal from the lower-left to the upper-right corner
          add_cell(mesh, {at(0, 0), at(2, 0), at(2, 2), at(1, 0), at(2, 1), centre});
          add_cell(mesh, {at(0, 0), at(2, 2), at(0, 2), centre, at(1, 2), at(0, 1)});
        } else {  // diagonal from the lower-right to the upper-left corner
          add_cell(mesh, {at(0, 0), at(2, 0), at(0, 2), at(1, 0), centre, at(0, 1)});
          add_cell(mesh, {at(2, 0), at(2, 2), at(0, 2), at(2, 1), at(1, 2), centre});
        }
      }
  } else {
    const Grid grid{nx, ny, 0};
    add_grid_nodes(mesh, grid, x, y, {});
    for (Index j = 0; j < ny; ++j)
      for (Index i = 0; i < nx; ++i) {
        const Index n0 = grid.id(i, j), n1 = grid.id(i + 1, j), n2 = grid.id(i + 1, j + 1),
                    n3 = grid.id(i, j + 1);
        const CellType type =
            spec.cell_type_at
                ? spec.cell_type_at(Vec3(0.5 * (x[i] + x[i + 1]), 0.5 * (y[j] + y[j + 1]), 0.0))
                : spec.cell_type;
        if (type == CellType::Quad4) {
          add_cell(mesh, type, {n0, n1, n2, n3});
        } else if (spec.diagonals == Diagonals::Crossed) {  // four triangles around the centre
          const Index centre = static_cast<Index>(mesh.nodes.size());
          mesh.nodes.push_back(0.25 *
                               (mesh.nodes[n0] + mesh.nodes[n1] + mesh.nodes[n2] + mesh.nodes[n3]));
          add_cell(mesh, type, {n0, n1, centre});
          add_cell(mesh, type, {n1, n2, centre});
          add_cell(mesh, type, {n2, n3, centre});
          add_cell(mesh, type, {n3, n0, centre});
        } else if ((i + j) % 2 == 0) {  // alternating diagonals avoid a directional bias
          add_cell(mesh, type, {n0, n1, n2});
          add_cell(mesh, type, {n0, n2, n3});
        } else {
          add_cell(mesh, type, {n0, n1, n3});
          add_cell(mesh, type, {n1, n2, n3});
        }
      }
  }
  mesh.cell_groups["all"] = all_ids(mesh.num_cells());
  return mesh;
}

Mesh generate_3d(const StructuredMeshSpec& spec) {
  const std::vector<double> x = axis_coordinates(spec.origin[0], spec.axes[0]);
  const std::vector<double> y = axis_coordinates(spec.origin[1], spec.axes[1]);
  const std::vector<double> z = axis_coordinates(spec.origin[2], spec.axes[2]);
  const Grid grid{static_cast<Index>(x.size()) - 1, static_cast<Index>(y.size()) - 1,
                  static_cast<Index>(z.size()) - 1};
  Mesh mesh;
  mesh.cell_type = spec.cell_type;
  add_grid_nodes(mesh, grid, x, y, z);

  // Tet4: the six tetrahedra around the main diagonal (0,0,0)-(1,1,1) of each box, one per
  // order in which the axes are walked (Kuhn's split). Every box is split the same way, so a
  // shared face gets the same diagonal from both sides and the mesh is conforming.
  constexpr int walks[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (Index k = 0; k < grid.nz; ++k)
    for (Index j = 0; j < grid.ny; ++j)
      for (Index i = 0; i < grid.nx; ++i) {
        const auto at = [&](int di, int dj, int dk) { return grid.id(i + di, j + dj, k + dk); };
        if (spec.cell_type == CellType::Hex8) {
          add_cell(mesh, {at(0, 0, 0), at(1, 0, 0), at(1, 1, 0), at(0, 1, 0), at(0, 0, 1),
                          at(1, 0, 1), at(1, 1, 1), at(0, 1, 1)});
          continue;
        }
        for (const auto& walk : walks) {
          int step[3] = {0, 0, 0};
          Index corner[4];
          corner[0] = at(0, 0, 0);
          for (int s = 0; s < 3; ++s) {
            step[walk[s]] = 1;
            corner[s + 1] = at(step[0], step[1], step[2]);
          }
          // An odd permutation of the axes gives a left-handed tetrahedron: swap two nodes.
          const bool odd = (walk[0] == 0 && walk[1] == 2) || (walk[0] == 1 && walk[1] == 0) ||
                           (walk[0] == 2 && walk[1] == 1);
          if (odd) std::swap(corner[1], corner[2]);
          add_cell(mesh, {corner[0], corner[1], corner[2], corner[3]});
        }
      }
  mesh.cell_groups["all"] = all_ids(mesh.num_cells());
  return mesh;
}

}  // namespace

std::vector<double> axis_coordinates(double origin, const std::vector<AxisSegment>& segments) {
  check_segments(segments, "axis segments");
  std::vector<double> coordinates{origin};
  double start = origin;
  for (const AxisSegment& segment : segments) {
    // Sizes grow by a constant factor q from cell to cell, q^(cells-1) = ratio; the first size
    // makes them add up to the segment length.
    const int n = segment.cells;
    const double q = n > 1 ? std::pow(segment.ratio, 1.0 / (n - 1)) : 1.0;
    const double first = std::abs(q - 1.0) < 1e-14
                             ? segment.length / n
                             : segment.length * (q - 1.0) / (std::pow(q, n) - 1.0);
    double size = first, position = start;
    for (int c = 1; c < n; ++c) {
      position += size;
      coordinates.push_back(position);
      size *= q;
    }
    start += segment.length;  // the segment end is exact, whatever the round-off inside
    coordinates.push_back(start);
  }
  return coordinates;
}

Mesh generate_structured_mesh(const StructuredMeshSpec& spec) {
  const int dim = cell_dimension(spec.cell_type);
  const char* names[3] = {"x", "y", "z"};
  for (int i = 0; i < dim; ++i)
    check_segments(spec.axes[i], std::string("structured mesh, axis ") + names[i]);
  if (spec.diagonals == Diagonals::Crossed && spec.cell_type != CellType::Tri3)
    throw std::invalid_argument(
        std::string("structured mesh: crossed diagonals split rectangles into tri3 cells; the "
                    "cell type is ") +
        to_string(spec.cell_type));
  if (spec.cell_type_at && spec.cell_type != CellType::Quad4 && spec.cell_type != CellType::Tri3)
    throw std::invalid_argument(
        std::string("structured mesh: only quad4 and tri3 cells can be mixed (they share their "
                    "corner nodes, so the mesh stays conforming); the cell type is ") +
        to_string(spec.cell_type));
  return dim == 2 ? generate_2d(spec) : generate_3d(spec);
}

}  // namespace geompm

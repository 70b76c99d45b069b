// A mesh recognised as a rectilinear grid: axis-aligned Quad4 or Hex8 cells on a complete tensor
// product of grid lines, uniform or graded (the meshes of the built-in generator). GIMP needs
// this structure: its weights are tensor products of 1D weights along the grid lines
// (docs/theory.md §9), and a point's particle domain is a box of whole-grid cells.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "geompm/mesh/mesh.hpp"

namespace geompm {

struct RectilinearGrid {
  int dim = 2;
  /// Coordinates of the grid lines along each axis, ascending (only the first dim are used).
  std::array<std::vector<double>, 3> lines;
  /// Mesh node id at grid index (i, j, k), i fastest.
  std::vector<Index> node_at;
  /// Mesh cell id at cell index (i, j, k) (cell (i, j, k) spans lines i..i+1, j..j+1, k..k+1).
  std::vector<Index> cell_at;
  /// Per mesh cell: its cell index along each axis.
  std::vector<std::array<int, 3>> cell_index;

  int cells_along(int d) const { return static_cast<int>(lines[d].size()) - 1; }
  Index node(int i, int j, int k) const {
    return node_at[std::size_t(i) + lines[0].size() * (std::size_t(j) + lines[1].size() * k)];
  }
  Index cell(int i, int j, int k) const {
    return cell_at[std::size_t(i) + std::size_t(cells_along(0)) *
                                        (std::size_t(j) + std::size_t(cells_along(1)) * k)];
  }
};

/// The rectilinear grid of `mesh`, or nullopt with the reason (naming a cell or node) in `why`.
/// Coordinates are matched to grid lines within 1e-9 of the mesh's extent.
std::optional<RectilinearGrid> find_rectilinear_grid(const Mesh& mesh, std::string& why);

}  // namespace geompm

#include "geompm/analysis/model_size.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "geompm/core/error.hpp"
#include "geompm/core/memory.hpp"

namespace geompm {

namespace {

// The least a cell and a point cost over a run: connectivity, topology, the grid of a step and
// the sparse tangent's entries (a cell's share of them) for a cell; the point store (position,
// displacements, velocity, acceleration, deformation gradient, elastic strain, stress, internal
// variables) for a point. Measured peaks are several times higher (the factorisation's fill).
constexpr double bytes_per_cell_2d = 1000, bytes_per_cell_3d = 4000, bytes_per_point = 600;

double cells_per_box(CellType type, Diagonals diagonals) {
  switch (type) {
    case CellType::Tri3:
      return diagonals == Diagonals::Crossed ? 4 : 2;
    case CellType::Tri6:
      return 2;
    case CellType::Tet4:
      return 6;
    default:
      return 1;
  }
}

}  // namespace

ModelSize estimate_model_size(const spec::Model& spec) {
  ModelSize size;
  if (!spec.mesh.generate) return size;
  const StructuredMeshSpec& mesh = *spec.mesh.generate;
  const int dim = cell_dimension(mesh.cell_type);
  double boxes = 1, grid_nodes = 1;
  for (int d = 0; d < dim; ++d) {
    double along = 0;
    for (const AxisSegment& s : mesh.axes[d]) along += s.cells;
    boxes *= along;
    grid_nodes *= along + 1;
  }
  // Regions of another cell type (tri3 in a quad4 mesh) split their rectangles in two.
  const bool typed_regions = std::any_of(spec.regions.begin(), spec.regions.end(),
                                         [](const spec::MeshRegion& r) { return r.cell; });
  size.cells =
      boxes * std::max(cells_per_box(mesh.cell_type, mesh.diagonals), typed_regions ? 2.0 : 1.0);
  size.nodes = grid_nodes + (mesh.diagonals == Diagonals::Crossed ? boxes : 0) +
               (mesh.cell_type == CellType::Tri6 ? 2 * grid_nodes : 0);
  int most_points = 0;
  for (const spec::Body& body : spec.bodies)
    most_points = std::max(most_points, body.points_per_cell > 0 ? body.points_per_cell : 8);
  size.points = size.cells * most_points;
  size.bytes = size.cells * (dim == 3 ? bytes_per_cell_3d : bytes_per_cell_2d) +
               size.points * bytes_per_point;
  return size;
}

void check_model_size(const spec::Model& spec) {
  const ModelSize size = estimate_model_size(spec);
  if (size.cells == 0) return;
  const double largest_index = std::numeric_limits<Index>::max();
  const std::string estimate = fmt::format(
      "the generated mesh has {:.3g} cells and {:.3g} nodes, for {:.3g} material "
      "points at most, needing at least {:.3g} GB of memory",
      size.cells, size.nodes, size.points, size.bytes / 1e9);
  if (size.cells > largest_index || size.nodes > largest_index || size.points > largest_index)
    throw InputError(spec.mesh.source,
                     fmt::format("{}; geompm counts at most {:.3g} cells, nodes or points "
                                 "(use fewer cells)",
                                 estimate, largest_index));
  const double memory = physical_memory_bytes();
  if (memory > 0 && size.bytes > memory)
    throw InputError(spec.mesh.source,
                     fmt::format("{}, more than this machine's {:.3g} GB (use fewer cells)",
                                 estimate, memory / 1e9));
}

}  // namespace geompm

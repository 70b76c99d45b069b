#include "geompm/analysis/linear_solver_hints.hpp"

#include <algorithm>

namespace geompm {

LinearSolverHints linear_solver_hints(const GridSystem& grid, const std::vector<Vec3>& nodes) {
  LinearSolverHints hints;
  // Finite strain, non-associated flow, F-bar and friction make the tangent unsymmetric.
  hints.symmetric = false;
  const int dim = grid.dim();
  hints.block_size = dim;
  const std::vector<Index>& active = grid.active_nodes();
  hints.node_coordinates.reserve(active.size());
  for (const Index node : active) hints.node_coordinates.push_back(nodes[node]);
  hints.unknown_node.assign(grid.num_free(), -1);
  hints.unknown_component.assign(grid.num_free(), -1);
  LinearSolverField displacement{"displacement", {}}, pressure{"pressure", {}};
  const std::vector<Index>& free = grid.free_index();
  const Index displacements = static_cast<Index>(active.size()) * dim;
  for (Index d = 0; d < static_cast<Index>(free.size()); ++d) {
    const Index row = free[d];
    if (row < 0) continue;  // constrained: not in the matrix
    if (d < displacements) {
      hints.unknown_node[row] = d / dim;
      hints.unknown_component[row] = static_cast<int>(d % dim);
      displacement.unknowns.push_back(row);
    } else {
      pressure.unknowns.push_back(row);
    }
  }
  for (LinearSolverField* field : {&displacement, &pressure}) {
    std::sort(field->unknowns.begin(), field->unknowns.end());
    if (!field->unknowns.empty() || field == &displacement)
      hints.fields.push_back(std::move(*field));
  }
  return hints;
}

}  // namespace geompm

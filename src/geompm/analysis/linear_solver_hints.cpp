#include "geompm/analysis/linear_solver_hints.hpp"

namespace geompm {

LinearSolverHints linear_solver_hints(const DofMap& dofs, const std::vector<Vec3>& nodes,
                                      const std::vector<int>& node_process) {
  LinearSolverHints hints;
  // Finite strain, non-associated flow, F-bar and friction make the tangent unsymmetric.
  hints.symmetric = false;
  hints.unknown_node.assign(dofs.num_free(), -1);
  hints.unknown_component.assign(dofs.num_free(), -1);
  if (!node_process.empty()) hints.unknown_process.assign(dofs.num_free(), 0);
  bool displacement_seen = false;
  for (int f = 0; f < dofs.num_fields(); ++f) {
    const Field& field = dofs.field(f);
    // The grid's displacement field gives the blocks (rigid-body modes for AMG); a further
    // displacement field (a structure's, later) is one more field of the split.
    const bool blocks = field.kind == FieldKind::Displacement && field.nodal && !displacement_seen;
    if (blocks) {
      displacement_seen = true;
      hints.block_size = field.components;
      hints.node_coordinates.reserve(field.entities);
      for (Index e = 0; e < field.entities; ++e)
        hints.node_coordinates.push_back(nodes[dofs.active_nodes()[e]]);
    }
    LinearSolverField split{field.name, {}};
    // Entity-major numbering and free indices in the order of the unknowns: ascending rows.
    for (Index e = 0; e < field.entities; ++e)
      for (int c = 0; c < field.components; ++c) {
        const Index row = dofs.free_index(dofs.dof(f, e, c));
        if (row < 0) continue;  // constrained: not in the matrix
        split.unknowns.push_back(row);
        if (!node_process.empty() && field.nodal)
          hints.unknown_process[row] = node_process[dofs.active_nodes()[e]];
        if (blocks) {
          hints.unknown_node[row] = e;
          hints.unknown_component[row] = c;
        }
      }
    hints.fields.push_back(std::move(split));
  }
  return hints;
}

}  // namespace geompm

// What the linear solver is told about a step's system besides its matrix
// (solver/linear_solver.hpp): the block size, the nodes' positions and the fields, from the
// step's unknowns (dofs/dof_map.hpp).
#pragma once

#include <vector>

#include "geompm/core/types.hpp"
#include "geompm/dofs/dof_map.hpp"
#include "geompm/solver/linear_solver.hpp"

namespace geompm {

/// The hints for the step's matrix, whose rows are the free unknowns of `dofs` (numbered): one
/// field per field of the map, with its free rows; the block size, node positions and each row's
/// node and component from the (nodal) displacement field, dim per active node. `nodes`: the
/// mesh's node positions.
/// `node_process`: in a distributed run, per mesh node the process that owns it (partition.hpp),
/// which then owns the node's unknowns; empty in a serial run.
LinearSolverHints linear_solver_hints(const DofMap& dofs, const std::vector<Vec3>& nodes,
                                      const std::vector<int>& node_process = {});

}  // namespace geompm

// What the linear solver is told about a step's system besides its matrix
// (solver/linear_solver.hpp): the block size, the nodes' positions and the fields, from the grid
// system's numbering of its unknowns.
#pragma once

#include <vector>

#include "geompm/core/types.hpp"
#include "geompm/physics/grid_system.hpp"
#include "geompm/solver/linear_solver.hpp"

namespace geompm {

/// The hints for the step's matrix, whose rows are the grid's free unknowns: the displacements,
/// dim per active node (the block size), then in the mixed p-u formulation one pressure per
/// active node (docs/theory.md eq. 11.6). `nodes`: the mesh's node positions.
LinearSolverHints linear_solver_hints(const GridSystem& grid, const std::vector<Vec3>& nodes);

}  // namespace geompm

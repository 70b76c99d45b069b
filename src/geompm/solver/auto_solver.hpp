// `auto`: the direct solver (UMFPACK) for a step of fewer unknowns than
// LinearSolverOptions::direct_limit (by default 5·10^5 in 2D, 10^4 in 3D), AMG (petsc_hypre:
// BoomerAMG, whose iterations grew least with the size, docs/performance.md note 17) from there on,
// chosen step by step at analyse(). Below the limit, which is above the sizes of the examples, a
// run is the same as with umfpack, to the bit; PETSc is not even initialised.
#pragma once

#include <memory>

#include "geompm/solver/linear_solver.hpp"

namespace geompm {

std::unique_ptr<LinearSolver> create_auto_solver(const LinearSolverOptions& options);

}  // namespace geompm

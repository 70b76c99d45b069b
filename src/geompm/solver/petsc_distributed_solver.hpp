// The linear solver of a distributed run (docs/architecture.md, "Distributed runs"): each
// process gives its share of the tangent (the entries of its own points and cells, in the step's
// free numbering, which every process shares); PETSc's distributed matrix (MPIAIJ) sums the
// shares, its rows owned by the processes that own their nodes, and the solution is scattered
// back whole to every process. The matrix is preallocated once a step from the shares' patterns
// and filled at each setup; off-process entries go to their owners at assembly.
#pragma once

#include <memory>
#include <string>

#include "geompm/solver/linear_solver.hpp"

namespace geompm {

/// The distributed solver standing in for the serial one `name` of a model: a direct one
/// (umfpack, sparse_lu, petsc_mumps) is MUMPS, petsc_hypre BoomerAMG, petsc_gamg GAMG (Krylov:
/// CG for a symmetric matrix, else GMRES), auto MUMPS below the direct limit and BoomerAMG from
/// it. PETSc must have been started on every process (petsc_communicator.hpp).
std::unique_ptr<LinearSolver> create_petsc_distributed_solver(const std::string& name,
                                                              const LinearSolverOptions& options);

}  // namespace geompm

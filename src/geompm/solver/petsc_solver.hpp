// The PETSc backend (issue 44): Krylov solves with algebraic multigrid, and MUMPS, behind
// LinearSolver. Registered as
//   petsc_gamg    CG (symmetric matrix) or right-preconditioned GMRES with PETSc's smoothed-
//                 aggregation AMG (GAMG), given the block size and the rigid-body modes as its
//                 near-null space; for the mixed p-u system a Schur-complement field split with
//                 GAMG on the displacement block;
//   petsc_hypre   the same Krylov methods with hypre's BoomerAMG (classical AMG);
//   petsc_mumps   MUMPS, sparse direct LU (preonly).
// Only petsc_solver.cpp and petsc_session.cpp include PETSc's headers.
#pragma once

#include <memory>

#include "geompm/solver/linear_solver.hpp"

namespace geompm {

std::unique_ptr<LinearSolver> create_petsc_gamg_solver(const LinearSolverOptions& options);
std::unique_ptr<LinearSolver> create_petsc_hypre_solver(const LinearSolverOptions& options);
std::unique_ptr<LinearSolver> create_petsc_mumps_solver(const LinearSolverOptions& options);

}  // namespace geompm

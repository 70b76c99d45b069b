// UMFPACK (SuiteSparse): sparse direct LU with a multifrontal factorisation over BLAS; the
// default linear solver, the fastest direct one for the models of docs/performance.md.
#pragma once

#include <memory>

#include "geompm/solver/linear_solver.hpp"

namespace geompm {

std::unique_ptr<LinearSolver> create_umfpack_solver();

}  // namespace geompm

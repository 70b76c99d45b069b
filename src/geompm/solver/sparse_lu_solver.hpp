// Eigen's own sparse LU (COLAMD ordering, supernodal): no external dependency, slower than
// UMFPACK on large models; the unit tests' solver.
#pragma once

#include <memory>

#include "geompm/solver/linear_solver.hpp"

namespace geompm {

std::unique_ptr<LinearSolver> create_sparse_lu_solver();

}  // namespace geompm

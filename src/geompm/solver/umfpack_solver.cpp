#include "geompm/solver/umfpack_solver.hpp"

#include <Eigen/UmfPackSupport>

#include "geompm/solver/eigen_direct_solver.hpp"

namespace geompm {

std::unique_ptr<LinearSolver> create_umfpack_solver() {
  return std::make_unique<EigenDirectSolver<Eigen::UmfPackLU<SparseMatrix>>>("umfpack");
}

}  // namespace geompm

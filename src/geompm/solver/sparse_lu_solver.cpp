#include "geompm/solver/sparse_lu_solver.hpp"

#include <Eigen/SparseLU>

#include "geompm/solver/eigen_direct_solver.hpp"

namespace geompm {

std::unique_ptr<LinearSolver> create_sparse_lu_solver() {
  return std::make_unique<
      EigenDirectSolver<Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>>>>("sparse_lu");
}

}  // namespace geompm

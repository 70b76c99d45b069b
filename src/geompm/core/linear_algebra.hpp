// The sparse matrix and vector types every room that assembles or solves a linear system shares:
// the physics assembles into them, the solver room solves with them, and neither needs the other.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace geompm {

/// Compressed sparse column, 32-bit indices: the layout UMFPACK takes without a copy.
using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
using Vector = Eigen::VectorXd;

}  // namespace geompm

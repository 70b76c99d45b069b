// The one interface behind which linear solvers sit (docs/architecture.md): the Newton loop
// knows a sparse matrix and vectors only. The pattern is analysed once per step (the active set
// changes only between steps) and factorised once per Newton iteration.
#pragma once

#include <Eigen/SparseCore>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace geompm {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
using Vector = Eigen::VectorXd;

/// A factorisation failed (singular or non-finite matrix): the step is cut back.
class LinearSolverFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  /// Symbolic analysis of the sparsity pattern of `a`.
  virtual void analyze(const SparseMatrix& a) = 0;
  /// Numeric factorisation; the pattern must be the analysed one.
  virtual void factorize(const SparseMatrix& a) = 0;
  virtual Vector solve(const Vector& b) = 0;
  virtual const char* name() const = 0;
};

/// "umfpack" (SuiteSparse, sparse direct LU; the default) or "sparse_lu" (Eigen's own, no
/// external dependency). Throws std::invalid_argument listing the known names.
std::unique_ptr<LinearSolver> create_linear_solver(const std::string& name);
std::vector<std::string> linear_solver_names();

}  // namespace geompm

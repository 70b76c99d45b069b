#include "geompm/solver/linear_solver.hpp"

#include <Eigen/SparseLU>
#include <Eigen/UmfPackSupport>

namespace geompm {

namespace {

template <class Factorization>
class EigenSolver final : public LinearSolver {
 public:
  explicit EigenSolver(const char* name) : name_(name) {}
  void analyze(const SparseMatrix& a) override { solver_.analyzePattern(a); }
  void factorize(const SparseMatrix& a) override {
    solver_.factorize(a);
    if (solver_.info() != Eigen::Success)
      throw LinearSolverFailure(std::string(name_) + ": the matrix is singular or not finite");
  }
  Vector solve(const Vector& b) override {
    Vector x = solver_.solve(b);
    if (solver_.info() != Eigen::Success || !x.allFinite())
      throw LinearSolverFailure(std::string(name_) + ": the solve failed");
    return x;
  }
  const char* name() const override { return name_; }

 private:
  const char* name_;
  Factorization solver_;
};

}  // namespace

std::vector<std::string> linear_solver_names() { return {"umfpack", "sparse_lu"}; }

std::unique_ptr<LinearSolver> create_linear_solver(const std::string& name) {
  if (name == "umfpack")
    return std::make_unique<EigenSolver<Eigen::UmfPackLU<SparseMatrix>>>("umfpack");
  if (name == "sparse_lu")
    return std::make_unique<EigenSolver<Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>>>>(
        "sparse_lu");
  throw std::invalid_argument("unknown linear solver '" + name + "'; known: umfpack, sparse_lu");
}

}  // namespace geompm

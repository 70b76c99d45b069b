#include "geompm/solver/linear_solver.hpp"

#include <omp.h>

#include <Eigen/SparseLU>
#include <Eigen/UmfPackSupport>

namespace geompm {

namespace {

// Runs the solver's calls on one OpenMP thread. OpenBLAS's OpenMP build (scripts/setup.sh), which
// UMFPACK calls for its dense frontal updates, runs its kernels on as many threads as OpenMP
// offers at the call, and on some processors the rounding of those kernels then depends on the
// count: on an AMD EPYC (OpenBLAS 0.3.21) a run on two threads differed from one on one by
// 8e-12, where Debian's reference BLAS gave identical results. With one thread here, results do
// not depend on the number of threads (tests/verification/test_threads.cpp,
// docs/architecture.md); on 2 cores the second BLAS thread bought nothing (docs/performance.md).
class OneThread {
 public:
  OneThread() : threads_(omp_get_max_threads()) { omp_set_num_threads(1); }
  ~OneThread() { omp_set_num_threads(threads_); }
  OneThread(const OneThread&) = delete;
  OneThread& operator=(const OneThread&) = delete;

 private:
  int threads_;
};

template <class Factorization>
class EigenSolver final : public LinearSolver {
 public:
  explicit EigenSolver(const char* name) : name_(name) {}
  void analyze(const SparseMatrix& a) override {
    const OneThread one;
    solver_.analyzePattern(a);
  }
  void factorize(const SparseMatrix& a) override {
    const OneThread one;
    solver_.factorize(a);
    if (solver_.info() != Eigen::Success)
      throw LinearSolverFailure(std::string(name_) + ": the matrix is singular or not finite");
  }
  Vector solve(const Vector& b) override {
    const OneThread one;
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

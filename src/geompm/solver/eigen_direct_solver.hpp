// The direct solvers Eigen wraps (UMFPACK, Eigen's SparseLU) behind LinearSolver: one symbolic
// analysis per analyse(), one numeric factorisation per setup(), one back-substitution per
// solve(). Each is registered by its own file (umfpack_solver.cpp, sparse_lu_solver.cpp).
#pragma once

#include <omp.h>

#include <Eigen/SparseCore>
#include <string>

#include "geompm/solver/linear_solver.hpp"

namespace geompm {

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
class EigenDirectSolver : public LinearSolver {
 public:
  explicit EigenDirectSolver(const char* name) : name_(name) {}

  // The symbolic analysis is done at the first setup after analyse(), on that matrix: UMFPACK's
  // takes the matrix's values too (for its statistics of the diagonal), and the step's pattern
  // holds no tangent yet when analyse() is called. The hints are of no use to a direct solver.
  void analyse(const SparseMatrix& /*pattern*/, const LinearSolverHints& /*hints*/) override {
    analysed_ = false;
  }
  void setup(const SparseMatrix& a) override {
    const OneThread one;
    if (!analysed_) {
      solver_.analyzePattern(a);
      analysed_ = true;
    }
    solver_.factorize(a);
    if (solver_.info() != Eigen::Success)
      throw LinearSolverFailure(std::string(name_) + ": the matrix is singular or not finite");
  }
  // One back-substitution with the factorisation of the last setup: exact up to round-off, so
  // the tolerance is not needed.
  int solve(const Vector& b, Vector& x, double /*relative_tolerance*/) override {
    const OneThread one;
    x = solver_.solve(b);
    if (solver_.info() != Eigen::Success || !x.allFinite())
      throw LinearSolverFailure(std::string(name_) + ": the solve failed");
    return 1;
  }
  const char* name() const override { return name_; }

 private:
  const char* name_;
  bool analysed_ = false;
  Factorization solver_;
};

}  // namespace geompm

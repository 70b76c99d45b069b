#include "geompm/solver/auto_solver.hpp"

#include "geompm/solver/petsc_solver.hpp"
#include "geompm/solver/umfpack_solver.hpp"

namespace geompm {

namespace {

class AutoSolver : public LinearSolver {
 public:
  explicit AutoSolver(const LinearSolverOptions& options) : options_(options) {}

  void analyse(const SparseMatrix& pattern, const LinearSolverHints& hints) override {
    const Index limit = options_.direct_limit >= 0 ? options_.direct_limit
                        : hints.block_size == 3    ? default_direct_limit_3d
                                                   : default_direct_limit;
    if (pattern.rows() < limit) {
      if (!direct_) direct_ = create_umfpack_solver();
      active_ = direct_.get();
    } else {
      if (!iterative_) iterative_ = create_petsc_hypre_solver(options_);
      active_ = iterative_.get();
    }
    active_->analyse(pattern, hints);
  }
  void setup(const SparseMatrix& matrix) override {
    if (!active_) throw LinearSolverFailure("auto: setup before analyse");
    active_->setup(matrix);
  }
  int solve(const Vector& b, Vector& x, double relative_tolerance) override {
    if (!active_) throw LinearSolverFailure("auto: solve before setup");
    return active_->solve(b, x, relative_tolerance);
  }
  const char* name() const override { return "auto"; }

 private:
  LinearSolverOptions options_;
  std::unique_ptr<LinearSolver> direct_, iterative_;
  LinearSolver* active_ = nullptr;
};

}  // namespace

std::unique_ptr<LinearSolver> create_auto_solver(const LinearSolverOptions& options) {
  return std::make_unique<AutoSolver>(options);
}

}  // namespace geompm

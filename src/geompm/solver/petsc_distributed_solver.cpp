#include "geompm/solver/petsc_distributed_solver.hpp"

#include <fmt/format.h>
#include <petscksp.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "geompm/solver/petsc_session.hpp"

namespace geompm {

namespace {

using petsc::check;

enum class Method { Auto, Mumps, Hypre, Gamg };

constexpr PetscInt max_krylov_iterations = 2000;

Method method_of(const std::string& name) {
  if (name == "auto") return Method::Auto;
  if (name == "petsc_hypre") return Method::Hypre;
  if (name == "petsc_gamg") return Method::Gamg;
  return Method::Mumps;  // the direct solvers
}

class PetscDistributedSolver final : public LinearSolver {
 public:
  PetscDistributedSolver(Method method, const LinearSolverOptions& options)
      : requested_(method), options_(options) {
    petsc::initialise(options.petsc_options);
    MPI_Comm_rank(PETSC_COMM_WORLD, &rank_);
    MPI_Comm_size(PETSC_COMM_WORLD, &size_);
  }
  ~PetscDistributedSolver() override { release(); }
  PetscDistributedSolver(const PetscDistributedSolver&) = delete;
  PetscDistributedSolver& operator=(const PetscDistributedSolver&) = delete;

  void analyse(const SparseMatrix& pattern, const LinearSolverHints& hints) override;
  void setup(const SparseMatrix& matrix) override;
  int solve(const Vector& b, Vector& x, double relative_tolerance) override;
  const char* name() const override { return "petsc_distributed"; }

 private:
  void release();
  void number_rows(Index rows, const LinearSolverHints& hints);
  void collect_rows(const SparseMatrix& pattern);
  void create_matrix();
  void create_ksp(Index rows, const LinearSolverHints& hints);
  void create_near_null_space();
  void add_padding();

  Method requested_, method_ = Method::Mumps;
  LinearSolverOptions options_;
  int rank_ = 0, size_ = 1;
  // The PETSc numbering: the rows of process 0, then of process 1, ..., each in the step's
  // order. petsc_row_[free row] is its PETSc row; this process owns [first_, first_ + owned_).
  // With nodal blocks (block_ > 1, every row a displacement) each node's block is complete, as
  // in the serial PETSc solvers: a constrained component is a padding row, decoupled, with the
  // mean diagonal, so that the matrix carries the block size AMG aggregates by.
  std::vector<PetscInt> petsc_row_, rows_of_process_;
  std::vector<Index> local_row_;         // per row this process owns: its free row, or -1 (padding)
  std::vector<PetscInt> padding_;        // the padding rows this process owns
  std::vector<Index> diagonal_entries_;  // the share's diagonal entries (value positions)
  PetscInt first_ = 0, owned_ = 0, total_ = 0;
  Index free_rows_ = 0;
  int block_ = 1;
  // This process's share of the tangent by rows: for each row with entries, its PETSc row, the
  // range [entry_start_[k], entry_start_[k+1]) of its PETSc columns and value positions.
  std::vector<PetscInt> share_row_, entry_start_, entry_column_;
  std::vector<Index> entry_value_;
  std::vector<PetscScalar> values_;
  const double* values_of_setup_ = nullptr;  // the share's values at the last setup
  Mat matrix_ = nullptr;
  Vec b_ = nullptr, x_ = nullptr, x_all_ = nullptr;
  MatNullSpace near_null_ = nullptr;
  VecScatter to_all_ = nullptr;
  KSP ksp_ = nullptr;
};

void PetscDistributedSolver::release() {
  KSPDestroy(&ksp_);
  MatNullSpaceDestroy(&near_null_);
  VecScatterDestroy(&to_all_);
  VecDestroy(&x_all_);
  VecDestroy(&b_);
  VecDestroy(&x_);
  MatDestroy(&matrix_);
}

void PetscDistributedSolver::analyse(const SparseMatrix& pattern, const LinearSolverHints& hints) {
  release();
  number_rows(pattern.rows(), hints);
  collect_rows(pattern);
  create_matrix();
  create_ksp(pattern.rows(), hints);
}

void PetscDistributedSolver::number_rows(Index rows, const LinearSolverHints& hints) {
  const auto owner = [&](Index row) {
    return hints.unknown_process.empty() ? 0 : hints.unknown_process[row];
  };
  free_rows_ = rows;
  const bool blocks = hints.block_size > 1 &&
                      static_cast<Index>(hints.unknown_node.size()) == rows &&
                      std::all_of(hints.unknown_node.begin(), hints.unknown_node.end(),
                                  [](Index n) { return n >= 0; });
  block_ = blocks ? hints.block_size : 1;
  // A row's place: its own (block_ 1), or its node's block and component.
  const Index places = blocks ? static_cast<Index>(hints.node_coordinates.size()) : rows;
  std::vector<int> place_owner(places, -1);
  for (Index r = 0; r < rows; ++r) place_owner[blocks ? hints.unknown_node[r] : r] = owner(r);
  rows_of_process_.assign(size_ + 1, 0);
  for (Index n = 0; n < places; ++n)
    if (place_owner[n] >= 0) rows_of_process_[place_owner[n] + 1] += block_;
  for (int p = 0; p < size_; ++p) rows_of_process_[p + 1] += rows_of_process_[p];
  std::vector<PetscInt> next(rows_of_process_.begin(), rows_of_process_.end() - 1);
  std::vector<PetscInt> place_row(places, -1);
  for (Index n = 0; n < places; ++n)
    if (place_owner[n] >= 0) {
      place_row[n] = next[place_owner[n]];
      next[place_owner[n]] += block_;
    }
  first_ = rows_of_process_[rank_];
  owned_ = rows_of_process_[rank_ + 1] - first_;
  total_ = rows_of_process_[size_];
  petsc_row_.assign(rows, 0);
  local_row_.assign(owned_, -1);
  for (Index r = 0; r < rows; ++r) {
    petsc_row_[r] =
        blocks ? place_row[hints.unknown_node[r]] + hints.unknown_component[r] : place_row[r];
    if (owner(r) == rank_) local_row_[petsc_row_[r] - first_] = r;
  }
  padding_.clear();
  for (PetscInt k = 0; k < owned_; ++k)
    if (local_row_[k] < 0) padding_.push_back(first_ + k);
}

// The share's entries row by row (Eigen's matrix is stored by columns).
void PetscDistributedSolver::collect_rows(const SparseMatrix& pattern) {
  const Index rows = pattern.rows();
  std::vector<PetscInt> count(rows + 1, 0);
  for (Index k = 0; k < pattern.nonZeros(); ++k) ++count[pattern.innerIndexPtr()[k] + 1];
  for (Index r = 0; r < rows; ++r) count[r + 1] += count[r];
  entry_column_.assign(pattern.nonZeros(), 0);
  diagonal_entries_.clear();
  entry_value_.assign(pattern.nonZeros(), 0);
  std::vector<PetscInt> at(count.begin(), count.end() - 1);
  for (Index c = 0; c < pattern.cols(); ++c)
    for (Index k = pattern.outerIndexPtr()[c]; k < pattern.outerIndexPtr()[c + 1]; ++k) {
      const Index r = pattern.innerIndexPtr()[k];
      entry_column_[at[r]] = petsc_row_[c];
      entry_value_[at[r]++] = k;
      if (r == c) diagonal_entries_.push_back(k);
    }
  // A row without entries adds nothing to the counts: the kept rows' ranges are contiguous.
  share_row_.clear();
  entry_start_.assign(1, 0);
  for (Index r = 0; r < rows; ++r)
    if (count[r + 1] > count[r]) {
      share_row_.push_back(petsc_row_[r]);
      entry_start_.push_back(count[r + 1]);
    }
  values_.assign(entry_column_.size(), 0.0);
}

// Preallocation: each process counts its share's entries per row in the owner's diagonal block
// and outside it; the owners get the sums (an upper bound where shares overlap, on the rows of
// nodes between processes).
void PetscDistributedSolver::create_matrix() {
  const PetscInt rows = total_;
  std::vector<PetscInt> diagonal(rows, 0), off(rows, 0);
  std::vector<int> owner_of(rows);
  for (int p = 0; p < size_; ++p)
    for (PetscInt r = rows_of_process_[p]; r < rows_of_process_[p + 1]; ++r) owner_of[r] = p;
  for (std::size_t k = 0; k + 1 < entry_start_.size(); ++k) {
    const PetscInt row = share_row_[k];
    const int p = owner_of[row];
    for (PetscInt e = entry_start_[k]; e < entry_start_[k + 1]; ++e) {
      const PetscInt col = entry_column_[e];
      if (col >= rows_of_process_[p] && col < rows_of_process_[p + 1])
        ++diagonal[row];
      else
        ++off[row];
    }
  }
  std::vector<int> counts(size_);
  for (int p = 0; p < size_; ++p) counts[p] = rows_of_process_[p + 1] - rows_of_process_[p];
  std::vector<PetscInt> d_nnz(std::max<PetscInt>(owned_, 1)), o_nnz(std::max<PetscInt>(owned_, 1));
  check(MPI_Reduce_scatter(diagonal.data(), d_nnz.data(), counts.data(), MPIU_INT, MPI_SUM,
                           PETSC_COMM_WORLD),
        "MPI_Reduce_scatter");
  check(MPI_Reduce_scatter(off.data(), o_nnz.data(), counts.data(), MPIU_INT, MPI_SUM,
                           PETSC_COMM_WORLD),
        "MPI_Reduce_scatter");
  for (const PetscInt pad : padding_) ++d_nnz[pad - first_];
  for (PetscInt r = 0; r < owned_; ++r) {
    d_nnz[r] = std::min(d_nnz[r], owned_);
    o_nnz[r] = std::min(o_nnz[r], rows - owned_);
  }
  check(MatCreate(PETSC_COMM_WORLD, &matrix_), "MatCreate");
  check(MatSetSizes(matrix_, owned_, owned_, rows, rows), "MatSetSizes");
  check(MatSetBlockSize(matrix_, block_), "MatSetBlockSize");
  check(MatSetType(matrix_, MATMPIAIJ), "MatSetType");
  check(MatMPIAIJSetPreallocation(matrix_, 0, d_nnz.data(), 0, o_nnz.data()),
        "MatMPIAIJSetPreallocation");
  check(MatSetOption(matrix_, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE), "MatSetOption");
  // Every setup of the step sends the same off-process entries.
  check(MatSetOption(matrix_, MAT_SUBSET_OFF_PROC_ENTRIES, PETSC_TRUE), "MatSetOption");
  check(MatCreateVecs(matrix_, &x_, &b_), "MatCreateVecs");
  check(VecScatterCreateToAll(x_, &to_all_, &x_all_), "VecScatterCreateToAll");
}

void PetscDistributedSolver::create_ksp(Index rows, const LinearSolverHints& hints) {
  method_ = requested_;
  if (method_ == Method::Auto) {
    const Index limit = options_.direct_limit >= 0 ? options_.direct_limit
                        : hints.block_size == 3    ? default_direct_limit_3d
                                                   : default_direct_limit;
    method_ = rows < limit ? Method::Mumps : Method::Hypre;
  }
  check(KSPCreate(PETSC_COMM_WORLD, &ksp_), "KSPCreate");
  PC pc = nullptr;
  check(KSPGetPC(ksp_, &pc), "KSPGetPC");
  if (method_ == Method::Mumps) {
    check(KSPSetType(ksp_, KSPPREONLY), "KSPSetType");
    check(PCSetType(pc, PCLU), "PCSetType(lu)");
    check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType");
  } else {
    check(KSPSetType(ksp_, hints.symmetric ? KSPCG : KSPGMRES), "KSPSetType");
    if (method_ == Method::Hypre) {
      check(PCSetType(pc, PCHYPRE), "PCSetType(hypre)");
      check(PCHYPRESetType(pc, "boomeramg"), "PCHYPRESetType");
    } else {
      check(PCSetType(pc, PCGAMG), "PCSetType(gamg)");
      petsc::set_default("-mg_levels_pc_type", "sor");
      create_near_null_space();
    }
  }
  check(KSPSetFromOptions(ksp_), "KSPSetFromOptions");
}

// The translations of the nodal blocks, as the serial GAMG takes them (petsc_solver.cpp: with
// the rotations its coarse levels broke).
void PetscDistributedSolver::create_near_null_space() {
  if (block_ < 2) return;
  std::vector<Vec> modes(block_);
  for (int c = 0; c < block_; ++c) {
    check(MatCreateVecs(matrix_, &modes[c], nullptr), "MatCreateVecs");
    PetscScalar* v = nullptr;
    check(VecGetArrayWrite(modes[c], &v), "VecGetArrayWrite");
    for (PetscInt k = 0; k < owned_; ++k) v[k] = k % block_ == c ? 1.0 : 0.0;
    check(VecRestoreArrayWrite(modes[c], &v), "VecRestoreArrayWrite");
    check(VecNormalize(modes[c], nullptr), "VecNormalize");
  }
  check(MatNullSpaceCreate(PETSC_COMM_WORLD, PETSC_FALSE, block_, modes.data(), &near_null_),
        "MatNullSpaceCreate");
  for (Vec& v : modes) VecDestroy(&v);
  check(MatSetNearNullSpace(matrix_, near_null_), "MatSetNearNullSpace");
}

// The padding rows' diagonal: the mean of the free rows' (summed over the processes' shares).
void PetscDistributedSolver::add_padding() {
  double sum = 0.0;
  for (const Index k : diagonal_entries_) sum += values_of_setup_[k];
  check(MPI_Allreduce(MPI_IN_PLACE, &sum, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD),
        "MPI_Allreduce");
  const double mean = free_rows_ > 0 ? std::abs(sum) / static_cast<double>(free_rows_) : 0.0;
  const PetscScalar value = mean > 0.0 ? mean : 1.0;
  for (const PetscInt pad : padding_)
    check(MatSetValues(matrix_, 1, &pad, 1, &pad, &value, ADD_VALUES), "MatSetValues");
}

void PetscDistributedSolver::setup(const SparseMatrix& matrix) {
  values_of_setup_ = matrix.valuePtr();
  check(MatZeroEntries(matrix_), "MatZeroEntries");
  const double* values = matrix.valuePtr();
  for (std::size_t e = 0; e < entry_value_.size(); ++e) values_[e] = values[entry_value_[e]];
  for (std::size_t k = 0; k + 1 < entry_start_.size(); ++k) {
    const PetscInt begin = entry_start_[k];
    check(MatSetValues(matrix_, 1, &share_row_[k], entry_start_[k + 1] - begin,
                       entry_column_.data() + begin, values_.data() + begin, ADD_VALUES),
          "MatSetValues");
  }
  add_padding();
  check(MatAssemblyBegin(matrix_, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  check(MatAssemblyEnd(matrix_, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  check(KSPSetOperators(ksp_, matrix_, matrix_), "KSPSetOperators");
  check(KSPSetUp(ksp_), "KSPSetUp");
  PC pc = nullptr;
  check(KSPGetPC(ksp_, &pc), "KSPGetPC");
  PCFailedReason failed = PC_NOERROR;
  check(PCGetFailedReasonRank(pc, &failed), "PCGetFailedReasonRank");
  // Each process knows only its own failure: agree on the worst, or one process would cut the
  // step back while the others wait in KSPSolve.
  int worst = static_cast<int>(failed);
  if (MPI_Allreduce(MPI_IN_PLACE, &worst, 1, MPI_INT, MPI_MAX,
                    PetscObjectComm(reinterpret_cast<PetscObject>(pc))) != MPI_SUCCESS)
    throw LinearSolverFailure("PETSc: the processes could not share the preconditioner's state");
  failed = static_cast<PCFailedReason>(worst);
  if (failed != PC_NOERROR)
    throw LinearSolverFailure(
        fmt::format("PETSc: the preconditioner failed ({})", PCFailedReasons[failed]));
}

int PetscDistributedSolver::solve(const Vector& b, Vector& x, double relative_tolerance) {
  PetscScalar* own = nullptr;
  check(VecGetArrayWrite(b_, &own), "VecGetArrayWrite");
  for (PetscInt k = 0; k < owned_; ++k) own[k] = local_row_[k] >= 0 ? b(local_row_[k]) : 0.0;
  check(VecRestoreArrayWrite(b_, &own), "VecRestoreArrayWrite");
  if (method_ != Method::Mumps)
    check(KSPSetTolerances(ksp_, relative_tolerance, PETSC_DEFAULT, PETSC_DEFAULT,
                           max_krylov_iterations),
          "KSPSetTolerances");
  check(KSPSolve(ksp_, b_, x_), "KSPSolve");
  KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
  check(KSPGetConvergedReason(ksp_, &reason), "KSPGetConvergedReason");
  if (reason < 0)
    throw LinearSolverFailure(fmt::format("PETSc: the distributed solve did not converge ({})",
                                          KSPConvergedReasons[reason]));
  PetscInt iterations = 0;
  check(KSPGetIterationNumber(ksp_, &iterations), "KSPGetIterationNumber");
  // The solution whole on every process, in the step's numbering.
  check(VecScatterBegin(to_all_, x_, x_all_, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
  check(VecScatterEnd(to_all_, x_, x_all_, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
  const PetscScalar* all = nullptr;
  check(VecGetArrayRead(x_all_, &all), "VecGetArrayRead");
  x.resize(static_cast<Index>(petsc_row_.size()));
  for (std::size_t r = 0; r < petsc_row_.size(); ++r) x(static_cast<Index>(r)) = all[petsc_row_[r]];
  check(VecRestoreArrayRead(x_all_, &all), "VecRestoreArrayRead");
  return std::max<int>(1, static_cast<int>(iterations));
}

}  // namespace

std::unique_ptr<LinearSolver> create_petsc_distributed_solver(const std::string& name,
                                                              const LinearSolverOptions& options) {
  return std::make_unique<PetscDistributedSolver>(method_of(name), options);
}

}  // namespace geompm

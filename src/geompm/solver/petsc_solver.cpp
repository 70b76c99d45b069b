#include "geompm/solver/petsc_solver.hpp"

#include <fmt/format.h>
#include <petscksp.h>

#include <Eigen/QR>
#include <algorithm>
#include <string>
#include <vector>

#include "geompm/core/error.hpp"
#include "geompm/solver/padded_csr.hpp"
#include "geompm/solver/petsc_session.hpp"
#include "geompm/solver/rigid_body_modes.hpp"

namespace geompm {

namespace {

using petsc::check;

enum class Method { Gamg, Hypre, Mumps };

// The most Krylov iterations a solve may take before it counts as failed (the step is cut back).
constexpr PetscInt max_krylov_iterations = 2000;
// GMRES's restart: the Krylov basis kept, memory (restart + 1) vectors. AMG converges in tens
// of iterations here (docs/performance.md), so a restart is rare.
constexpr PetscInt gmres_restart = 60;

// The rigid-body modes in the padded numbering (every node's whole block), orthonormalised: the
// near-null space GAMG's smoothed aggregation builds its coarse spaces from.
Eigen::MatrixXd padded_modes(const PaddedCsr& csr, const LinearSolverHints& hints) {
  LinearSolverHints padded;
  padded.block_size = hints.block_size;
  padded.node_coordinates = hints.node_coordinates;
  for (int r = 0; r < csr.displacement_rows; ++r) {
    padded.unknown_node.push_back(r / hints.block_size);
    padded.unknown_component.push_back(r % hints.block_size);
  }
  // The translations only. With the rotations too, GAMG made aggregates of one node (2 rows in
  // 2D) for 3 modes, whose coarse unknowns then had a zero diagonal, and SOR failed on that level
  // (the block of 160 x 160 cells, tests/unit/analysis/test_petsc_solvers.cpp).
  const Eigen::MatrixXd modes = rigid_body_modes(padded).leftCols(hints.block_size);
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(modes);
  return qr.householderQ() * Eigen::MatrixXd::Identity(modes.rows(), modes.cols());
}

class PetscSolver : public LinearSolver {
 public:
  PetscSolver(Method method, const char* name, const LinearSolverOptions& options)
      : method_(method), name_(name) {
    petsc::initialise(options.petsc_options);
  }
  ~PetscSolver() override { release(); }
  PetscSolver(const PetscSolver&) = delete;
  PetscSolver& operator=(const PetscSolver&) = delete;

  void analyse(const SparseMatrix& pattern, const LinearSolverHints& hints) override;
  void setup(const SparseMatrix& matrix) override;
  int solve(const Vector& b, Vector& x, double relative_tolerance) override;
  const char* name() const override { return name_; }

 private:
  void release();
  void create_matrix();
  void create_near_null_space(const LinearSolverHints& hints);
  void create_fields(const LinearSolverHints& hints);
  void configure(bool symmetric);
  void configure_amg(PC pc);
  void configure_field_split(PC pc);
  bool symmetric(const SparseMatrix& matrix) const;

  Method method_;
  const char* name_;
  PaddedCsr csr_;
  std::vector<int> transpose_;
  int block_size_ = 1;
  Mat matrix_ = nullptr;
  Vec b_ = nullptr, x_ = nullptr;
  KSP ksp_ = nullptr;
  MatNullSpace near_null_ = nullptr;
  IS displacement_ = nullptr, pressure_ = nullptr;
  bool symmetric_hint_ = false;
  bool unsymmetric_for_step_ = false;  // CG failed this step: GMRES to its end
  int configured_ = -1;  // -1: not yet this step; else whether configured for symmetric
  bool options_checked_ = false;
  const SparseMatrix* matrix_of_setup_ = nullptr;  // LinearSolver::setup: it outlives the solves
};

void PetscSolver::release() {
  matrix_of_setup_ = nullptr;
  KSPDestroy(&ksp_);
  MatNullSpaceDestroy(&near_null_);
  ISDestroy(&displacement_);
  ISDestroy(&pressure_);
  VecDestroy(&b_);
  VecDestroy(&x_);
  MatDestroy(&matrix_);
}

// Once per step: the padded CSR layout, PETSc's matrix preallocated from it (values follow at
// each setup), the near-null space and the fields. The KSP is built at the first setup, once
// the symmetry of the values is known.
void PetscSolver::analyse(const SparseMatrix& pattern, const LinearSolverHints& hints) {
  release();
  configured_ = -1;
  unsymmetric_for_step_ = false;
  block_size_ = std::max(1, hints.block_size);
  symmetric_hint_ = hints.symmetric;
  csr_ = PaddedCsr::build(pattern, hints);
  transpose_ = transpose_entries(pattern);
  create_matrix();
  if (method_ == Method::Mumps) return;
  create_near_null_space(hints);
  create_fields(hints);
}

void PetscSolver::create_matrix() {
  check(MatCreate(PETSC_COMM_SELF, &matrix_), "MatCreate");
  check(MatSetSizes(matrix_, csr_.rows, csr_.rows, csr_.rows, csr_.rows), "MatSetSizes");
  // Whole nodes only: with another field's rows after the blocks the count may not divide.
  if (block_size_ > 1 && csr_.rows % block_size_ == 0)
    check(MatSetBlockSize(matrix_, block_size_), "MatSetBlockSize");
  check(MatSetType(matrix_, MATSEQAIJ), "MatSetType");
  const std::vector<PetscScalar> zeros(csr_.column.size(), 0.0);
  check(MatSeqAIJSetPreallocationCSR(matrix_, csr_.row_start.data(), csr_.column.data(),
                                     zeros.data()),
        "MatSeqAIJSetPreallocationCSR");
  check(MatCreateVecs(matrix_, &x_, &b_), "MatCreateVecs");
}

void PetscSolver::create_near_null_space(const LinearSolverHints& hints) {
  if (csr_.displacement_rows == 0 || hints.node_coordinates.empty()) return;
  const Eigen::MatrixXd modes = padded_modes(csr_, hints);
  std::vector<Vec> vectors(modes.cols());
  for (Eigen::Index k = 0; k < modes.cols(); ++k) {
    check(VecCreateSeq(PETSC_COMM_SELF, csr_.displacement_rows, &vectors[k]), "VecCreateSeq");
    PetscScalar* v = nullptr;
    check(VecGetArrayWrite(vectors[k], &v), "VecGetArrayWrite");
    std::copy(modes.col(k).data(), modes.col(k).data() + csr_.displacement_rows, v);
    check(VecRestoreArrayWrite(vectors[k], &v), "VecRestoreArrayWrite");
  }
  // Extended by zeros to the other fields' rows when the whole matrix is GAMG's.
  const bool whole = csr_.displacement_rows == csr_.rows;
  check(MatNullSpaceCreate(PETSC_COMM_SELF, PETSC_FALSE, PetscInt(vectors.size()), vectors.data(),
                           &near_null_),
        "MatNullSpaceCreate");
  for (Vec& v : vectors) VecDestroy(&v);
  if (whole) check(MatSetNearNullSpace(matrix_, near_null_), "MatSetNearNullSpace");
}

// The mixed p-u system's two fields, for the Schur split: the displacement block (padded nodes)
// and everything else. Other extra fields (structures, contact) go without a split for now.
void PetscSolver::create_fields(const LinearSolverHints& hints) {
  const auto pressure =
      std::find_if(hints.fields.begin(), hints.fields.end(),
                   [](const LinearSolverField& f) { return f.name == "pressure"; });
  if (pressure == hints.fields.end() || hints.fields.size() != 2 || csr_.displacement_rows == 0)
    return;
  check(ISCreateStride(PETSC_COMM_SELF, csr_.displacement_rows, 0, 1, &displacement_),
        "ISCreateStride");
  check(ISSetBlockSize(displacement_, block_size_), "ISSetBlockSize");
  const std::vector<int> rows = csr_.rows_of(pressure->unknowns);
  check(ISCreateGeneral(PETSC_COMM_SELF, PetscInt(rows.size()), rows.data(), PETSC_COPY_VALUES,
                        &pressure_),
        "ISCreateGeneral");
  // The split hands the near-null space to its displacement block's matrix.
  if (near_null_)
    check(PetscObjectCompose(PetscObject(displacement_), "nearnullspace", PetscObject(near_null_)),
          "PetscObjectCompose");
}

// The tangent is not symmetric in general (hints.symmetric says so); an elastic, small-strain
// one is, and CG then costs less memory and work than GMRES. The saddle-point p-u system goes to
// GMRES whatever its symmetry: it is indefinite.
bool PetscSolver::symmetric(const SparseMatrix& matrix) const {
  if (pressure_ || unsymmetric_for_step_) return false;
  return symmetric_hint_ || is_symmetric(matrix, transpose_);
}

void PetscSolver::configure_amg(PC pc) {
  if (method_ == Method::Hypre) {
    check(PCSetType(pc, PCHYPRE), "PCSetType(hypre)");
    check(PCHYPRESetType(pc, "boomeramg"), "PCHYPRESetType");
    return;
  }
  check(PCSetType(pc, PCGAMG), "PCSetType(gamg)");
  // The coarse spaces are rebuilt from each Newton iteration's matrix but the aggregates, from
  // the step's first, are kept: the pattern is the step's, and the stiffness changes little.
  check(PCGAMGSetReuseInterpolation(pc, PETSC_TRUE), "PCGAMGSetReuseInterpolation");
  // Symmetric SOR on the levels instead of GAMG's default Chebyshev-Jacobi: Chebyshev's
  // eigenvalue estimate fails on a footing's stiff prescribed-motion springs beside soft empty
  // cells (CG stopped with an indefinite preconditioner, GMRES did not converge in 2000
  // iterations on examples/mohr_coulomb_footing; with SOR about 7 a Newton solve).
  petsc::set_default("-mg_levels_pc_type", "sor");
}

void PetscSolver::configure_field_split(PC pc) {
  check(PCSetType(pc, PCFIELDSPLIT), "PCSetType(fieldsplit)");
  check(PCFieldSplitSetIS(pc, "u", displacement_), "PCFieldSplitSetIS(u)");
  check(PCFieldSplitSetIS(pc, "p", pressure_), "PCFieldSplitSetIS(p)");
  // [A B; C D] = [1 0; C A^-1 1] [A 0; 0 S] [1 A^-1 B; 0 1], S = D - C A^-1 B, with A^-1 one AMG
  // cycle and S approximated by D - C diag(A)^-1 B (selfp): Murphy, Golub & Wathen (2000) show
  // the full factorisation with exact blocks converges in one iteration, so the count measures
  // the blocks' approximations only.
  check(PCFieldSplitSetType(pc, PC_COMPOSITE_SCHUR), "PCFieldSplitSetType");
  check(PCFieldSplitSetSchurFactType(pc, PC_FIELDSPLIT_SCHUR_FACT_FULL), "SchurFactType");
  check(PCFieldSplitSetSchurPre(pc, PC_FIELDSPLIT_SCHUR_PRE_SELFP, nullptr), "SchurPre");
  // Sub-solvers by option, so that experts may override them (prefix fieldsplit_u_ / _p_).
  petsc::set_default("-fieldsplit_u_ksp_type", "preonly");
  petsc::set_default("-fieldsplit_u_pc_type", method_ == Method::Hypre ? "hypre" : "gamg");
  petsc::set_default("-fieldsplit_u_mg_levels_pc_type", "sor");
  petsc::set_default("-fieldsplit_p_ksp_type", "preonly");
  petsc::set_default("-fieldsplit_p_pc_type", "jacobi");
}

void PetscSolver::configure(bool symmetric) {
  KSPDestroy(&ksp_);
  check(KSPCreate(PETSC_COMM_SELF, &ksp_), "KSPCreate");
  check(KSPSetOperators(ksp_, matrix_, matrix_), "KSPSetOperators");
  PC pc = nullptr;
  check(KSPGetPC(ksp_, &pc), "KSPGetPC");
  if (method_ == Method::Mumps) {
    check(KSPSetType(ksp_, KSPPREONLY), "KSPSetType(preonly)");
    check(PCSetType(pc, PCLU), "PCSetType(lu)");
    check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType(mumps)");
  } else {
    // The test is on the true residual |b - A x| / |b| (LinearSolver::solve's contract): CG
    // measures it as is, GMRES when preconditioned on the right.
    if (symmetric) {
      check(KSPSetType(ksp_, KSPCG), "KSPSetType(cg)");
    } else {
      check(KSPSetType(ksp_, KSPGMRES), "KSPSetType(gmres)");
      check(KSPGMRESSetRestart(ksp_, gmres_restart), "KSPGMRESSetRestart");
      check(KSPSetPCSide(ksp_, PC_RIGHT), "KSPSetPCSide");
    }
    check(KSPSetNormType(ksp_, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
    if (pressure_)
      configure_field_split(pc);
    else
      configure_amg(pc);
  }
  // The model's (or the command line's) PETSc options override the choices above.
  const PetscErrorCode code = KSPSetFromOptions(ksp_);
  if (code != 0) {
    try {
      check(code, "KSPSetFromOptions");
    } catch (const LinearSolverFailure& e) {
      throw InputError(fmt::format("{} (numerics.petsc_options or --petsc-options)", e.what()));
    }
  }
  configured_ = symmetric ? 1 : 0;
}

void PetscSolver::setup(const SparseMatrix& matrix) {
  if (!matrix_) throw LinearSolverFailure(std::string(name_) + ": setup before analyse");
  if (matrix.nonZeros() != SparseMatrix::Index(csr_.source.size()) -
                               SparseMatrix::Index(csr_.rows - csr_.padded_row.size()) ||
      !matrix.coeffs().allFinite())
    throw LinearSolverFailure(std::string(name_) +
                              ": the matrix is not finite or not of the analysed pattern");
  PetscScalar* values = nullptr;
  check(MatSeqAIJGetArrayWrite(matrix_, &values), "MatSeqAIJGetArrayWrite");
  csr_.fill(matrix, values);
  check(MatSeqAIJRestoreArrayWrite(matrix_, &values), "MatSeqAIJRestoreArrayWrite");
  matrix_of_setup_ = &matrix;
  const bool sym = method_ != Method::Mumps && symmetric(matrix);
  if (configured_ != int(sym)) configure(sym);
  check(KSPSetOperators(ksp_, matrix_, matrix_), "KSPSetOperators");
  // The preconditioner (AMG hierarchy, factorisation) is built here, not at the first solve.
  check(KSPSetUp(ksp_), "KSPSetUp");
}

int PetscSolver::solve(const Vector& b, Vector& x, double relative_tolerance) {
  if (!ksp_) throw LinearSolverFailure(std::string(name_) + ": solve before setup");
  if (b.size() != Index(csr_.padded_row.size()))
    throw LinearSolverFailure(std::string(name_) + ": right-hand side of the wrong size");
  if (b.squaredNorm() == 0.0) {
    x.setZero(b.size());
    return 0;
  }
  PetscScalar* v = nullptr;
  check(VecGetArrayWrite(b_, &v), "VecGetArrayWrite");
  csr_.scatter(b, v);
  check(VecRestoreArrayWrite(b_, &v), "VecRestoreArrayWrite");
  check(KSPSetTolerances(ksp_, relative_tolerance, 1e-300, PETSC_DEFAULT, max_krylov_iterations),
        "KSPSetTolerances");
  check(KSPSolve(ksp_, b_, x_), "KSPSolve");
  KSPConvergedReason reason;
  PetscInt iterations = 0;
  check(KSPGetConvergedReason(ksp_, &reason), "KSPGetConvergedReason");
  // CG needs a positive definite matrix and preconditioner; a symmetric tangent need not be one
  // (softening, a saddle point). Then GMRES, for the rest of the step.
  if ((reason == KSP_DIVERGED_INDEFINITE_PC || reason == KSP_DIVERGED_INDEFINITE_MAT) &&
      configured_ == 1) {
    configure(false);
    symmetric_hint_ = false;
    unsymmetric_for_step_ = true;
    check(KSPSetUp(ksp_), "KSPSetUp");
    return solve(b, x, relative_tolerance);
  }
  check(KSPGetIterationNumber(ksp_, &iterations), "KSPGetIterationNumber");
  if (reason < 0) {
    std::string why = KSPConvergedReasons[reason];
    if (reason == KSP_DIVERGED_PC_FAILED) {
      PC pc = nullptr;
      PCFailedReason failed = PC_NOERROR;
      if (KSPGetPC(ksp_, &pc) == 0 && PCGetFailedReasonRank(pc, &failed) == 0)
        why += std::string(": ") + PCFailedReasons[failed];
    }
    throw LinearSolverFailure(fmt::format(
        "{}: the Krylov solve did not converge ({}) in {} iterations", name_, why, iterations));
  }
  const PetscScalar* r = nullptr;
  check(VecGetArrayRead(x_, &r), "VecGetArrayRead");
  csr_.gather(r, x);
  check(VecRestoreArrayRead(x_, &r), "VecRestoreArrayRead");
  if (!x.allFinite())
    throw LinearSolverFailure(std::string(name_) + ": the solution is not finite");
  // The Krylov method's own residual is a recurrence; on a (nearly) singular system it can drift
  // from the true one (hypre's GMRES reported convergence at a true residual of 5e-3 on the
  // inconsistent system of tests/unit/analysis/test_petsc_solvers.cpp). One product checks it.
  if (method_ != Method::Mumps && matrix_of_setup_) {
    const double true_residual = (*matrix_of_setup_ * x - b).norm() / b.norm();
    if (!(true_residual <= 10.0 * relative_tolerance + 1e-13))
      throw LinearSolverFailure(fmt::format(
          "{}: the Krylov solve stopped at a true relative residual of {:.2e} (asked: {:.2e})",
          name_, true_residual, relative_tolerance));
  }
  if (!options_checked_) {
    options_checked_ = true;
    if (const std::string unused = petsc::unused_options(); !unused.empty())
      throw InputError(
          fmt::format("numerics.petsc_options (or --petsc-options): {} not used by the {} solver "
                      "(misspelt, or meant for another "
                      "solver)",
                      unused, name_));
  }
  return method_ == Method::Mumps ? 1 : std::max<int>(1, int(iterations));
}

}  // namespace

std::unique_ptr<LinearSolver> create_petsc_gamg_solver(const LinearSolverOptions& options) {
  return std::make_unique<PetscSolver>(Method::Gamg, "petsc_gamg", options);
}
std::unique_ptr<LinearSolver> create_petsc_hypre_solver(const LinearSolverOptions& options) {
  return std::make_unique<PetscSolver>(Method::Hypre, "petsc_hypre", options);
}
std::unique_ptr<LinearSolver> create_petsc_mumps_solver(const LinearSolverOptions& options) {
  return std::make_unique<PetscSolver>(Method::Mumps, "petsc_mumps", options);
}

}  // namespace geompm

// The one interface behind which linear solvers sit (docs/architecture.md): Newton knows a sparse
// matrix and vectors only, never whether the solver factorises or iterates.
//
//   analyse(pattern, hints)   once per step: the pattern is fixed for the step (the active cells
//                             change only between steps), and so is what the hints say;
//   setup(matrix)             once per Newton iteration: the operator of the following solves
//                             (a direct solver factorises it, an iterative one builds its
//                             preconditioner);
//   solve(b, x, tolerance)    any number of times against the operator of the last setup;
//                             returns the iterations it took (1 for a direct solver).
//
// Solvers are created by name from a registry (solver/linear_solver_registry.cpp): one file per
// solver, one line there.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "geompm/core/linear_algebra.hpp"
#include "geompm/core/types.hpp"

namespace geompm {

/// A factorisation or a solve failed (singular or non-finite matrix, an iterative solver that did
/// not reach its tolerance): the step is cut back.
class LinearSolverFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A named set of the matrix's unknowns ("displacement", "pressure"; later contact multipliers,
/// structure or rigid-body unknowns), for field-split preconditioners.
struct LinearSolverField {
  std::string name;
  std::vector<Index> unknowns;  // rows of the matrix, ascending
};

/// What a solver may use besides the matrix, all in the matrix's own numbering (its rows are the
/// free unknowns: constrained ones are not in it). A direct solver needs none of it; AMG takes
/// the block size and the rigid-body modes of the displacement field as its near-null space,
/// a field split takes the fields.
struct LinearSolverHints {
  /// Whether the matrix is symmetric (it is not in general: finite strain, non-associated flow,
  /// F-bar and friction make the tangent unsymmetric).
  bool symmetric = false;
  /// Displacement components per node: the block size of the displacement field.
  int block_size = 1;
  /// Per node of the displacement field: its position (rigid-body modes, rigid_body_modes()).
  std::vector<Vec3> node_coordinates;
  /// Per row of the matrix: the node (index into node_coordinates) and component of a
  /// displacement unknown, or -1 for an unknown of another field. A node with a constrained
  /// component has fewer than block_size rows.
  std::vector<Index> unknown_node;
  std::vector<int> unknown_component;
  /// The fields, a partition of the rows.
  std::vector<LinearSolverField> fields;
  /// In a distributed run, per row: the process that owns it (its node's owner; process 0 for
  /// an unknown of no node); empty in a serial run.
  std::vector<int> unknown_process;
};

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  /// Once per step, before the step's first setup: the step's sparsity pattern (every matrix
  /// given to setup until the next analyse has it) and what the hints say about its unknowns.
  virtual void analyse(const SparseMatrix& pattern, const LinearSolverHints& hints) = 0;
  /// The operator of the following solves. The matrix must outlive them: a solver may keep a
  /// reference to it instead of a copy. Throws LinearSolverFailure if it cannot be used.
  virtual void setup(const SparseMatrix& matrix) = 0;
  /// Solves A x = b for the operator A of the last setup, to `relative_tolerance` in the
  /// relative residual |b - A x| / |b| for an iterative solver (a direct solver solves exactly,
  /// as far as round-off goes, and ignores it); x's value on entry is not used. Valid any number
  /// of times after one setup, for direct and iterative solvers alike: Newton re-solves against
  /// the last operator to measure the correction a converged residual asks for. Returns the
  /// iterations used (1 for a direct solver). Throws LinearSolverFailure if it fails.
  virtual int solve(const Vector& b, Vector& x, double relative_tolerance) = 0;
  /// The name it is registered under.
  virtual const char* name() const = 0;
};

/// The unknowns below which `auto` picks the direct solver (UMFPACK) and from which AMG
/// (petsc_hypre). On the 2D elastic block of bench/ UMFPACK's step was as fast as or faster than
/// AMG's at every size measured, 10^4 to 10^6 points; at 10^6 points (5·10^5 unknowns) the two
/// took the same linear-solver time (docs/performance.md, note 17). The limit is that size: AMG
/// where it no longer costs time, and saves memory (a fifth of a step's peak).
inline constexpr Index default_direct_limit = 500000;
/// The same in 3D (a displacement block size of 3), where a direct factorisation fills in far
/// more: on the 3D block of bench/ BoomerAMG's step was as fast as UMFPACK's at 6.6·10^3
/// unknowns (12^3 cells) and twice as fast at 1.5·10^4 (docs/performance.md, note 21).
inline constexpr Index default_direct_limit_3d = 10000;

/// What a solver may be told besides its name (numerics.linear_solver of the model file, or the
/// command line's --linear-solver and --petsc-options).
struct LinearSolverOptions {
  /// PETSc options for experts, in PETSc's command-line syntax ("-ksp_type fgmres"); they override
  /// the PETSc solvers' own choices.
  std::string petsc_options;
  /// `auto`: the direct solver below this many unknowns, AMG from it on; negative: by the
  /// problem's dimension (default_direct_limit, or default_direct_limit_3d in 3D).
  Index direct_limit = -1;
};

/// A registered solver by name: "umfpack" (SuiteSparse sparse direct LU; the default),
/// "sparse_lu" (Eigen's own, no external dependency), "auto" (umfpack or petsc_hypre by size),
/// "petsc_gamg", "petsc_hypre", "petsc_mumps" (petsc_solver.hpp). Throws std::invalid_argument
/// listing the known names.
std::unique_ptr<LinearSolver> create_linear_solver(const std::string& name,
                                                   const LinearSolverOptions& options = {});
/// Whether the named solver is one of PETSc's (or may be: auto), i.e. reads petsc_options.
bool uses_petsc(const std::string& name);
/// Empty if `options` reads as PETSc options ("-key [value] ..."), else what is wrong.
std::string petsc_options_error(const std::string& options);
/// The registered names, the default first (for error messages and the model reader).
std::vector<std::string> linear_solver_names();

}  // namespace geompm

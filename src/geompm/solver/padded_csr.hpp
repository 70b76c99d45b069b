// The layout in which the PETSc backend (petsc_solver.cpp) hands a step's matrix to PETSc:
// compressed sparse rows (PETSc's AIJ; Eigen's matrix here is compressed columns), and with the
// displacement field padded to whole nodes. A constrained displacement component is not in
// geompm's matrix, so a node may have fewer than block_size rows; AMG aggregates nodes (blocks)
// only if every node has all of them. The padded matrix puts node n's component c at row
// n * block_size + c and gives each constrained component an identity row of its own (decoupled:
// its right-hand side and solution are 0), then the rows of the other fields in their order.
//
// Built once per step from the pattern (analyse); each Newton iteration's values are then copied
// through `source` in one pass (setup), never inserted entry by entry. Pure C++, no PETSc: the
// library stays in its own translation unit.
#pragma once

#include <vector>

#include "geompm/core/linear_algebra.hpp"
#include "geompm/solver/linear_solver.hpp"

namespace geompm {

struct PaddedCsr {
  int rows = 0;                 // of the padded matrix
  int displacement_rows = 0;    // nodes x block_size, the padded matrix's first rows
  std::vector<int> row_start;   // rows + 1
  std::vector<int> column;      // per entry, ascending within a row
  std::vector<int> source;      // per entry: its index in the CSC values, or -1 (identity)
  std::vector<int> padded_row;  // per row of geompm's matrix: its row here
  std::vector<int> diagonal;    // the CSC indices of geompm's matrix's diagonal entries

  /// The layout of `pattern` (compressed, square, rows in the numbering of `hints`).
  static PaddedCsr build(const SparseMatrix& pattern, const LinearSolverHints& hints);
  /// Copies `matrix`'s values (the pattern's) into `to` (one value per entry, in this layout's
  /// order); the identity rows get the mean of the matrix's diagonal, so that they are of its
  /// size and do not distort a smoother's or a Krylov method's scaling.
  void fill(const SparseMatrix& matrix, double* to) const;
  /// b in geompm's numbering to the padded one (0 in padding rows), and back.
  void scatter(const Vector& from, double* to) const;
  void gather(const double* from, Vector& to) const;
  /// The padded rows of a field's unknowns (ascending in geompm's numbering).
  std::vector<int> rows_of(const std::vector<Index>& unknowns) const;
};

/// Per entry of a compressed matrix: the index of its transpose's entry, -1 if not in the pattern.
std::vector<int> transpose_entries(const SparseMatrix& pattern);
/// Whether each entry equals its transpose's to round-off (1e-12 of the largest entry); a
/// missing transpose counts as 0.
bool is_symmetric(const SparseMatrix& matrix, const std::vector<int>& transpose);

}  // namespace geompm

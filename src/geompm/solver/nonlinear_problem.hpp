// What Newton solves: a residual R(x) and its tangent K = -dR/dx in vectors and a sparse matrix,
// with the diagnostics the log (newton.csv) shows. The physics implements it
// (analysis/step.cpp: the Lagrangian phase); Newton and its line searches only call it.
#pragma once

#include <string>

#include "geompm/core/linear_algebra.hpp"
#include "geompm/core/types.hpp"

namespace geompm {

/// Newton's active set at an iterate: for a nonsmooth residual (return mapping), the members on
/// the nonsmooth side and how many switched since the iterate before. -1: not known.
struct ActiveSet {
  Index size = -1;
  Index changed = -1;
};

class NonlinearProblem {
 public:
  virtual ~NonlinearProblem() = default;
  /// Residual R(x) (out-of-balance force at the free unknowns), a force scale for the relative
  /// criterion, and the tangent K = -dR/dx when `tangent` is not null (its pattern fixed for the
  /// step). Returns false if x is inadmissible (a point turned inside out, or its stress update
  /// failed).
  virtual bool evaluate(const Vector& x, Vector& residual, double& force_scale,
                        SparseMatrix* tangent) = 0;
  /// After evaluate() returned false: why, for the failure message.
  virtual std::string inadmissible_reason() const {
    return "inadmissible deformation (a point's volume became <= 0)";
  }
  /// Norm of the whole increment of the step at x (prescribed parts included).
  virtual double increment_norm(const Vector& x) const = 0;
  /// The unknown with the largest residual at the last evaluation, in the problem's own
  /// numbering, or -1 if the problem does not say (for diagnostics only).
  virtual Index largest_residual_unknown() const { return -1; }
  /// The free unknown `free` (an index into x) in the problem's own numbering, as
  /// largest_residual_unknown() (for diagnostics only).
  virtual Index problem_unknown(Index free) const { return free; }
  /// For diagnostics: the size of the active set of the last evaluation (in plasticity the
  /// points returned plastically) and how many members entered or left it since the last call
  /// (-1 if the problem does not say; Newton sets -1 at a solve's first iterate). Called once
  /// per iterate that Newton logs.
  virtual ActiveSet active_set() { return {}; }
};

}  // namespace geompm

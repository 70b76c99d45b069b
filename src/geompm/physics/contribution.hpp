// One term of a step's residual and tangent (docs/architecture.md, "Contributions"): the
// material points' internal force, inertia, gravity and point loads, the empty-cell stiffness,
// the springs and penalties that keep sparse nodes in place, prescribed point motions, contact.
// The Lagrangian phase solves R(du) = f_ext - f_int - M a = 0 (seed eq. 6) with every sum the
// sum of the step's contributions; each knows the unknowns only through the step's DofMap.
//
// A contribution lives for one step: it is made when the step's grid and unknowns are known
// (analysis/step_contributions.cpp lists the makers, one line each), declares its couplings,
// adds its forces and stiffness at every Newton evaluation, and at the converged increment
// reports its reactions and commits what it must carry into the next step.
#pragma once

#include <map>
#include <string>

#include "geompm/core/types.hpp"
#include "geompm/dofs/sparsity.hpp"

namespace geompm {

/// The three sums of the residual, per unknown of the step (every unknown, constrained ones
/// included: their entries are the reactions).
struct SystemForces {
  Vector internal;  // f_int: the body's resistance, springs, penalties, contact
  Vector inertia;   // M a
  Vector external;  // f_ext: gravity and applied loads

  /// Zeroes the sums, keeping their storage from one Newton evaluation to the next.
  void reset(Index size) {
    for (Vector* v : {&internal, &inertia, &external}) {
      if (v->size() != size) v->resize(size);
      v->setZero();
    }
  }
};

/// Forces the contributions report at the converged increment, for histories.
struct Reactions {
  std::map<int, Vec3> point_sets;        // point-set bit -> force its prescribed motion exerts
  std::map<std::string, Vec3> contacts;  // structure -> force the soil exerts on it by contact
};

class Contribution {
 public:
  virtual ~Contribution() = default;
  virtual const char* name() const = 0;

  /// Whether its forces are a sum over the material points this process holds, which a
  /// distributed run sums over the processes (docs/architecture.md, "Distributed runs"); the
  /// terms of the grid alone, which every process holds whole, are added by process 0 only.
  virtual bool sums_own_points() const { return false; }
  /// The couplings it adds to the tangent's pattern, once a step.
  virtual void declare_couplings(SparsityBuilder& /*pattern*/) const {}
  /// The pattern is built: where its own entries go can be found once for the step.
  virtual void attach(const SparseMatrix& /*pattern*/) {}
  /// Adds its forces at the step's increment `du` (every unknown) into `forces` and, with
  /// `tangent`, its stiffness d(f_int + M a - f_ext)/d du at the free unknowns. False: `du` is
  /// inadmissible for it (a veto; Newton backtracks or the step is cut back).
  virtual bool add(const Vector& du, SystemForces& forces, SparseMatrix* tangent) = 0;
  /// At the converged increment: the forces it exerts, for histories.
  virtual void report(const Vector& /*du*/, Reactions& /*reactions*/) {}
  /// The step is accepted: keep what the next step needs.
  virtual void commit() {}
};

}  // namespace geompm

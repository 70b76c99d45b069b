// Terms the point integrator assembles cell by cell together with the material points, into one
// local vector and matrix per cell and one scatter (like the domain integrators of a finite
// element form): their sums then come out in the same order whatever else the step holds, and
// they run on all threads with the cells. A CellTerm is a constant matrix on a cell's unknowns (the
// empty-cell stiffness, seed §3.2); a PointTerm a force at a point that depends on the point's
// displacement (a prescribed point motion's spring, docs/theory.md eq. 5.1).
#pragma once

#include "geompm/core/types.hpp"

namespace geompm {

class CellTerm {
 public:
  virtual ~CellTerm() = default;
  /// Active cell ci's matrix over its unknowns in local order (the displacements node by node,
  /// then the pressures; column-major), constant over the step and acting on the step's
  /// increment, or null for none.
  virtual const double* cell_block(Index ci) const = 0;
};

class PointTerm {
 public:
  virtual ~PointTerm() = default;
  /// Whether the term acts on point p.
  virtual bool acts(Index p) const = 0;
  /// The force at the point as it enters f_int (minus the force on the point) and its stiffness
  /// d force / d u, u = sum_a N_a du_a the point's displacement over the step. Called from several
  /// threads at once, each point by one thread only.
  virtual void force(Index p, const Vec3& u, Vec3& force, Mat3& stiffness) = 0;
};

}  // namespace geompm

// The nodal pressure field of the mixed p-u formulation (docs/theory.md §11): each active node
// carries an unknown x_p, the pressure's change over the step divided by a scale s = G / h, so
// that it is a length like the displacements and its equation, multiplied by s, a force (eq.
// 11.6): p = p_start + s x_p. This object knows s, the start values p_start of the step, and the
// last converged field that the fitted start (eq. 11.11) carries from one step to the next.
#pragma once

#include <vector>

#include "geompm/dofs/dof_map.hpp"
#include "geompm/physics/grid_system.hpp"

namespace geompm {

class PressureField {
 public:
  /// Phase 1: the scale from the stiffest mixed soil of the step and the start values: the
  /// points' pressures averaged onto the nodes with weights N v (eq. 11.6), or, with the fitted
  /// start, the last converged field smoothed where it was well supported (eq. 11.11).
  void initialise(const GridSystem& grid, const MaterialPoints& points);
  /// Phase 3: remembers the converged nodal pressure where it was well supported (eq. 11.11).
  void remember(const GridSystem& grid, const DofMap& dofs, const Vector& du);
  /// Forgets the last converged field, so that a phase's first step starts from its points.
  void forget() { last_.clear(); }

  /// s = G / h (eq. 11.6).
  double scale() const { return scale_; }
  /// K of the stiffest mixed soil: the pressure regularisation of empty space (eq. 11.7).
  double reference_bulk() const { return reference_bulk_; }
  /// The nodal pressure at the start of the step, per active node.
  const Vector& start() const { return start_; }
  /// Nodal pressures (compression positive) per active node at the step's unknowns `du`
  /// (every unknown of `dofs`): p = p_start + s x_p.
  Vector nodal_pressure(const DofMap& dofs, const Vector& du) const;

  /// The last converged field per mesh node (NaN where not well supported), for checkpoints.
  const std::vector<double>& last() const { return last_; }
  void set_last(std::vector<double> last) { last_ = std::move(last); }

 private:
  void mark_supported_nodes(const GridSystem& grid);

  double scale_ = 1.0;
  double reference_bulk_ = 1.0;
  Vector start_;
  bool fitted_start_ = false;
  std::vector<double> last_;
  std::vector<char> supported_;  // per active node of the step
};

/// The pressure field's id in a DofMap ("pressure"); -1 without one.
inline int pressure_field(const DofMap& dofs) { return dofs.find("pressure"); }

}  // namespace geompm

// The FEM region's terms in a step (seed §3.4, docs/theory.md §19): the internal force and
// consistent tangent of its Gauss points (physics/gauss_cell.hpp, the material points' kernel on
// the cells' configuration at the start of the step, eqs. 19.2-19.3) and their self-weight under
// the phase's gravity (f_ext, eq. 19.4), on the grid's displacement unknowns: a node an FEM cell
// shares with an MPM cell is one unknown of one monolithic system. At the converged step it
// writes the Gauss points' new states into the region's store; the nodes are moved by the step
// (analysis/step.cpp), before the points are relocated. In a distributed run each process adds
// and commits the cells it owns (FemRegion::keep_own).
#pragma once

#include <vector>

#include "geompm/coupling/fem_region.hpp"
#include "geompm/physics/contribution.hpp"
#include "geompm/physics/grid_system.hpp"

namespace geompm {

class FemRegionTerm final : public Contribution {
 public:
  /// `gravity` at the end of the step. Every node of the region's cells must be active in
  /// `grid` (GridSystem activates FEM cells).
  FemRegionTerm(FemRegion& region, const GridSystem& grid, const DofMap& dofs, const Vec3& gravity);
  const char* name() const override { return "fem region"; }
  /// Its forces are sums over the Gauss points of the cells this process works on (FemRegion::
  /// keep_own), as the material points' are over the points it holds.
  bool sums_own_points() const override { return true; }
  void declare_couplings(SparsityBuilder& pattern) const override;
  /// Finds where each cell's stiffness entries go in the step's pattern, once a step.
  void attach(const SparseMatrix& pattern) override;
  bool add(const Vector& du, SystemForces& forces, SparseMatrix* tangent) override;
  void report(const Vector& du, Reactions& reactions) override;
  void commit() override;

  /// Writes into the region's Gauss points the state at `du` (every unknown of the step): stress,
  /// F, b_e, internal variables, position and volume. False where a point is inadmissible.
  bool commit_state(const Vector& du);

 private:
  // Adds the cells' internal forces (and tangent) at du; writes the states if `commit`.
  bool add_cells(const Vector& du, SystemForces* forces, SparseMatrix* tangent, bool commit);
  // The same for region cell k (element E).
  template <class E>
  bool add_cell(Index k, const Vector& du, SystemForces* forces, SparseMatrix* tangent,
                bool commit);

  FemRegion& region_;
  const GridSystem& grid_;
  const DofMap& dofs_;
  // Per FEM cell k, entries [cell_start_[k], cell_start_[k + 1]) of cell_dofs_, X_ and applied_
  // (its nodes' unknowns; a mixed mesh's cells have different counts), and from slot_start_[k]
  // its square of slots_.
  std::vector<std::size_t> cell_start_, slot_start_;
  std::vector<Index> cell_dofs_;  // per FEM cell: its nodes' displacement unknowns, node-major
  std::vector<double> X_;         // per FEM cell: its nodes' positions at the step's start
  std::vector<char> averaged_;    // per FEM cell: its material takes the cell's volume average
  std::vector<int> slots_;        // per FEM cell: its unknowns^2 slots in the tangent's values
  std::vector<std::vector<Index>> colours_;  // the region's cells (k) by the grid's colours
  Vector applied_;                           // self-weight per entry of cell_dofs_
  Vector converged_;
  bool reported_ = false;
};

}  // namespace geompm

// The tangent's sparsity pattern for a step, over the free unknowns of a DofMap: every
// contribution declares the couplings it adds (docs/architecture.md, "Contributions") and the
// pattern is built once, before Newton, and filled by every iteration. Nodes that share a cell,
// a point's stencil or a penalty face couple every nodal unknown of one with every nodal unknown
// of the other; unknowns of other fields (a rigid body, a contact multiplier) couple unknown by
// unknown.
#pragma once

#include <span>
#include <vector>

#include "geompm/core/linear_algebra.hpp"
#include "geompm/dofs/dof_map.hpp"

namespace geompm {

class SparsityBuilder {
 public:
  explicit SparsityBuilder(const DofMap& dofs);

  /// Every nodal unknown of each of these active nodes couples with every nodal unknown of each.
  void couple_nodes(std::span<const Index> nodes);
  /// Each of these unknowns couples with each (any fields).
  void couple_unknowns(std::span<const Index> unknowns);

  /// The pattern over the free unknowns (columns and, in each, rows in ascending free index),
  /// with zero values.
  SparseMatrix build();

 private:
  const DofMap& dofs_;
  std::vector<std::vector<Index>> node_neighbours_;  // per active node
  std::vector<std::vector<Index>> extra_;            // per unknown: coupled unknowns
};

/// Adds `value` to entry (row, col) of a tangent over the free unknowns, both given as unknowns
/// of `dofs`; nothing where either is constrained. Throws std::logic_error if the pattern has no
/// such entry (a contribution that did not declare its coupling).
void add_to_tangent(SparseMatrix& tangent, const DofMap& dofs, Index row, Index col, double value);

/// Where the entries among `unknowns` (m of them, their couplings declared) lie in the pattern's
/// values: slots[c * m + r] for row unknowns[r] and column unknowns[c], -1 where either is
/// constrained. Found once a step (a contribution's attach), so that each Newton iteration adds a
/// block's entries without add_to_tangent's search per entry. Throws std::logic_error as
/// add_to_tangent does.
void block_slots(const SparseMatrix& pattern, const DofMap& dofs, std::span<const Index> unknowns,
                 int* slots);

}  // namespace geompm

#include "geompm/dofs/sparsity.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace geompm {

SparsityBuilder::SparsityBuilder(const DofMap& dofs)
    : dofs_(dofs), node_neighbours_(dofs.active_nodes().size()) {}

void SparsityBuilder::couple_nodes(std::span<const Index> nodes) {
  for (Index a : nodes)
    node_neighbours_[a].insert(node_neighbours_[a].end(), nodes.begin(), nodes.end());
}

void SparsityBuilder::couple_unknowns(std::span<const Index> unknowns) {
  if (extra_.empty()) extra_.resize(dofs_.size());
  for (Index d : unknowns) extra_[d].insert(extra_[d].end(), unknowns.begin(), unknowns.end());
}

SparseMatrix SparsityBuilder::build() {
  for (auto& list : node_neighbours_) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  std::vector<int> nodal;  // the nodal fields, in the order of their unknowns
  for (int f = 0; f < dofs_.num_fields(); ++f)
    if (dofs_.field(f).nodal) nodal.push_back(f);
  // Columns in the order of their free index; rows ascending: the nodal fields' unknowns are
  // numbered field by field, node by node, so walking fields, then neighbours, then components
  // gives them in order; couplings of other fields are merged in.
  const Index n_free = dofs_.num_free();
  std::vector<int> outer(n_free + 1, 0);
  std::vector<int> inner;
  std::vector<Index> rows;
  for (Index col = 0; col < n_free; ++col) {
    const Index d = dofs_.dof_of_free(col);
    const Unknown u = dofs_.unknown(d);
    rows.clear();
    if (dofs_.field(u.field).nodal)
      for (int f : nodal)
        for (Index b : node_neighbours_[u.entity])
          for (int k = 0; k < dofs_.field(f).components; ++k)
            if (const Index row = dofs_.free_index(dofs_.dof(f, b, k)); row >= 0)
              rows.push_back(row);
    if (!extra_.empty() && !extra_[d].empty()) {
      for (Index e : extra_[d])
        if (const Index row = dofs_.free_index(e); row >= 0) rows.push_back(row);
      std::sort(rows.begin(), rows.end());
      rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    }
    inner.insert(inner.end(), rows.begin(), rows.end());
    outer[col + 1] = static_cast<int>(inner.size());
  }
  SparseMatrix pattern(n_free, n_free);
  pattern.resizeNonZeros(static_cast<Index>(inner.size()));
  // Returned by move (Eigen's copy would copy every entry once more).
  std::copy(outer.begin(), outer.end(), pattern.outerIndexPtr());
  std::copy(inner.begin(), inner.end(), pattern.innerIndexPtr());
  std::fill(pattern.valuePtr(), pattern.valuePtr() + inner.size(), 0.0);
  return pattern;
}

namespace {

// The position of entry (row, col), free indices, in the pattern's values.
int value_slot(const SparseMatrix& pattern, Index row, Index col, const char* who) {
  const int* inner = pattern.innerIndexPtr();
  const int* end = inner + pattern.outerIndexPtr()[col + 1];
  const int* at = std::lower_bound(inner + pattern.outerIndexPtr()[col], end, row);
  if (at == end || *at != row)
    throw std::logic_error(std::string(who) + ": a coupling that is not in the pattern");
  return static_cast<int>(at - inner);
}

}  // namespace

void add_to_tangent(SparseMatrix& tangent, const DofMap& dofs, Index row, Index col, double value) {
  const Index r = dofs.free_index(row), c = dofs.free_index(col);
  if (r < 0 || c < 0) return;
  tangent.valuePtr()[value_slot(tangent, r, c, "add_to_tangent")] += value;
}

void block_slots(const SparseMatrix& pattern, const DofMap& dofs, std::span<const Index> unknowns,
                 int* slots) {
  const std::size_t m = unknowns.size();
  for (std::size_t c = 0; c < m; ++c) {
    const Index col = dofs.free_index(unknowns[c]);
    for (std::size_t r = 0; r < m; ++r) {
      const Index row = dofs.free_index(unknowns[r]);
      slots[c * m + r] = row < 0 || col < 0 ? -1 : value_slot(pattern, row, col, "block_slots");
    }
  }
}

}  // namespace geompm

// The empty-cell stiffness (seed §3.2): a small linear elastic stiffness in empty and partly
// filled cells keeps the system regular where the points leave nodes nearly unsupported. Built
// once a step on the grid of the step, it acts on the step's increment; the point integrator
// assembles it with the cell's points (a CellTerm).
#pragma once

#include <cstdint>
#include <vector>

#include "geompm/core/tensor.hpp"
#include "geompm/dofs/dof_map.hpp"
#include "geompm/physics/grid_system.hpp"
#include "geompm/physics/local_terms.hpp"
#include "geompm/physics/pressure_field.hpp"

namespace geompm {

class EmptyCellStiffness final : public CellTerm {
 public:
  /// `pressure`: the step's pressure field when the DofMap has one, else null.
  EmptyCellStiffness(const GridSystem& grid, const DofMap& dofs, const PressureField* pressure);
  const double* cell_block(Index ci) const override {
    return offset_[ci] < 0 ? nullptr : stiffness_.data() + std::size_t(offset_[ci]) * m_ * m_;
  }
  /// Whether no cell carries any (full cells get none).
  bool empty() const { return stiffness_.empty(); }

 private:
  void build();
  /// Active cell ci's block (its own unknowns square, at the cell's stride), of type E.
  template <class E>
  void build_cell(Index ci, const Tensor4& C, double pressure_factor);
  /// The share of active cell ci the displacement and pressure terms hold: the fraction not
  /// covered by (mixed) points, 0 below 1e-9 (a full cell's round-off) or with the term off.
  double displacement_weight(Index ci) const;
  double pressure_weight(Index ci) const;
  int cell_unknowns() const { return m_; }

  const GridSystem& grid_;
  const PressureField* pressure_;
  int m_;  // unknowns per cell (of the largest cell of a mixed mesh): the blocks' stride
  std::vector<std::int64_t> offset_;  // per active cell: its block in stiffness_, or -1 (none)
  std::vector<double> stiffness_;     // m_^2 per cell with (1 - fill) > 0
};

}  // namespace geompm

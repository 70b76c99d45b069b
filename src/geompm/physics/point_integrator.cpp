#include "geompm/physics/point_integrator.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>

#include "geompm/mesh/element.hpp"
#include "geompm/physics/point_kernel.hpp"

namespace geompm {

PointIntegrator::PointIntegrator(const GridSystem& grid, const MaterialPoints& points,
                                 const DofMap& dofs, const PressureField* pressure)
    : grid_(grid),
      points_(points),
      dofs_(dofs),
      pressure_(pressure),
      dim_(grid.dim()),
      nen_(grid.nodes_per_cell()),
      displacement_(dofs.find("displacement")),
      pressure_field_(pressure_field(dofs)),
      plastic_(points.size(), 0) {
  if (pressure_field_ < 0) pressure_ = nullptr;
}

void PointIntegrator::declare_couplings(SparsityBuilder& pattern) const {
  const auto& node_to_active = grid_.node_to_active();
  std::vector<Index> nodes;
  for (Index c : grid_.active_cells()) {
    if (!grid_.owns_cell(c)) continue;  // another process's (add_cell)
    nodes.clear();
    for (Index node : grid_.mesh().cell_nodes(c)) nodes.push_back(node_to_active[node]);
    pattern.couple_nodes(nodes);
  }
  if (grid_.wide_stencil())
    for (Index p = 0; p < points_.size(); ++p)
      pattern.couple_nodes({grid_.wide_nodes().data() + grid_.wide_begin(p),
                            static_cast<std::size_t>(grid_.wide_end(p) - grid_.wide_begin(p))});
  // The volume average couples the stencils of a cell's averaged points (theory §12).
  for (Index ci = 0; ci < static_cast<Index>(grid_.active_cells().size()); ++ci)
    pattern.couple_nodes(grid_.averaged_stencil_union(ci));
}

void PointIntegrator::attach(const SparseMatrix& pattern) {
  // Scatter maps: local (row, column) of each active cell -> position in the values array.
  const int m = cell_unknowns();
  const Index n_active = static_cast<Index>(grid_.active_cells().size());
  const auto& node_to_active = grid_.node_to_active();
  scatter_.assign(std::size_t(n_active) * m * m, -1);
#pragma omp parallel for schedule(dynamic, 64) if (n_active > 256)
  for (Index ci = 0; ci < n_active; ++ci) {
    if (!grid_.owns_cell(grid_.active_cells()[ci])) continue;
    const auto nodes = grid_.mesh().cell_nodes(grid_.active_cells()[ci]);
    const int nen = static_cast<int>(nodes.size());  // of a mixed mesh, below nen_
    const int m_cell = cell_unknowns(nen);
    std::array<Index, 27> active{};
    for (int a = 0; a < nen; ++a) active[a] = node_to_active[nodes[a]];
    std::array<Index, 27 * 4> free{};  // per local unknown: its free index (-1: constrained)
    for (int l = 0; l < m_cell; ++l) free[l] = dofs_.free_index(local_dof(active, nen, l));
    for (int lc = 0; lc < m_cell; ++lc) {
      const Index col = free[lc];
      if (col < 0) continue;
      const int* begin = pattern.innerIndexPtr() + pattern.outerIndexPtr()[col];
      const int* end = pattern.innerIndexPtr() + pattern.outerIndexPtr()[col + 1];
      for (int lr = 0; lr < m_cell; ++lr) {
        const Index row = free[lr];
        if (row < 0) continue;
        const int* at = std::lower_bound(begin, end, row);
        scatter_[(std::size_t(ci) * m + lc) * m + lr] =
            static_cast<int>(at - pattern.innerIndexPtr());
      }
    }
  }
}

bool PointIntegrator::add(const Vector& du, SystemForces& forces, SparseMatrix* tangent) {
  inadmissible_point_ = -1;
  // A mixed mesh's cells one type at a time (add_cells skips the others).
  bool cells_ok = true;
  for (CellType type : grid_.mesh().types_present())
    cells_ok = dispatch_cell_type(type,
                                  [&](auto e) {
                                    using E = decltype(e);
                                    return pressure_
                                               ? add_cells<E, true>(du, forces.internal, tangent)
                                               : add_cells<E, false>(du, forces.internal, tangent);
                                  }) &&
               cells_ok;
  if (!grid_.wide_stencil()) return cells_ok;
  const bool wide_ok = dim_ == 3 ? add_wide_stencil_points<3>(du, forces.internal, tangent)
                                 : add_wide_stencil_points<2>(du, forces.internal, tangent);
  return cells_ok && wide_ok;
}

bool PointIntegrator::commit_state(MaterialPoints& points, const Vector& du) {
  // Each point reads its start state before its state is written, and belongs to one cell (or
  // one wide stencil pass), so writing through while evaluating is safe.
  commit_to_ = &points;
  SystemForces forces;
  forces.reset(dofs_.size());
  const bool admissible = add(du, forces, nullptr);
  commit_to_ = nullptr;
  return admissible;
}

void PointIntegrator::commit(Index p, const FiniteStrainState& state, double volume,
                             const Mat3& stress, double own_volume, double volume_mismatch) const {
  plastic_[p] = state.plastic ? 1 : 0;  // each point by one thread only
  if (!commit_to_) return;
  commit_to_->volume_mismatch[p] = volume_mismatch;
  commit_to_->domain_stretch[p] *= std::pow(own_volume / volume, 1.0 / dim_);
  commit_to_->stress[p] = stress;
  commit_to_->deformation_gradient[p] = state.deformation_gradient;
  commit_to_->elastic_left_cauchy_green[p] = state.elastic_left_cauchy_green;
  commit_to_->internal[p] = state.internal;
  commit_to_->volume[p] = volume;
}

PointStartState PointIntegrator::start_state(Index p) const {
  return {grid_.materials()[points_.material[p]],
          points_.position[p],
          points_.volume[p],
          points_.deformation_gradient[p],
          points_.elastic_left_cauchy_green[p],
          points_.internal[p],
          points_.volume_mismatch[p]};
}

void PointIntegrator::note_inadmissible(Index p, bool stress_update_failed) const {
#pragma omp critical(geompm_inadmissible_point)
  if (inadmissible_point_ < 0 || p < inadmissible_point_) {
    inadmissible_point_ = p;
    inadmissible_by_stress_update_ = stress_update_failed;
  }
}

}  // namespace geompm

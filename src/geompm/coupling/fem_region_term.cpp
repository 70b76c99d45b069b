#include "geompm/coupling/fem_region_term.hpp"

#include <atomic>
#include <span>
#include <stdexcept>

#include "geompm/dofs/sparsity.hpp"
#include "geompm/mesh/cell_dispatch.hpp"
#include "geompm/mesh/element.hpp"
#include "geompm/physics/gauss_cell.hpp"

namespace geompm {

FemRegionTerm::FemRegionTerm(FemRegion& region, const GridSystem& grid, const DofMap& dofs,
                             const Vec3& gravity)
    : region_(region), grid_(grid), dofs_(dofs) {
  const Mesh& mesh = grid.mesh();
  const int dim = grid.dim();
  const int field = dofs.find("displacement");
  const MaterialPoints& gauss = region.gauss_points();
  cell_start_.assign(1, 0);
  slot_start_.assign(1, 0);
  for (std::size_t k = 0; k < region.cells().size(); ++k) {
    const Index c = region.cells()[k];
    const auto nodes = mesh.cell_nodes(c);
    const std::size_t size = nodes.size() * dim;  // a mixed mesh's cells differ
    cell_start_.push_back(cell_start_.back() + size);
    slot_start_.push_back(slot_start_.back() + size * size);
    for (Index a : nodes) {
      const Index active = grid.node_to_active()[a];
      if (active < 0) throw std::logic_error("fem region: a node of an FEM cell is not active");
      for (int i = 0; i < dim; ++i) cell_dofs_.push_back(dofs.dof(field, active, i));
      for (int i = 0; i < dim; ++i) X_.push_back(mesh.nodes[a](i));
    }
    averaged_.push_back(grid.settings().volume_average[gauss.material[region.gauss_begin(k)]]);
  }
  // The region's cells by the grid's colours (no two cells of a colour share a node).
  std::vector<Index> of_cell(mesh.num_cells(), -1);
  for (std::size_t k = 0; k < region.cells().size(); ++k)
    of_cell[region.cells()[k]] = static_cast<Index>(k);
  // In a distributed run, this process's cells only (FemRegion::keep_own).
  for (const std::vector<Index>& colour : grid.colours()) {
    colours_.emplace_back();
    for (Index ci : colour)
      if (const Index k = of_cell[grid.active_cells()[ci]]; k >= 0 && region.own(k))
        colours_.back().push_back(k);
  }
  // Self-weight f_a = sum_q m_q N_a(xi_q) g (eq. 19.4): the Gauss points' masses are constant.
  applied_ = Vector::Zero(static_cast<Index>(cell_dofs_.size()));
  for_each_cell_typed(
      mesh, static_cast<Index>(region.cells().size()), [&](Index k) { return region.cells()[k]; },
      [&](auto element, Index k) {
        using E = decltype(element);
        if (!region.own(k)) return;
        double* cell = applied_.data() + cell_start_[k];
        for (Index g = region.gauss_begin(k); g < region.gauss_begin(k + 1); ++g) {
          const typename E::Values N = E::shape(gauss.local[g].template head<E::dim>());
          for (int a = 0; a < E::nodes; ++a)
            for (int i = 0; i < dim; ++i) cell[a * dim + i] += gauss.mass[g] * N(a) * gravity(i);
        }
      });
}

void FemRegionTerm::declare_couplings(SparsityBuilder& pattern) const {
  std::vector<Index> block;
  for (std::size_t k = 0; k + 1 < cell_start_.size(); ++k) {
    if (!region_.own(k)) continue;
    block.assign(cell_dofs_.begin() + cell_start_[k], cell_dofs_.begin() + cell_start_[k + 1]);
    pattern.couple_unknowns(block);
  }
}

void FemRegionTerm::attach(const SparseMatrix& pattern) {
  const std::size_t cells = region_.cells().size();
  slots_.resize(slot_start_.back());
  for (std::size_t k = 0; k < cells; ++k)
    if (region_.own(k))  // the pattern holds this process's cells' blocks only
      block_slots(pattern, dofs_,
                  std::span<const Index>(cell_dofs_.data() + cell_start_[k],
                                         cell_start_[k + 1] - cell_start_[k]),
                  slots_.data() + slot_start_[k]);
}

bool FemRegionTerm::add_cells(const Vector& du, SystemForces* forces, SparseMatrix* tangent,
                              bool commit) {
  // One colour at a time, its cells (which share no node) on all threads: every entry of the
  // force and the tangent is summed in the same order whatever the number of threads.
  std::atomic<bool> admissible{true};
  for (const std::vector<Index>& colour : colours_)
    for_each_cell_typed(
        grid_.mesh(), static_cast<Index>(colour.size()),
        [&](Index j) { return region_.cells()[colour[j]]; },
        [&](auto element, Index j) {
          if (!add_cell<decltype(element)>(colour[j], du, forces, tangent, commit))
            admissible = false;
        },
        colour.size() > 64);
  return admissible.load();
}

template <class E>
bool FemRegionTerm::add_cell(Index k, const Vector& du, SystemForces* forces, SparseMatrix* tangent,
                             bool commit) {
  constexpr int n = E::nodes * E::dim;
  MaterialPoints& gauss = region_.gauss_points();
  Eigen::Matrix<double, E::nodes, E::dim> X, u;
  PointKernelResult<E> cell;
  const Index* dofs = cell_dofs_.data() + cell_start_[k];
  const double* x = X_.data() + cell_start_[k];
  for (int a = 0; a < E::nodes; ++a)
    for (int i = 0; i < E::dim; ++i) {
      X(a, i) = x[a * E::dim + i];
      u(a, i) = du(dofs[a * E::dim + i]);
    }
  const Index first = region_.gauss_begin(k);
  const auto start_of = [&](int q) {
    const Index g = first + q;
    return PointStartState{
        grid_.materials()[gauss.material[g]], Vec3::Zero(),     0.0, gauss.deformation_gradient[g],
        gauss.elastic_left_cauchy_green[g],   gauss.internal[g]};
  };
  const auto on_state = [&](int q, const PointKernelResult<E>& r) {
    if (!commit) return;
    const Index g = first + q;
    gauss.stress[g] = r.state.cauchy_stress;
    gauss.deformation_gradient[g] = r.state.deformation_gradient;
    gauss.elastic_left_cauchy_green[g] = r.state.elastic_left_cauchy_green;
    gauss.internal[g] = r.state.internal;
    gauss.volume[g] = r.volume;
    Vec3 dx = Vec3::Zero();
    const typename E::Values N = E::shape(gauss.local[g].template head<E::dim>());
    dx.head<E::dim>() = u.transpose() * N;
    gauss.position[g] += dx;
    gauss.displacement[g] += dx;
    gauss.phase_displacement[g] += dx;
  };
  if (!integrate_gauss_cell<E>(X, u, grid_.axisymmetric(), tangent != nullptr, averaged_[k] != 0,
                               start_of, cell, on_state))
    return false;
  scatter_cell<E>(cell, dofs, dofs_, forces ? &forces->internal : nullptr, tangent,
                  slots_.empty() ? nullptr : slots_.data() + slot_start_[k]);
  return true;
}

bool FemRegionTerm::add(const Vector& du, SystemForces& forces, SparseMatrix* tangent) {
  if (!add_cells(du, &forces, tangent, false)) return false;
  for (std::size_t k = 0; k < cell_dofs_.size(); ++k) forces.external(cell_dofs_[k]) += applied_(k);
  return true;
}

bool FemRegionTerm::commit_state(const Vector& du) { return add_cells(du, nullptr, nullptr, true); }

void FemRegionTerm::report(const Vector& du, Reactions& /*reactions*/) {
  converged_ = du;
  reported_ = true;
}

void FemRegionTerm::commit() {
  if (reported_ && !commit_state(converged_))
    throw std::logic_error("fem region: a converged increment is inadmissible");
}

}  // namespace geompm

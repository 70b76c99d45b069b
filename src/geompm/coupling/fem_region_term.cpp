#include "geompm/coupling/fem_region_term.hpp"

#include <atomic>
#include <span>
#include <stdexcept>

#include "geompm/dofs/sparsity.hpp"
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
  const int nq = region.points_per_cell();
  cell_size_ = mesh.nodes_per_cell() * dim;
  for (std::size_t k = 0; k < region.cells().size(); ++k) {
    const Index c = region.cells()[k];
    const auto nodes = mesh.cell_nodes(c);
    for (Index a : nodes) {
      const Index active = grid.node_to_active()[a];
      if (active < 0) throw std::logic_error("fem region: a node of an FEM cell is not active");
      for (int i = 0; i < dim; ++i) cell_dofs_.push_back(dofs.dof(field, active, i));
      for (int i = 0; i < dim; ++i) X_.push_back(mesh.nodes[a](i));
    }
    const Index first = static_cast<Index>(k) * nq;
    averaged_.push_back(grid.settings().volume_average[gauss.material[first]]);
  }
  // The region's cells by the grid's colours (no two cells of a colour share a node).
  std::vector<Index> of_cell(mesh.num_cells(), -1);
  for (std::size_t k = 0; k < region.cells().size(); ++k)
    of_cell[region.cells()[k]] = static_cast<Index>(k);
  for (const std::vector<Index>& colour : grid.colours()) {
    colours_.emplace_back();
    for (Index ci : colour)
      if (const Index k = of_cell[grid.active_cells()[ci]]; k >= 0) colours_.back().push_back(k);
  }
  // Self-weight f_a = sum_q m_q N_a(xi_q) g (eq. 19.4): the Gauss points' masses are constant.
  applied_ = Vector::Zero(static_cast<Index>(cell_dofs_.size()));
  dispatch_cell_type(mesh.cell_type, [&](auto element) {
    using E = decltype(element);
    for (std::size_t k = 0; k < region.cells().size(); ++k) {
      double* cell = applied_.data() + k * cell_size_;
      for (int q = 0; q < nq; ++q) {
        const Index g = static_cast<Index>(k) * nq + q;
        const typename E::Values N = E::shape(gauss.local[g].template head<E::dim>());
        for (int a = 0; a < E::nodes; ++a)
          for (int i = 0; i < dim; ++i) cell[a * dim + i] += gauss.mass[g] * N(a) * gravity(i);
      }
    }
  });
}

void FemRegionTerm::declare_couplings(SparsityBuilder& pattern) const {
  std::vector<Index> block(cell_size_);
  for (std::size_t c = 0; c * cell_size_ < cell_dofs_.size(); ++c) {
    std::copy_n(cell_dofs_.begin() + c * cell_size_, cell_size_, block.begin());
    pattern.couple_unknowns(block);
  }
}

void FemRegionTerm::attach(const SparseMatrix& pattern) {
  const std::size_t n = cell_size_, cells = region_.cells().size();
  slots_.resize(cells * n * n);
  for (std::size_t k = 0; k < cells; ++k)
    block_slots(pattern, dofs_, std::span<const Index>(cell_dofs_.data() + k * n, n),
                slots_.data() + k * n * n);
}

bool FemRegionTerm::add_cells(const Vector& du, SystemForces* forces, SparseMatrix* tangent,
                              bool commit) {
  // One colour at a time, its cells (which share no node) on all threads: every entry of the
  // force and the tangent is summed in the same order whatever the number of threads.
  return dispatch_cell_type(grid_.mesh().cell_type, [&](auto element) {
    using E = decltype(element);
    std::atomic<bool> admissible{true};
    for (const std::vector<Index>& colour : colours_) {
      const Index count = static_cast<Index>(colour.size());
#pragma omp parallel for schedule(dynamic, 8) if (count > 64)
      for (Index j = 0; j < count; ++j)
        if (!add_cell<E>(colour[j], du, forces, tangent, commit)) admissible = false;
    }
    return admissible.load();
  });
}

template <class E>
bool FemRegionTerm::add_cell(Index k, const Vector& du, SystemForces* forces, SparseMatrix* tangent,
                             bool commit) {
  constexpr int n = E::nodes * E::dim;
  MaterialPoints& gauss = region_.gauss_points();
  const int nq = region_.points_per_cell();
  Eigen::Matrix<double, E::nodes, E::dim> X, u;
  PointKernelResult<E> cell;
  const Index* dofs = cell_dofs_.data() + k * n;
  const double* x = X_.data() + k * n;
  for (int a = 0; a < E::nodes; ++a)
    for (int i = 0; i < E::dim; ++i) {
      X(a, i) = x[a * E::dim + i];
      u(a, i) = du(dofs[a * E::dim + i]);
    }
  const Index first = k * nq;
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
                  slots_.empty() ? nullptr : slots_.data() + k * n * n);
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

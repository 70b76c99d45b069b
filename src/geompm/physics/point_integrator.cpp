#include "geompm/physics/point_integrator.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>

#include "geompm/mesh/element.hpp"
#include "geompm/physics/exact_pressure_projection.hpp"
#include "geompm/physics/mixed_point_kernel.hpp"
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
    const auto nodes = grid_.mesh().cell_nodes(grid_.active_cells()[ci]);
    std::array<Index, 27> active{};
    for (int a = 0; a < nen_; ++a) active[a] = node_to_active[nodes[a]];
    std::array<Index, 27 * 4> free{};  // per local unknown: its free index (-1: constrained)
    for (int l = 0; l < m; ++l) free[l] = dofs_.free_index(local_dof(active, nen_, l));
    for (int lc = 0; lc < m; ++lc) {
      const Index col = free[lc];
      if (col < 0) continue;
      const int* begin = pattern.innerIndexPtr() + pattern.outerIndexPtr()[col];
      const int* end = pattern.innerIndexPtr() + pattern.outerIndexPtr()[col + 1];
      for (int lr = 0; lr < m; ++lr) {
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
  const bool cells_ok = dispatch_cell_type(grid_.mesh().cell_type, [&](auto e) {
    using E = decltype(e);
    return pressure_ ? add_cells<E, true>(du, forces.internal, tangent)
                     : add_cells<E, false>(du, forces.internal, tangent);
  });
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

template <class E>
void PointIntegrator::pressure_stabilisation(Index ci,
                                             Eigen::Matrix<double, E::nodes, E::nodes>& S) const {
  // Polynomial pressure projection (Dohrmann & Bochev 2004; theory eq. 11.5): the pressure's
  // departure from its mean over the cell, p - Pi p, is penalised with 1/G,
  //   S = sum_p (v_p / G_p) (N_p - m)(N_p - m)^T,   m = sum_p v_p N_p / sum_p v_p,
  // over the cell's mixed points with their start-of-step volumes (so S does not depend on the
  // unknowns). It removes the checkerboard modes equal-order u-p cells allow and vanishes for a
  // pressure constant over the cell. At the field's pressure it is made stronger (eq. 14.4).
  const double strength =
      grid_.settings().mixed_field_pressure ? field_pressure_stabilisation : 1.0;
  constexpr int nen = E::nodes;
  using Values = Eigen::Matrix<double, nen, 1>;
  S.setZero();
  Values mean = Values::Zero();
  double volume = 0.0;
  for (Index p = grid_.cell_point_begin(ci); p < grid_.cell_point_end(ci); ++p)
    if (grid_.is_mixed(points_, p)) {
      mean += points_.volume[p] * Eigen::Map<const Values>(grid_.cell_shape(p));
      volume += points_.volume[p];
    }
  if (volume <= 0.0) return;
  mean /= volume;
  double compliance = 0.0;  // sum of the points' v / G
  for (Index p = grid_.cell_point_begin(ci); p < grid_.cell_point_end(ci); ++p)
    if (grid_.is_mixed(points_, p)) {
      const double shear =
          grid_.materials()[points_.material[p]]->elastic_moduli(points_.internal[p]).shear;
      const Values d = Eigen::Map<const Values>(grid_.cell_shape(p)) - mean;
      S.noalias() += (strength * points_.volume[p] / shear) * (d * d.transpose());
      compliance += points_.volume[p] / shear;
    }
  // Eq. 11.10: a share of the exactly integrated projection, with the points' v / G, so that
  // only the cell's constant pressures escape it however its points cluster.
  if (const double floor = grid_.settings().pressure_stabilisation_floor; floor > 0.0)
    S.noalias() += (strength * floor * compliance) * exact_pressure_projection<E>();
}

template <class E>
Stencil<E::nodes, E::dim> PointIntegrator::cell_stencil(Index p) const {
  PointStencil<E> s;
  s.N = Eigen::Map<const typename E::Values>(grid_.cell_shape(p));
  s.dN_dX = Eigen::Map<const Eigen::Matrix<double, E::nodes, E::dim>>(grid_.cell_gradients(p));
  return s;
}

template <int NS, int Dim, class StencilOf>
bool PointIntegrator::average_volume_change(Index ci, const Eigen::Matrix<double, NS, Dim>& du,
                                            StencilOf&& stencil_of,
                                            AveragedVolumeChange<NS, Dim>& average) const {
  // Eq. 12.1 and 12.4 over the cell's averaged points: volume ratios weighted by the start-of-step
  // volumes (so the cell's volume is kept exactly: sum_q v_q,n dJ^ = sum_q v_q), divergence
  // operators by the current ones. stencil_of(p): point p's weights over the rows of du.
  const bool axisymmetric = grid_.axisymmetric();
  const Index n = du.rows() * Dim;
  Eigen::Matrix<double, 1, KernelResult<NS, Dim>::n> divergence(1, n);
  double start_volume = 0.0, volume = 0.0;
  average.divergence.setZero(1, n);
  for (Index p = grid_.cell_point_begin(ci); p < grid_.cell_point_end(ci); ++p) {
    if (!grid_.is_averaged(points_, p)) continue;
    double dJ = 1.0;
    if (!point_volume_change(stencil_of(p), start_state(p), du, axisymmetric, dJ, divergence)) {
      note_inadmissible(p);
      return false;
    }
    const double v_n = points_.volume[p];
    start_volume += v_n;
    volume += v_n * dJ;
    average.divergence += (v_n * dJ) * divergence;
  }
  average.ratio = start_volume > 0.0 ? volume / start_volume : 1.0;
  if (volume > 0.0) average.divergence /= volume;
  return true;
}

template <int NS, int Dim, class Gradients, class Force, class Stiffness>
void PointIntegrator::add_point_terms(Index p, const Eigen::Matrix<double, NS, 1>& N,
                                      const Gradients& dN_dX,
                                      const Eigen::Matrix<double, NS, Dim>& du, bool with_tangent,
                                      Force& f, Stiffness& K) const {
  // A force F(u) at the place x_p + offset whose derivative is D = dF/du enters f_int as F W_a
  // and the tangent as W_a W_b D, W the weights of that place: W = N at the point (a prescribed
  // motion's spring, docs/theory.md eq. 5.1), W = N + grad N . offset elsewhere in its domain,
  // carried by the step's deformation (a footing's contact, eq. 13.6).
  const int nodes = static_cast<int>(N.size());
  const auto add = [&](const Eigen::Matrix<double, NS, 1>& W, const Vec3& force,
                       const Mat3& stiffness) {
    for (int a = 0; a < nodes; ++a)
      for (int i = 0; i < Dim; ++i) f(a * Dim + i) += force(i) * W(a);
    if (!with_tangent) return;
    for (int a = 0; a < nodes; ++a)
      for (int b = 0; b < nodes; ++b) {
        const double w = W(a) * W(b);
        for (int i = 0; i < Dim; ++i)
          for (int k = 0; k < Dim; ++k)
            if (stiffness(i, k) != 0.0) K(a * Dim + i, b * Dim + k) += w * stiffness(i, k);
      }
  };
  for (PointTerm* term : point_terms_) {
    if (!term->acts(p)) continue;
    const Vec3 offset = term->offset(p);
    Vec3 u = Vec3::Zero(), force;
    Mat3 stiffness;
    if (offset == Vec3::Zero()) {
      u.template head<Dim>() = du.transpose() * N;
      term->force(p, u, force, stiffness);
      add(N, force, stiffness);
    } else {
      const Eigen::Matrix<double, NS, 1> W = N + dN_dX * offset.template head<Dim>();
      u.template head<Dim>() = du.transpose() * W;
      term->force(p, u, force, stiffness);
      add(W, force, stiffness);
    }
  }
}

template <class E, bool Mixed>
bool PointIntegrator::add_cells(const Vector& du, Vector& f_int, SparseMatrix* tangent) {
  std::atomic<bool> admissible{true};
  for (const auto& colour : grid_.colours()) {
    const Index count = static_cast<Index>(colour.size());
#pragma omp parallel for schedule(dynamic, 8) if (count > 64)
    for (Index k = 0; k < count; ++k)
      if (!add_cell<E, Mixed>(colour[k], du, f_int, tangent)) admissible = false;
  }
  return admissible;
}

template <class E, bool Mixed>
bool PointIntegrator::add_cell(Index ci, const Vector& du, Vector& f_int, SparseMatrix* tangent) {
  constexpr int nen = E::nodes, dim = E::dim, n = nen * dim, m = n + (Mixed ? nen : 0);
  const double s_p = pressure_ ? pressure_->scale() : 1.0;
  const auto nodes = grid_.mesh().cell_nodes(grid_.active_cells()[ci]);
  std::array<Index, nen> active;
  for (int a = 0; a < nen; ++a) active[a] = grid_.node_to_active()[nodes[a]];
  Eigen::Matrix<double, nen, dim> du_local;
  Eigen::Matrix<double, m, 1> x_flat;  // the cell's unknowns, local order (local_dof)
  for (int l = 0; l < m; ++l) x_flat(l) = du(local_dof(active, nen, l));
  for (int a = 0; a < nen; ++a) du_local.row(a) = x_flat.template segment<dim>(a * dim);
  Eigen::Matrix<double, nen, 1> p_local;  // nodal pressures (eq. 11.6)
  if constexpr (Mixed)
    for (int a = 0; a < nen; ++a) p_local(a) = pressure_->start()(active[a]) + s_p * x_flat(n + a);

  Eigen::Matrix<double, m, 1> f_cell = Eigen::Matrix<double, m, 1>::Zero();
  Eigen::Matrix<double, m, m> K_cell = Eigen::Matrix<double, m, m>::Zero();
  for (const auto& term : cell_terms_)
    if (const double* block = term->cell_block(ci)) {
      const Eigen::Map<const Eigen::Matrix<double, m, m>> K_term(block);
      f_cell.noalias() += K_term * x_flat;
      K_cell += K_term;
    }
  if constexpr (Mixed) {
    Eigen::Matrix<double, nen, nen> S;
    pressure_stabilisation<E>(ci, S);
    // Eq. 11.5 on the pressure, or eq. 11.9 on its change over the step (s_p x, eq. 11.6).
    if (grid_.settings().mixed_incremental_pressure)
      f_cell.template tail<nen>().noalias() += (s_p * s_p) * (S * x_flat.template tail<nen>());
    else
      f_cell.template tail<nen>().noalias() += s_p * (S * p_local);
    K_cell.template bottomRightCorner<nen, nen>() += (s_p * s_p) * S;
  }
  // Points with a wide stencil are assembled one by one (add_wide_stencil_points).
  const Index point_end =
      grid_.wide_stencil() ? grid_.cell_point_begin(ci) : grid_.cell_point_end(ci);
  AveragedVolumeChange<nen, dim> average;
  if (grid_.averaging() && point_end > grid_.cell_point_begin(ci) &&
      !average_volume_change(
          ci, du_local, [&](Index q) { return cell_stencil<E>(q); }, average))
    return false;
  const bool admissible = integrate_cell_points<E, Mixed>(ci, point_end, du_local, p_local, average,
                                                          tangent != nullptr, f_cell, K_cell);
  for (int l = 0; l < m; ++l) f_int(local_dof(active, nen, l)) += f_cell(l);
  if (tangent) {
    const int* map = scatter_.data() + std::size_t(ci) * m * m;
    double* values = tangent->valuePtr();
    for (int lc = 0; lc < m; ++lc)
      for (int lr = 0; lr < m; ++lr) {
        const int at = map[lc * m + lr];
        if (at >= 0) values[at] += K_cell(lr, lc);
      }
  }
  return admissible;
}

template <class E, bool Mixed, class Displacements, class Pressures, class Average, class CellForce,
          class CellStiffness>
bool PointIntegrator::integrate_cell_points(Index ci, Index point_end,
                                            const Displacements& du_local, const Pressures& p_local,
                                            const Average& average, bool with_tangent,
                                            CellForce& f_cell, CellStiffness& K_cell) const {
  constexpr int nen = E::nodes, n = nen * E::dim;
  const bool axisymmetric = grid_.axisymmetric();
  const double s_p = pressure_ ? pressure_->scale() : 1.0;
  PointStencil<E> s;
  PointKernelResult<E> r;
  [[maybe_unused]] MixedKernelResult<E::nodes, E::dim> rm;
  bool admissible = true;
  for (Index p = grid_.cell_point_begin(ci); p < point_end; ++p) {
    s = cell_stencil<E>(p);
    const PointStartState start = start_state(p);
    const Average* cell_average = grid_.is_averaged(points_, p) ? &average : nullptr;
    // The point's forces and stiffness by its formulation; then, shared, its state.
    const FiniteStrainState* state = &r.state;
    const Mat3* stress = &r.state.cauchy_stress;
    double volume = 0.0, own_volume = 0.0, volume_mismatch = 0.0;
    bool ok = false;
    if constexpr (Mixed) {
      if (grid_.is_mixed(points_, p)) {
        ok = integrate_mixed_point(s, start, du_local, p_local, axisymmetric, with_tangent, rm,
                                   cell_average, grid_.settings().mixed_field_pressure,
                                   grid_.settings().mixed_incremental_pressure);
        if (ok) {
          f_cell.template head<n>() += rm.u.internal_force;
          f_cell.template tail<nen>() += s_p * rm.pressure_residual;
          if (with_tangent) {
            K_cell.template topLeftCorner<n, n>() += rm.u.stiffness;
            K_cell.template topRightCorner<n, nen>() += s_p * rm.K_up;
            K_cell.template bottomLeftCorner<nen, n>() += s_p * rm.K_pu;
            K_cell.template bottomRightCorner<nen, nen>() += (s_p * s_p) * rm.K_pp;
          }
          state = &rm.u.state;
          stress = &rm.total_stress;
          volume = rm.u.state_volume;
          own_volume = rm.u.volume;
          volume_mismatch = rm.volume_mismatch;
        }
      }
    }
    if (!(Mixed && grid_.is_mixed(points_, p))) {
      ok = integrate_point(s, start, du_local, axisymmetric, with_tangent, r, cell_average);
      if (ok) {
        f_cell.template head<n>() += r.internal_force;
        if (with_tangent) K_cell.template topLeftCorner<n, n>() += r.stiffness;
        volume = r.state_volume;
        own_volume = r.volume;
      }
    }
    if (!ok) {
      note_inadmissible(p, Mixed && grid_.is_mixed(points_, p) ? rm.u.state.stress_update_failed
                                                               : r.state.stress_update_failed);
      admissible = false;
      continue;
    }
    if (!point_terms_.empty())
      add_point_terms(p, s.N, s.dN_dX, du_local, with_tangent, f_cell, K_cell);
    commit(p, *state, volume, *stress, own_volume, volume_mismatch);
  }
  return admissible;
}

namespace {

// Point p's wide-stencil weights over `over` (sorted active nodes holding its own stencil), into
// `out`: a copy of its own, or padded with zeros.
template <int Dim>
void fill_wide_stencil(const GridSystem& grid, Index p, const std::vector<Index>& over,
                       Stencil<Eigen::Dynamic, Dim>& out) {
  const auto& wide_nodes = grid.wide_nodes();
  const auto& wide_N = grid.wide_values();
  const auto& wide_gradients = grid.wide_gradients();
  const Index begin = grid.wide_begin(p), end = grid.wide_end(p);
  const Index size = static_cast<Index>(over.size());
  if (size == end - begin) {  // its own stencil: a copy
    out.N = Eigen::Map<const Eigen::VectorXd>(wide_N.data() + begin, size);
    out.dN_dX = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Dim, Eigen::RowMajor>>(
        wide_gradients.data() + std::size_t(begin) * Dim, size, Dim);
    return;
  }
  out.N.setZero(size);
  out.dN_dX.setZero(size, Dim);
  for (Index a = begin; a < end; ++a) {
    const Index at = std::lower_bound(over.begin(), over.end(), wide_nodes[a]) - over.begin();
    out.N(at) = wide_N[a];
    for (int i = 0; i < Dim; ++i) out.dN_dX(at, i) = wide_gradients[std::size_t(a) * Dim + i];
  }
}

// One point's force and stiffness over its unknowns `dofs` into f_int and the tangent.
void scatter_point(const DofMap& map, const std::vector<Index>& dofs, const Eigen::VectorXd& f,
                   const Eigen::MatrixXd* K, Vector& f_int, SparseMatrix* tangent) {
  const int local = static_cast<int>(dofs.size());
  for (int l = 0; l < local; ++l) f_int(dofs[l]) += f(l);
  if (!tangent) return;
  const int* outer = tangent->outerIndexPtr();
  const int* inner = tangent->innerIndexPtr();
  double* values = tangent->valuePtr();
  for (int lc = 0; lc < local; ++lc) {
    const Index col = map.free_index(dofs[lc]);
    if (col < 0) continue;
    const int* at = inner + outer[col];
    const int* end = inner + outer[col + 1];
    // Stencil nodes are sorted and pressures come after displacements: rows ascend.
    for (int lr = 0; lr < local; ++lr) {
      const Index row = map.free_index(dofs[lr]);
      if (row < 0) continue;
      at = std::lower_bound(at, end, row);
      values[at - inner] += (*K)(lr, lc);
    }
  }
}

}  // namespace

// What one thread needs to integrate the points of a cell with wide stencils.
template <int Dim>
struct PointIntegrator::WideWork {
  using Dynamic = Stencil<Eigen::Dynamic, Dim>;
  Dynamic s;
  KernelResult<Eigen::Dynamic, Dim> r;
  MixedKernelResult<Eigen::Dynamic, Dim> rm;
  AveragedVolumeChange<Eigen::Dynamic, Dim> average;
  Eigen::Matrix<double, Eigen::Dynamic, Dim> du_local;
  Eigen::VectorXd p_local;
  std::vector<Index> cell_nodes, nodes;
};

template <int Dim>
bool PointIntegrator::add_wide_stencil_points(const Vector& du, Vector& f_int,
                                              SparseMatrix* tangent) {
  // The points' stencils overlap across cells of one colour, so their forces are not scattered
  // as they are computed: the cells of a chunk are integrated in parallel into per-point local
  // vectors and matrices, which are then scattered one after the other, in point order. The
  // sums are the same whatever the number of threads.
  const Index n_cells = static_cast<Index>(grid_.active_cells().size());
  constexpr Index chunk_points = 2048;
  bool admissible = true;
  for (Index first = 0; first < n_cells && admissible;) {
    Index last = first;
    while (last < n_cells &&
           grid_.cell_point_begin(last) - grid_.cell_point_begin(first) < chunk_points)
      ++last;
    const Index offset = grid_.cell_point_begin(first);
    const Index count = grid_.cell_point_end(last - 1) - offset;
    if (wide_locals_.size() < std::size_t(count)) wide_locals_.resize(count);
#pragma omp parallel if (last - first > 16)
    {
      WideWork<Dim> work;
#pragma omp for schedule(dynamic, 4)
      for (Index ci = first; ci < last; ++ci)
        if (!integrate_wide_cell<Dim>(ci, du, tangent != nullptr, work, offset)) {
#pragma omp atomic write
          admissible = false;
        }
    }
    if (!admissible) break;
    for (Index k = 0; k < count; ++k) {
      const PointLocal& local = wide_locals_[k];
      scatter_point(dofs_, local.dofs, local.f, tangent ? &local.K : nullptr, f_int, tangent);
    }
    first = last;
  }
  return admissible;
}

template <int Dim>
bool PointIntegrator::integrate_wide_cell(Index ci, const Vector& du, bool with_tangent,
                                          WideWork<Dim>& w, Index offset) const {
  // The points of cell ci, each into its local vector and matrix. With the volume average
  // (theory §12) the averaged points of a cell see the union of their stencils, their own
  // weights padded with zeros, so that the average's rate and every point's forces live on the
  // same unknowns.
  using Dynamic = typename WideWork<Dim>::Dynamic;
  const auto& wide_nodes = grid_.wide_nodes();
  const auto gather = [&](const std::vector<Index>& over) {
    w.du_local.resize(static_cast<Index>(over.size()), Dim);
    for (std::size_t a = 0; a < over.size(); ++a)
      for (int i = 0; i < Dim; ++i) w.du_local(a, i) = du(dofs_.dof(displacement_, over[a], i));
  };
  const std::span<const Index> union_nodes = grid_.averaged_stencil_union(ci);
  const bool cell_average = grid_.averaging() && !union_nodes.empty();
  if (cell_average) {
    w.cell_nodes.assign(union_nodes.begin(), union_nodes.end());
    gather(w.cell_nodes);
    if (!average_volume_change(
            ci, w.du_local,
            [&](Index q) {
              Dynamic padded;
              fill_wide_stencil(grid_, q, w.cell_nodes, padded);
              return padded;
            },
            w.average))
      return false;
  }
  for (Index p = grid_.cell_point_begin(ci); p < grid_.cell_point_end(ci); ++p) {
    const bool averaged = cell_average && grid_.is_averaged(points_, p);
    if (averaged)
      w.nodes = w.cell_nodes;
    else
      w.nodes.assign(wide_nodes.begin() + grid_.wide_begin(p),
                     wide_nodes.begin() + grid_.wide_end(p));
    fill_wide_stencil(grid_, p, w.nodes, w.s);
    gather(w.nodes);
    PointLocal& local = wide_locals_[p - offset];
    if (!integrate_wide_point<Dim>(p, du, averaged, with_tangent, w, local)) return false;
    // Point terms act on the displacements, the first ns * Dim local unknowns.
    if (!point_terms_.empty())
      add_point_terms(p, w.s.N, w.s.dN_dX, w.du_local, with_tangent, local.f, local.K);
    const int ns = static_cast<int>(w.nodes.size());
    local.dofs.resize(local.f.size());
    for (int l = 0; l < static_cast<int>(local.f.size()); ++l)
      local.dofs[l] = local_dof(w.nodes, ns, l);
  }
  return true;
}

template <int Dim>
bool PointIntegrator::integrate_wide_point(Index p, const Vector& du, bool averaged,
                                           bool with_tangent, WideWork<Dim>& w,
                                           PointLocal& local) const {
  const bool axisymmetric = grid_.axisymmetric();
  const Index ns = static_cast<Index>(w.nodes.size());
  const PointStartState start = start_state(p);
  if (grid_.is_mixed(points_, p)) {
    // The pressure is interpolated with the point's own weights (eq. 11.1): its cell's (DDMP)
    // or its domain's (GIMP).
    w.p_local.resize(ns);
    for (Index a = 0; a < ns; ++a)
      w.p_local(a) = pressure_->start()(w.nodes[a]) +
                     pressure_->scale() * du(dofs_.dof(pressure_field_, w.nodes[a]));
    if (!integrate_mixed_point(w.s, start, w.du_local, w.p_local, axisymmetric, with_tangent, w.rm,
                               averaged ? &w.average : nullptr,
                               grid_.settings().mixed_field_pressure,
                               grid_.settings().mixed_incremental_pressure)) {
      note_inadmissible(p, w.rm.u.state.stress_update_failed);
      return false;
    }
    const double s_p = pressure_->scale();
    const int size = static_cast<int>(ns) * (Dim + 1);
    local.f.resize(size);
    local.f << w.rm.u.internal_force, s_p * w.rm.pressure_residual;
    if (with_tangent) {
      local.K.resize(size, size);
      local.K << w.rm.u.stiffness, s_p * w.rm.K_up, s_p * w.rm.K_pu, (s_p * s_p) * w.rm.K_pp;
    }
    commit(p, w.rm.u.state, w.rm.u.state_volume, w.rm.total_stress, w.rm.u.volume,
           w.rm.volume_mismatch);
    return true;
  }
  if (!integrate_point(w.s, start, w.du_local, axisymmetric, with_tangent, w.r,
                       averaged ? &w.average : nullptr)) {
    note_inadmissible(p, w.r.state.stress_update_failed);
    return false;
  }
  local.f = w.r.internal_force;
  if (with_tangent) local.K = w.r.stiffness;
  commit(p, w.r.state, w.r.state_volume, w.r.state.cauchy_stress, w.r.volume);
  return true;
}

}  // namespace geompm

// PointIntegrator on wide stencils (DDMP, GIMP: a point's weights reach beyond its cell), in a
// translation unit of its own (docs/performance.md, build times).
#include "geompm/physics/point_integrator_cells.hpp"

namespace geompm {

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
      add_point_terms(p, w.s.N, w.du_local, with_tangent, local.f, local.K);
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
                               averaged ? &w.average : nullptr, grid_.is_field_pressure(points_, p),
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

template bool PointIntegrator::add_wide_stencil_points<2>(const Vector&, Vector&, SparseMatrix*);
template bool PointIntegrator::add_wide_stencil_points<3>(const Vector&, Vector&, SparseMatrix*);

}  // namespace geompm

#include "geompm/physics/grid_system.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "geompm/mesh/cell_geometry.hpp"
#include "geompm/mesh/element.hpp"
#include "geompm/physics/exact_pressure_projection.hpp"
#include "geompm/physics/ghost_penalty.hpp"
#include "geompm/physics/gimp_weights.hpp"
#include "geompm/physics/mixed_point_kernel.hpp"
#include "geompm/physics/point_kernel.hpp"
#include "geompm/physics/pressure_start_fit.hpp"

namespace geompm {

namespace {

// A bubble over the reference cell: 1 at the centre, 0 on the cell boundary (DDMP blending).
double cell_bubble(CellType type, const Vec3& xi) {
  switch (type) {
    case CellType::Tri3:
    case CellType::Tri6:
      return 27.0 * xi(0) * xi(1) * (1.0 - xi(0) - xi(1));
    case CellType::Quad4:
      return (1.0 - xi(0) * xi(0)) * (1.0 - xi(1) * xi(1));
    case CellType::Tet4:
      return 256.0 * xi(0) * xi(1) * xi(2) * (1.0 - xi(0) - xi(1) - xi(2));
    case CellType::Hex8:
      return (1.0 - xi(0) * xi(0)) * (1.0 - xi(1) * xi(1)) * (1.0 - xi(2) * xi(2));
  }
  return 0.0;
}

}  // namespace

GridSystem::GridSystem(const Mesh& mesh, const MeshTopology& topology,
                       const std::vector<const Material*>& materials, const GridSettings& settings)
    : mesh_(mesh),
      topology_(topology),
      materials_(materials),
      settings_(settings),
      dim_(mesh.dim()),
      nen_(mesh.nodes_per_cell()) {
  settings_.mixed.resize(materials_.size(), 0);
  mixed_ = std::any_of(settings_.mixed.begin(), settings_.mixed.end(), [](char m) { return m; });
  settings_.volume_average.resize(materials_.size(), 0);
  averaging_ = std::any_of(settings_.volume_average.begin(), settings_.volume_average.end(),
                           [](char a) { return a; });
  if (settings_.interpolation == GridInterpolation::Gimp) {
    std::string why;
    rectilinear_ = find_rectilinear_grid(mesh, why);
    if (!rectilinear_)
      throw std::invalid_argument("numerics.interpolation: gimp needs a rectilinear grid, but " +
                                  why);
  }
}

template <class F>
void GridSystem::for_each_weight(const MaterialPoints& points, Index p, F&& f) const {
  // f(active node, N_a(x_p)) over the nodes point p sees: its wide stencil (DDMP, GIMP) or its
  // cell. The one place that knows the difference, for mapping, loads and convect.
  if (wide_stencil()) {
    for (Index a = wide_start_[p]; a < wide_start_[p + 1]; ++a) f(wide_nodes_[a], wide_N_[a]);
    return;
  }
  const auto nodes = mesh_.cell_nodes(points.cell[p]);
  for (int a = 0; a < nen_; ++a) f(node_to_active_[nodes[a]], shape_[std::size_t(p) * nen_ + a]);
}

Vec3 GridSystem::interpolate(const MaterialPoints& points, Index p, const Vector& nodal) const {
  Vec3 value = Vec3::Zero();
  for_each_weight(points, p, [&](Index node, double N) {
    for (int i = 0; i < dim_; ++i) value(i) += N * nodal(node * dim_ + i);
  });
  return value;
}

Vec3 GridSystem::interpolate_at(const MaterialPoints& points, Index p, const Vec3& offset,
                                const Vector& nodal) const {
  Vec3 value = Vec3::Zero();
  const auto add = [&](Index node, double N, const double* gradient) {
    double w = N;
    for (int d = 0; d < dim_; ++d) w += gradient[d] * offset(d);
    for (int i = 0; i < dim_; ++i) value(i) += w * nodal(node * dim_ + i);
  };
  if (wide_stencil()) {
    for (Index a = wide_start_[p]; a < wide_start_[p + 1]; ++a)
      add(wide_nodes_[a], wide_N_[a], wide_gradients_.data() + std::size_t(a) * dim_);
    return value;
  }
  // Cell gradients are stored column-major (nen x dim) per point.
  const auto nodes = mesh_.cell_nodes(points.cell[p]);
  const double* G = gradients_.data() + std::size_t(p) * nen_ * dim_;
  for (int a = 0; a < nen_; ++a) {
    double gradient[3] = {0, 0, 0};
    for (int d = 0; d < dim_; ++d) gradient[d] = G[d * nen_ + a];
    add(node_to_active_[nodes[a]], shape_[std::size_t(p) * nen_ + a], gradient);
  }
  return value;
}

// ---------------------------------------------------------------------------------------------
// Phase 1: initialise
// ---------------------------------------------------------------------------------------------

void GridSystem::initialise(MaterialPoints& points) {
  dispatch_cell_type(mesh_.cell_type, [&](auto e) { initialise_typed<decltype(e)>(points); });
}

template <class E>
void GridSystem::initialise_typed(MaterialPoints& points) {
  constexpr int nen = E::nodes, dim = E::dim;
  points.sort_by_cell();
  const Index n_points = points.size();
  const Index n_cells = mesh_.num_cells();

  // Active cells: occupied cells, then `buffer_layers` rings of neighbours (seed §3.2: empty
  // buffer cells catch points that move out of the body, e.g. above a free surface). With GIMP
  // a cell that a point's domain overlaps is occupied too: the nodes of the point's stencil are
  // its nodes.
  std::vector<char> is_active(n_cells, 0);
  for (Index p = 0; p < n_points; ++p) is_active[points.cell[p]] = 1;
  if (settings_.interpolation == GridInterpolation::Gimp) build_gimp_stencils(points, is_active);
  std::vector<Index> frontier;
  for (Index c = 0; c < n_cells; ++c)
    if (is_active[c]) frontier.push_back(c);
  for (int layer = 0; layer < settings_.buffer_layers; ++layer) {
    std::vector<Index> next;
    for (Index c : frontier)
      for (Index nb : topology_.cell_neighbours.row(c))
        if (!is_active[nb]) {
          is_active[nb] = 1;
          next.push_back(nb);
        }
    frontier.swap(next);
  }
  active_cells_.clear();
  for (Index c = 0; c < n_cells; ++c)
    if (is_active[c]) active_cells_.push_back(c);

  // Point ranges per active cell (points are sorted by cell).
  const Index n_active = static_cast<Index>(active_cells_.size());
  cell_point_begin_.assign(n_active, 0);
  cell_point_end_.assign(n_active, 0);
  {
    Index p = 0;
    for (Index ci = 0; ci < n_active; ++ci) {
      const Index c = active_cells_[ci];
      while (p < n_points && points.cell[p] < c) ++p;
      cell_point_begin_[ci] = p;
      while (p < n_points && points.cell[p] == c) ++p;
      cell_point_end_[ci] = p;
    }
  }

  // Active nodes.
  node_to_active_.assign(mesh_.num_nodes(), -1);
  active_nodes_.clear();
  for (Index c : active_cells_)
    for (Index node : mesh_.cell_nodes(c))
      if (node_to_active_[node] < 0) node_to_active_[node] = 0;
  for (Index node = 0; node < mesh_.num_nodes(); ++node)
    if (node_to_active_[node] == 0) {
      node_to_active_[node] = static_cast<Index>(active_nodes_.size());
      active_nodes_.push_back(node);
    }
  // Stencils were built with mesh node ids, ascending; active ids keep their order.
  if (settings_.interpolation == GridInterpolation::Gimp)
    for (Index& node : wide_nodes_) node = node_to_active_[node];
  colour_active_cells();

  // Shape functions and reference gradients at each point, on the grid of this step.
  shape_.assign(std::size_t(n_points) * nen, 0.0);
  gradients_.assign(std::size_t(n_points) * nen * dim, 0.0);
  cell_fill_.assign(n_active, 0.0);
  cell_mixed_fill_.assign(n_active, 0.0);
  cell_size_.assign(n_points, 0.0);
  plastic_.assign(n_points, 0);
  target_stiffness_.clear();
  point_reaction_.clear();
  force_law_acts_.clear();
  force_law_offset_.clear();
  force_law_ = nullptr;
  const bool radial = settings_.kinematics == Kinematics::Axisymmetric;
#pragma omp parallel for schedule(dynamic, 16) if (n_active > 256)
  for (Index ci = 0; ci < n_active; ++ci) {
    const Index c = active_cells_[ci];
    const Eigen::Matrix<double, E::nodes, E::dim> X =
        cell_node_coordinates<cell_type_of<E>>(mesh_, c).transpose();
    double occupied = 0.0, occupied_mixed = 0.0;
    for (Index p = cell_point_begin_[ci]; p < cell_point_end_[ci]; ++p) {
      const auto s = make_stencil<E>(X, points.local[p].template head<dim>());
      Eigen::Map<typename E::Values>(shape_.data() + std::size_t(p) * nen) = s.N;
      Eigen::Map<Eigen::Matrix<double, nen, dim>>(gradients_.data() + std::size_t(p) * nen * dim) =
          s.dN_dX;
      occupied += points.volume[p];
      if (is_mixed(points, p)) occupied_mixed += points.volume[p];
    }
    const double measure = cell_measure(mesh_, c, radial);
    cell_fill_[ci] = std::min(1.0, occupied / measure);
    cell_mixed_fill_[ci] = std::min(1.0, occupied_mixed / measure);
    const double size = std::pow(cell_measure(mesh_, c, false), 1.0 / dim);
    for (Index p = cell_point_begin_[ci]; p < cell_point_end_[ci]; ++p) cell_size_[p] = size;
  }

  if (mixed_) initialise_pressure(points);
  empty_cell_stiffness_typed<E>();
  step_blocks_.clear();
  sparse_node_springs_typed<E>(points);
  ghost_penalty_blocks(points);
  if (settings_.interpolation == GridInterpolation::DualDomain)
    build_dual_domain_stencils<E>(points);
  union_start_.clear();
  union_nodes_.clear();
  if (wide_stencil() && averaging_) build_averaged_stencil_unions(points);

  // Mass, momentum and acceleration to the nodes (seed eq. 9), in point order (deterministic).
  const Index n_dofs = num_dofs();
  mass_ = Vector::Zero(n_dofs);
  velocity_ = Vector::Zero(n_dofs);
  acceleration_ = Vector::Zero(n_dofs);
  for (Index p = 0; p < n_points; ++p)
    for_each_weight(points, p, [&](Index node, double N) {
      const double w = points.mass[p] * N;
      for (int i = 0; i < dim; ++i) {
        mass_(node * dim + i) += w;
        velocity_(node * dim + i) += w * points.velocity[p](i);
        acceleration_(node * dim + i) += w * points.acceleration[p](i);
      }
    });
  const double tiny = n_dofs > 0 ? 1e-14 * std::max(mass_.maxCoeff(), 0.0) : 0.0;
  for (Index d = 0; d < n_dofs; ++d) {
    if (mass_(d) > tiny) {
      velocity_(d) /= mass_(d);
      acceleration_(d) /= mass_(d);
    } else {
      velocity_(d) = acceleration_(d) = 0.0;
    }
  }
}

void GridSystem::initialise_pressure(const MaterialPoints& points) {
  // The scales of the pressure unknowns (theory eq. 11.6) from the stiffest mixed soil of the
  // step, and the start value of the nodal pressures: the points' pressures (from the total
  // stress they carry) averaged onto the nodes with weights N v, so that Newton starts from the
  // last converged pressure field instead of from zero.
  const Index n_nodes = static_cast<Index>(active_nodes_.size());
  double shear = 0.0, bulk = 0.0, size = 0.0;
  Index count = 0;
  pressure_start_ = Vector::Zero(n_nodes);
  Vector weight = Vector::Zero(n_nodes);
  for (Index p = 0; p < points.size(); ++p) {
    if (!is_mixed(points, p)) continue;
    const ElasticModuli moduli = materials_[points.material[p]]->elastic_moduli(points.internal[p]);
    shear = std::max(shear, moduli.shear);
    bulk = std::max(bulk, moduli.bulk);
    size += cell_size_[p];
    ++count;
    const double pressure = -points.stress[p].trace() / 3.0;
    const auto nodes = mesh_.cell_nodes(points.cell[p]);
    for (int a = 0; a < nen_; ++a) {
      const double w = shape_[std::size_t(p) * nen_ + a] * points.volume[p];
      weight(node_to_active_[nodes[a]]) += w;
      pressure_start_(node_to_active_[nodes[a]]) += w * pressure;
    }
  }
  for (Index a = 0; a < n_nodes; ++a)
    if (weight(a) > 0.0) pressure_start_(a) /= weight(a);
  pressure_scale_ = count > 0 ? shear / (size / count) : 1.0;
  reference_bulk_ = count > 0 ? bulk : 1.0;
  if (!settings_.fitted_pressure_start) return;
  // Eq. 11.11: where the last converged field is known and the node's support is well filled,
  // start from that field smoothed by the local linear fit; elsewhere from the points.
  mark_supported_pressure_nodes();
  if (last_pressure_.size() == std::size_t(mesh_.num_nodes()))
    fit_pressure_start(mesh_, active_cells_, active_nodes_, node_to_active_, last_pressure_,
                       pressure_supported_, pressure_start_);
}

void GridSystem::mark_supported_pressure_nodes() {
  // A node is well supported when every cell around it is active and at least half filled by
  // mixed points: at the free surface, the heave and the footing's base its pressure is poorly
  // determined, and its last value would be carried on by the fit of eq. 11.11.
  const Index n_nodes = static_cast<Index>(active_nodes_.size());
  std::vector<Index> active_cells_around(n_nodes, 0);
  pressure_supported_.assign(n_nodes, 1);
  for (std::size_t ci = 0; ci < active_cells_.size(); ++ci)
    for (Index node : mesh_.cell_nodes(active_cells_[ci])) {
      const Index a = node_to_active_[node];
      ++active_cells_around[a];
      if (cell_mixed_fill_[ci] < 0.5) pressure_supported_[a] = 0;
    }
  for (Index a = 0; a < n_nodes; ++a)
    if (active_cells_around[a] < Index(topology_.node_cells.row(active_nodes_[a]).size()))
      pressure_supported_[a] = 0;
}

Vector GridSystem::nodal_pressure(const Vector& x) const {
  const Index n_nodes = static_cast<Index>(active_nodes_.size());
  if (!mixed_) return Vector::Zero(n_nodes);
  return pressure_start_ + pressure_scale_ * x.segment(pressure_dof(0), n_nodes);
}

void GridSystem::colour_active_cells() {
  // Greedy colouring: a cell takes the smallest colour that no cell sharing a node has taken.
  const Index n_active = static_cast<Index>(active_cells_.size());
  std::vector<int> colour_of(mesh_.num_cells(), -1);
  colours_.clear();
  std::vector<char> used;
  for (Index ci = 0; ci < n_active; ++ci) {
    const Index c = active_cells_[ci];
    used.assign(colours_.size() + 1, 0);
    for (Index nb : topology_.cell_neighbours.row(c))
      if (colour_of[nb] >= 0) used[colour_of[nb]] = 1;
    int colour = 0;
    while (used[colour]) ++colour;
    colour_of[c] = colour;
    if (colour == static_cast<int>(colours_.size())) colours_.emplace_back();
    colours_[colour].push_back(ci);
  }
}

template <class E>
void GridSystem::empty_cell_stiffness_typed() {
  // A small linear elastic stiffness in empty and partly filled cells keeps the system regular
  // (seed §3.2). It is scaled by the empty fraction (1 - fill) of the cell, so full cells get
  // none and it fades in as a cell empties. Small strain on the grid of the step, nu = 0.3.
  // In a mixed system the pressure unknowns of empty space need the same: the pressure block a
  // full cell of the stiffest mixed soil would have (v N N^T / K, eq. 11.2), scaled by the
  // fraction of the cell not covered by mixed points (theory eq. 11.7). Like the displacement
  // part it acts on the change over the step, holding it as weakly as the soil's own
  // compressibility would.
  constexpr int nen = E::nodes, dim = E::dim, n = nen * dim;
  using GC = GradientComponents<dim>;
  constexpr int nc = GC::count;
  const int m = cell_dofs();
  const Index n_active = static_cast<Index>(active_cells_.size());
  // Stored only for the cells that get some (full cells are most of a body).
  empty_offset_.assign(n_active, -1);
  std::size_t stored = 0;
  const auto displacement_weight = [&](Index ci) {
    return settings_.empty_cell_modulus > 0.0 ? 1.0 - cell_fill_[ci] : 0.0;
  };
  const auto pressure_weight = [&](Index ci) { return mixed_ ? 1.0 - cell_mixed_fill_[ci] : 0.0; };
  for (Index ci = 0; ci < n_active; ++ci)
    if (displacement_weight(ci) > 1e-9 || pressure_weight(ci) > 1e-9)
      empty_offset_[ci] = static_cast<std::int64_t>(stored++);
  empty_stiffness_.assign(stored * m * m, 0.0);
  if (stored == 0) return;
  const double E_empty = settings_.empty_cell_modulus, nu = 0.3;
  const Tensor4 C =
      isotropic_elasticity4(E_empty * nu / ((1 + nu) * (1 - 2 * nu)), E_empty / (2 * (1 + nu)));
  Eigen::Matrix<double, nc, nc> A;
  for (int c = 0; c < nc; ++c)
    for (int d = 0; d < nc; ++d)
      A(c, d) = C(pair_index(GC::row[c], GC::col[c]), pair_index(GC::row[d], GC::col[d]));
  const double pressure_factor = pressure_scale_ * pressure_scale_ / reference_bulk_;
  const bool axisymmetric = settings_.kinematics == Kinematics::Axisymmetric;
#pragma omp parallel for schedule(dynamic, 16) if (n_active > 256)
  for (Index ci = 0; ci < n_active; ++ci) {
    // Full cells whose point volumes sum to a hair below the cell's get none (round-off).
    if (empty_offset_[ci] < 0) continue;
    const double w_u = displacement_weight(ci) > 1e-9 ? displacement_weight(ci) : 0.0;
    const double w_p = pressure_weight(ci) > 1e-9 ? pressure_weight(ci) : 0.0;
    const Eigen::Matrix<double, E::nodes, E::dim> X =
        cell_node_coordinates<cell_type_of<E>>(mesh_, active_cells_[ci]).transpose();
    Eigen::Map<Eigen::MatrixXd> K(empty_stiffness_.data() + std::size_t(empty_offset_[ci]) * m * m,
                                  m, m);
    for (int q = 0; q < E::quadrature_size(); ++q) {
      const auto xi = E::quadrature_point(q);
      const auto s = make_stencil<E>(X, xi);
      const Eigen::Matrix<double, dim, dim> J = X.transpose() * E::shape_gradients(xi);
      double dv = E::quadrature_weight(q) * std::abs(J.determinant());
      const double r = s.N.dot(X.col(0));
      if (axisymmetric) dv *= r;
      Eigen::Matrix<double, nc, n> B = Eigen::Matrix<double, nc, n>::Zero();
      for (int a = 0; a < nen; ++a)
        for (int c = 0; c < nc; ++c)
          if (GC::row[c] < dim && GC::col[c] < dim)
            B(c, a * dim + GC::row[c]) = s.dN_dX(a, GC::col[c]);
      if (axisymmetric)
        for (int a = 0; a < nen; ++a) B(nc - 1, a * dim) = s.N(a) / r;
      if (w_u > 0.0) K.topLeftCorner(n, n).noalias() += w_u * dv * (B.transpose() * A * B);
      if (w_p > 0.0)
        K.bottomRightCorner(m - n, m - n).noalias() +=
            (w_p * dv * pressure_factor) * (s.N * s.N.transpose());
    }
  }
}

template <class E>
void GridSystem::sparse_node_springs_typed(const MaterialPoints& points) {
  // A node whose support the points barely reach (a soil point at the far corner of its support,
  // the rest emptied, as beside a footing's edge) is held only by the empty-cell stiffness of its
  // cells: Newton's corrections move it by as much as the step's increment, and a contact or a
  // return nearby turns them back (docs/validation.md §7). Eq. 6.2: its support fill
  // s_a = sum_p N_a(x_p) v_p / sum_c |c| / nen (the points' volume it sees against the volume its
  // shape function covers) below s_min gives it a spring E_s (1 - s_a / s_min) |c| / (nen h_c^2)
  // from each of its cells, on the step's displacement like the empty-cell stiffness: one
  // diagonal block per such node, summed over its cells once a step.
  if (settings_.sparse_node_modulus <= 0.0) return;
  constexpr int nen = E::nodes, dim = E::dim;
  const Index n_nodes = static_cast<Index>(active_nodes_.size());
  const bool radial = settings_.kinematics == Kinematics::Axisymmetric;
  std::vector<double> seen(n_nodes, 0.0), covered(n_nodes, 0.0), spring_share(n_nodes, 0.0);
  for (Index ci = 0; ci < static_cast<Index>(active_cells_.size()); ++ci) {
    const Index c = active_cells_[ci];
    const auto nodes = mesh_.cell_nodes(c);
    const double share = cell_measure(mesh_, c, radial) / nen;
    const double spring = share / std::pow(cell_measure(mesh_, c, false), 2.0 / dim);
    for (int a = 0; a < nen; ++a) {
      const Index na = node_to_active_[nodes[a]];
      covered[na] += share;
      spring_share[na] += spring;
      for (Index p = cell_point_begin_[ci]; p < cell_point_end_[ci]; ++p)
        seen[na] += shape_[std::size_t(p) * nen + a] * points.volume[p];
    }
  }
  const double fill_min = settings_.sparse_node_fill;
  for (Index na = 0; na < n_nodes; ++na) {
    const double fill = covered[na] > 0.0 ? seen[na] / covered[na] : 1.0;
    if (fill < fill_min)
      step_blocks_.push_back(
          {{na},
           Eigen::MatrixXd::Constant(
               1, 1, settings_.sparse_node_modulus * (1.0 - fill / fill_min) * spring_share[na])});
  }
}

void GridSystem::ghost_penalty_blocks(const MaterialPoints& points) {
  if (settings_.ghost_penalty <= 0.0) return;
  const Index n_active = static_cast<Index>(active_cells_.size());
  std::vector<double> modulus(n_active, 0.0);
  for (Index ci = 0; ci < n_active; ++ci)
    for (Index p = cell_point_begin_[ci]; p < cell_point_end_[ci]; ++p) {
      // The point's own Young's modulus E = 9 K G / (3 K + G): it varies in space where s_u does.
      const ElasticModuli m = materials_[points.material[p]]->elastic_moduli(points.internal[p]);
      const double E =
          3.0 * m.bulk + m.shear > 0.0 ? 9.0 * m.bulk * m.shear / (3.0 * m.bulk + m.shear) : 0.0;
      modulus[ci] = std::max(modulus[ci], E);
    }
  std::vector<NodeBlock> faces =
      ghost_penalty_faces(mesh_, topology_, active_cells_, node_to_active_, {modulus, cell_fill_},
                          {settings_.ghost_penalty, settings_.ghost_penalty_fill,
                           settings_.kinematics == Kinematics::Axisymmetric});
  step_blocks_.insert(step_blocks_.end(), std::make_move_iterator(faces.begin()),
                      std::make_move_iterator(faces.end()));
}

void GridSystem::add_step_blocks(const Vector& du, Vector& f_int, SparseMatrix* tangent) const {
  // Few blocks (the body's edge): one thread, in order, so the sums are deterministic.
  for (const NodeBlock& block : step_blocks_) {
    const Index size = static_cast<Index>(block.nodes.size());
    for (int i = 0; i < dim_; ++i)
      for (Index a = 0; a < size; ++a)
        for (Index b = 0; b < size; ++b)
          f_int(block.nodes[a] * dim_ + i) += block.weight(a, b) * du(block.nodes[b] * dim_ + i);
    if (!tangent) continue;
    const int* outer = tangent->outerIndexPtr();
    const int* inner = tangent->innerIndexPtr();
    double* values = tangent->valuePtr();
    for (int i = 0; i < dim_; ++i)
      for (Index b = 0; b < size; ++b) {
        const Index col = free_index_[block.nodes[b] * dim_ + i];
        if (col < 0) continue;
        for (Index a = 0; a < size; ++a) {
          const Index row = free_index_[block.nodes[a] * dim_ + i];
          if (row < 0) continue;
          const int* end = inner + outer[col + 1];
          const int* at = std::lower_bound(inner + outer[col], end, row);
          if (at == end || *at != row)  // set_constraints couples every block's nodes
            throw std::logic_error("step block: a coupling is not in the pattern");
          values[at - inner] += block.weight(a, b);
        }
      }
  }
}

Vector GridSystem::external_force(const MaterialPoints& points, const Vec3& gravity,
                                  const std::vector<PointSetForce>& forces) const {
  Vector f = Vector::Zero(num_dofs());
  const Index n_points = points.size();
  // Share of each point set's force per point: by mass, or by volume for a massless set.
  std::vector<double> set_mass(forces.size(), 0.0), set_volume(forces.size(), 0.0);
  for (std::size_t k = 0; k < forces.size(); ++k)
    for (Index p = 0; p < n_points; ++p)
      if (points.sets[p] >> forces[k].set & 1u) {
        set_mass[k] += points.mass[p];
        set_volume[k] += points.volume[p];
      }
  for (Index p = 0; p < n_points; ++p) {
    Vec3 force = points.mass[p] * gravity;
    for (std::size_t k = 0; k < forces.size(); ++k)
      if (points.sets[p] >> forces[k].set & 1u)
        force += forces[k].force * (set_mass[k] > 0 ? points.mass[p] / set_mass[k]
                                                    : points.volume[p] / set_volume[k]);
    for_each_weight(points, p, [&](Index node, double N) {
      for (int i = 0; i < dim_; ++i) f(node * dim_ + i) += N * force(i);
    });
  }
  return f;
}

void GridSystem::set_point_targets(std::vector<double> stiffness, std::vector<Vec3> target,
                                   std::vector<unsigned char> mask) {
  target_stiffness_ = std::move(stiffness);
  target_ = std::move(target);
  target_mask_ = std::move(mask);
  point_reaction_.assign(target_stiffness_.size(), Vec3::Zero());
}

void GridSystem::set_point_force_law(std::vector<char> acts, std::vector<Vec3> offset,
                                     PointForceLaw law) {
  force_law_acts_ = std::move(acts);
  force_law_offset_ = std::move(offset);
  force_law_ = std::move(law);
}

void GridSystem::set_constraints(const std::vector<char>& constrained) {
  const Index n_dofs = num_dofs();
  free_index_.assign(n_dofs, -1);
  num_free_ = 0;
  for (Index d = 0; d < n_dofs; ++d)
    if (!constrained[d]) free_index_[d] = num_free_++;

  // Pattern: free unknowns of nodes that share an active cell. Columns are built node by node,
  // so the row indices of each column come out sorted.
  const Index n_nodes = static_cast<Index>(active_nodes_.size());
  std::vector<std::vector<Index>> neighbours(n_nodes);
  for (Index c : active_cells_) {
    const auto nodes = mesh_.cell_nodes(c);
    for (Index a : nodes)
      for (Index b : nodes) neighbours[node_to_active_[a]].push_back(node_to_active_[b]);
  }
  if (wide_stencil())
    for (std::size_t p = 0; p + 1 < wide_start_.size(); ++p)
      for (Index a = wide_start_[p]; a < wide_start_[p + 1]; ++a)
        for (Index b = wide_start_[p]; b < wide_start_[p + 1]; ++b)
          neighbours[wide_nodes_[a]].push_back(wide_nodes_[b]);
  // The volume average couples the stencils of a cell's averaged points (theory §12).
  for (std::size_t ci = 0; ci + 1 < union_start_.size(); ++ci)
    for (Index a = union_start_[ci]; a < union_start_[ci + 1]; ++a)
      neighbours[union_nodes_[a]].insert(neighbours[union_nodes_[a]].end(),
                                         union_nodes_.begin() + union_start_[ci],
                                         union_nodes_.begin() + union_start_[ci + 1]);
  // A block couples its nodes (the ghost penalty: two cells across their face, eq. 6.3).
  for (const NodeBlock& block : step_blocks_)
    for (Index a : block.nodes)
      neighbours[a].insert(neighbours[a].end(), block.nodes.begin(), block.nodes.end());
  for (auto& list : neighbours) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  // Columns in the order of their free index: the displacements of all nodes, then (mixed) the
  // pressures; in each column the displacement rows, then the pressure rows, both ascending.
  std::vector<int> outer(num_free_ + 1, 0);
  std::vector<int> inner;
  const auto add_column = [&](Index a, Index dof) {
    const Index col = free_index_[dof];
    if (col < 0) return;
    for (Index b : neighbours[a])
      for (int k = 0; k < dim_; ++k)
        if (const Index row = free_index_[b * dim_ + k]; row >= 0) inner.push_back(row);
    if (mixed_)
      for (Index b : neighbours[a])
        if (const Index row = free_index_[pressure_dof(b)]; row >= 0) inner.push_back(row);
    outer[col + 1] = static_cast<int>(inner.size());
  };
  for (Index a = 0; a < n_nodes; ++a)
    for (int i = 0; i < dim_; ++i) add_column(a, a * dim_ + i);
  if (mixed_)
    for (Index a = 0; a < n_nodes; ++a) add_column(a, pressure_dof(a));
  pattern_ = SparseMatrix(num_free_, num_free_);
  pattern_.resizeNonZeros(static_cast<Index>(inner.size()));
  std::copy(outer.begin(), outer.end(), pattern_.outerIndexPtr());
  std::copy(inner.begin(), inner.end(), pattern_.innerIndexPtr());
  std::fill(pattern_.valuePtr(), pattern_.valuePtr() + inner.size(), 0.0);

  // Scatter maps: local (row, column) of each active cell -> position in the values array.
  const int m = cell_dofs();
  const Index n_active = static_cast<Index>(active_cells_.size());
  scatter_.assign(std::size_t(n_active) * m * m, -1);
#pragma omp parallel for schedule(dynamic, 64) if (n_active > 256)
  for (Index ci = 0; ci < n_active; ++ci) {
    const auto nodes = mesh_.cell_nodes(active_cells_[ci]);
    std::array<Index, 27> active{};
    for (int a = 0; a < nen_; ++a) active[a] = node_to_active_[nodes[a]];
    for (int lc = 0; lc < m; ++lc) {
      const Index col = free_index_[local_dof(active, nen_, lc)];
      if (col < 0) continue;
      const int* begin = pattern_.innerIndexPtr() + pattern_.outerIndexPtr()[col];
      const int* end = pattern_.innerIndexPtr() + pattern_.outerIndexPtr()[col + 1];
      for (int lr = 0; lr < m; ++lr) {
        const Index row = free_index_[local_dof(active, nen_, lr)];
        if (row < 0) continue;
        const int* at = std::lower_bound(begin, end, row);
        scatter_[(std::size_t(ci) * m + lc) * m + lr] =
            static_cast<int>(at - pattern_.innerIndexPtr());
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Phase 2: Lagrangian
// ---------------------------------------------------------------------------------------------

PointStartState GridSystem::start_state(const MaterialPoints& points, Index p) const {
  return {materials_[points.material[p]],
          points.position[p],
          points.volume[p],
          points.deformation_gradient[p],
          points.elastic_left_cauchy_green[p],
          points.internal[p],
          points.volume_mismatch[p]};
}

void GridSystem::note_inadmissible(Index p, bool stress_update_failed) const {
#pragma omp critical(geompm_inadmissible_point)
  if (inadmissible_point_ < 0 || p < inadmissible_point_) {
    inadmissible_point_ = p;
    inadmissible_by_stress_update_ = stress_update_failed;
  }
}

bool GridSystem::internal_force(const MaterialPoints& points, const Vector& du, Vector& f_int,
                                SparseMatrix* tangent) {
  inadmissible_point_ = -1;
  return dispatch_cell_type(mesh_.cell_type, [&](auto e) {
    using E = decltype(e);
    return mixed_ ? internal_force_typed<E, true>(points, du, f_int, tangent)
                  : internal_force_typed<E, false>(points, du, f_int, tangent);
  });
}

template <int NS, int Dim, class Gradients, class Force, class Stiffness>
void GridSystem::add_point_forces(Index p, const Eigen::Matrix<double, NS, 1>& N,
                                  const Gradients& dN_dX, const Eigen::Matrix<double, NS, Dim>& du,
                                  bool with_tangent, Force& f, Stiffness& K) {
  // Forces that depend on the displacement of one place of the point's domain alone: a force
  // F(u) whose derivative is D = dF/du enters f_int as F W_a and the tangent as W_a W_b D, W the
  // weights of that place. The penalty spring k (u_p - target) of a prescribed motion acts at the
  // point (W = N, docs/theory.md eq. 5.1); a point force law (contact with a rigid footing) at
  // x_p + offset, carried by the step's deformation (W = N + grad N . offset, eq. 13.6).
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
  if (!target_stiffness_.empty() && target_stiffness_[p] > 0.0) {
    const double k = target_stiffness_[p];
    const Eigen::Matrix<double, Dim, 1> u = du.transpose() * N;
    Vec3 force = Vec3::Zero(), reaction = Vec3::Zero();
    Mat3 stiffness = Mat3::Zero();
    for (int i = 0; i < Dim; ++i) {
      if (!(target_mask_[p] >> i & 1u)) continue;
      force(i) = k * (u(i) - target_[p](i));
      stiffness(i, i) = k;
      reaction(i) = -force(i);
    }
    point_reaction_[p] = reaction;
    add(N, force, stiffness);
  }
  if (!force_law_acts_.empty() && force_law_acts_[p]) {
    const Eigen::Matrix<double, NS, 1> W = N + dN_dX * force_law_offset_[p].template head<Dim>();
    Vec3 u = Vec3::Zero(), force;
    u.template head<Dim>() = du.transpose() * W;
    Mat3 stiffness;
    force_law_(p, u, force, stiffness);
    add(W, force, stiffness);
  }
}

template <class E>
void GridSystem::pressure_stabilisation(const MaterialPoints& points, Index ci,
                                        Eigen::Matrix<double, E::nodes, E::nodes>& S) const {
  // Polynomial pressure projection (Dohrmann & Bochev 2004; theory eq. 11.5): the pressure's
  // departure from its mean over the cell, p - Pi p, is penalised with 1/G,
  //   S = sum_p (v_p / G_p) (N_p - m)(N_p - m)^T,   m = sum_p v_p N_p / sum_p v_p,
  // over the cell's mixed points with their start-of-step volumes (so S does not depend on the
  // unknowns). It removes the checkerboard modes equal-order u-p cells allow and vanishes for a
  // pressure constant over the cell. At the field's pressure it is made stronger (eq. 14.4).
  const double strength = settings_.mixed_field_pressure ? field_pressure_stabilisation : 1.0;
  constexpr int nen = E::nodes;
  using Values = Eigen::Matrix<double, nen, 1>;
  S.setZero();
  Values mean = Values::Zero();
  double volume = 0.0;
  for (Index p = cell_point_begin_[ci]; p < cell_point_end_[ci]; ++p)
    if (is_mixed(points, p)) {
      mean += points.volume[p] * Eigen::Map<const Values>(shape_.data() + std::size_t(p) * nen);
      volume += points.volume[p];
    }
  if (volume <= 0.0) return;
  mean /= volume;
  double compliance = 0.0;  // sum of the points' v / G
  for (Index p = cell_point_begin_[ci]; p < cell_point_end_[ci]; ++p)
    if (is_mixed(points, p)) {
      const double shear = materials_[points.material[p]]->elastic_moduli(points.internal[p]).shear;
      const Values d = Eigen::Map<const Values>(shape_.data() + std::size_t(p) * nen) - mean;
      S.noalias() += (strength * points.volume[p] / shear) * (d * d.transpose());
      compliance += points.volume[p] / shear;
    }
  // Eq. 11.10: a share of the exactly integrated projection, with the points' v / G, so that
  // only the cell's constant pressures escape it however its points cluster.
  if (const double floor = settings_.pressure_stabilisation_floor; floor > 0.0)
    S.noalias() += (strength * floor * compliance) * exact_pressure_projection<E>();
}

template <class E>
Stencil<E::nodes, E::dim> GridSystem::cell_stencil(Index p) const {
  PointStencil<E> s;
  s.N = Eigen::Map<const typename E::Values>(shape_.data() + std::size_t(p) * E::nodes);
  s.dN_dX = Eigen::Map<const Eigen::Matrix<double, E::nodes, E::dim>>(
      gradients_.data() + std::size_t(p) * E::nodes * E::dim);
  return s;
}

template <int NS, int Dim, class StencilOf>
bool GridSystem::average_volume_change(const MaterialPoints& points, Index ci,
                                       const Eigen::Matrix<double, NS, Dim>& du,
                                       StencilOf&& stencil_of,
                                       AveragedVolumeChange<NS, Dim>& average) const {
  // Eq. 12.1 and 12.4 over the cell's averaged points: volume ratios weighted by the start-of-step
  // volumes (so the cell's volume is kept exactly: sum_q v_q,n dJ^ = sum_q v_q), divergence
  // operators by the current ones. stencil_of(p): point p's weights over the rows of du.
  const bool axisymmetric = settings_.kinematics == Kinematics::Axisymmetric;
  const Index n = du.rows() * Dim;
  Eigen::Matrix<double, 1, KernelResult<NS, Dim>::n> divergence(1, n);
  double start_volume = 0.0, volume = 0.0;
  average.divergence.setZero(1, n);
  for (Index p = cell_point_begin_[ci]; p < cell_point_end_[ci]; ++p) {
    if (!is_averaged(points, p)) continue;
    double dJ = 1.0;
    if (!point_volume_change(stencil_of(p), start_state(points, p), du, axisymmetric, dJ,
                             divergence)) {
      note_inadmissible(p);
      return false;
    }
    const double v_n = points.volume[p];
    start_volume += v_n;
    volume += v_n * dJ;
    average.divergence += (v_n * dJ) * divergence;
  }
  average.ratio = start_volume > 0.0 ? volume / start_volume : 1.0;
  if (volume > 0.0) average.divergence /= volume;
  return true;
}

template <class E, bool Mixed>
bool GridSystem::internal_force_typed(const MaterialPoints& points, const Vector& du, Vector& f_int,
                                      SparseMatrix* tangent) {
  constexpr int nen = E::nodes, dim = E::dim, n = nen * dim, m = n + (Mixed ? nen : 0);
  f_int = Vector::Zero(num_dofs());
  if (tangent) {
    if (tangent != &pattern_ &&
        (tangent->nonZeros() != pattern_.nonZeros() || tangent->rows() != pattern_.rows()))
      *tangent = pattern_;
    std::fill(tangent->valuePtr(), tangent->valuePtr() + tangent->nonZeros(), 0.0);
  }
  const bool axisymmetric = settings_.kinematics == Kinematics::Axisymmetric;
  const double s_p = pressure_scale_;
  std::atomic<bool> admissible{true};
  for (const auto& colour : colours_) {
    const Index count = static_cast<Index>(colour.size());
#pragma omp parallel for schedule(dynamic, 8) if (count > 64)
    for (Index k = 0; k < count; ++k) {
      const Index ci = colour[k];
      const auto nodes = mesh_.cell_nodes(active_cells_[ci]);
      std::array<Index, nen> active;
      for (int a = 0; a < nen; ++a) active[a] = node_to_active_[nodes[a]];
      Eigen::Matrix<double, nen, dim> du_local;
      Eigen::Matrix<double, m, 1> x_flat;  // the cell's unknowns, local order (local_dof)
      for (int l = 0; l < m; ++l) x_flat(l) = du(local_dof(active, nen, l));
      for (int a = 0; a < nen; ++a) du_local.row(a) = x_flat.template segment<dim>(a * dim);
      Eigen::Matrix<double, nen, 1> p_local;  // nodal pressures (eq. 11.6)
      if constexpr (Mixed)
        for (int a = 0; a < nen; ++a) p_local(a) = pressure_start_(active[a]) + s_p * x_flat(n + a);

      Eigen::Matrix<double, m, 1> f_cell = Eigen::Matrix<double, m, 1>::Zero();
      Eigen::Matrix<double, m, m> K_cell = Eigen::Matrix<double, m, m>::Zero();
      if (empty_offset_[ci] >= 0) {
        const Eigen::Map<const Eigen::Matrix<double, m, m>> K_empty(
            empty_stiffness_.data() + std::size_t(empty_offset_[ci]) * m * m);
        f_cell.noalias() = K_empty * x_flat;
        K_cell = K_empty;
      }
      if constexpr (Mixed) {
        Eigen::Matrix<double, nen, nen> S;
        pressure_stabilisation<E>(points, ci, S);
        // Eq. 11.5 on the pressure, or eq. 11.9 on its change over the step (s_p x, eq. 11.6).
        if (settings_.mixed_incremental_pressure)
          f_cell.template tail<nen>().noalias() += (s_p * s_p) * (S * x_flat.template tail<nen>());
        else
          f_cell.template tail<nen>().noalias() += s_p * (S * p_local);
        K_cell.template bottomRightCorner<nen, nen>() += (s_p * s_p) * S;
      }

      PointStencil<E> s;
      PointKernelResult<E> r;
      [[maybe_unused]] MixedKernelResult<E::nodes, E::dim> rm;
      // Points with a wide stencil are assembled one by one below.
      const Index point_end = wide_stencil() ? cell_point_begin_[ci] : cell_point_end_[ci];
      AveragedVolumeChange<nen, dim> average;
      if (averaging_ && point_end > cell_point_begin_[ci] &&
          !average_volume_change(
              points, ci, du_local, [&](Index q) { return cell_stencil<E>(q); }, average)) {
        admissible = false;
        continue;
      }
      for (Index p = cell_point_begin_[ci]; p < point_end; ++p) {
        s = cell_stencil<E>(p);
        const PointStartState start = start_state(points, p);
        const AveragedVolumeChange<nen, dim>* cell_average =
            is_averaged(points, p) ? &average : nullptr;
        // The point's forces and stiffness by its formulation; then, shared, its prescribed-motion
        // spring and its state.
        const FiniteStrainState* state = &r.state;
        const Mat3* stress = &r.state.cauchy_stress;
        double volume = 0.0, own_volume = 0.0, volume_mismatch = 0.0;
        bool ok = false;
        if constexpr (Mixed) {
          if (is_mixed(points, p)) {
            ok = integrate_mixed_point(
                s, start, du_local, p_local, axisymmetric, tangent != nullptr, rm, cell_average,
                settings_.mixed_field_pressure, settings_.mixed_incremental_pressure);
            if (ok) {
              f_cell.template head<n>() += rm.u.internal_force;
              f_cell.template tail<nen>() += s_p * rm.pressure_residual;
              if (tangent) {
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
        if (!(Mixed && is_mixed(points, p))) {
          ok = integrate_point(s, start, du_local, axisymmetric, tangent != nullptr, r,
                               cell_average);
          if (ok) {
            f_cell.template head<n>() += r.internal_force;
            if (tangent) K_cell.template topLeftCorner<n, n>() += r.stiffness;
            volume = r.state_volume;
            own_volume = r.volume;
          }
        }
        if (!ok) {
          note_inadmissible(p, Mixed && is_mixed(points, p) ? rm.u.state.stress_update_failed
                                                            : r.state.stress_update_failed);
          admissible = false;
          continue;
        }
        if (has_point_force(p))
          add_point_forces(p, s.N, s.dN_dX, du_local, tangent != nullptr, f_cell, K_cell);
        commit(p, *state, volume, *stress, own_volume, volume_mismatch);
      }
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
    }
  }
  if (wide_stencil() && !wide_stencil_point_forces<dim>(points, du, f_int, tangent)) return false;
  add_step_blocks(du, f_int, tangent);
  return admissible;
}

// ---------------------------------------------------------------------------------------------
// DDMP: smoothed gradients over a wider stencil (docs/theory.md §8)
// ---------------------------------------------------------------------------------------------

template <class E>
void GridSystem::build_dual_domain_stencils(const MaterialPoints& points) {
  // Node-averaged gradients (Zhang, Ma & Giguere 2011, J. Comput. Phys. 230): for node j,
  //   G_ij = sum_q v_q N_j(x_q) grad N_i(x_q) / sum_q v_q N_j(x_q)      (theory eq. 8.1)
  // over the points q around j, and at a point p the gradient of N_i becomes
  //   grad~ N_i(x_p) = alpha grad N_i(x_p) + (1 - alpha) sum_j N_j(x_p) G_ij   (theory eq. 8.2)
  // with alpha a bubble of the cell (1 at its centre, 0 on its boundary): the cell's own gradient
  // keeps the smoothed field free of zero-energy (checkerboard) modes, and vanishes where a
  // point crosses into the next cell, so the point's forces change continuously. Exact for
  // linear fields.
  constexpr int nen = E::nodes, dim = E::dim;
  using Gradient = Eigen::Matrix<double, dim, 1>;
  const Index n_points = points.size();
  const Index n_nodes = static_cast<Index>(active_nodes_.size());
  std::vector<double> weight(n_nodes, 0.0);
  std::vector<std::vector<std::pair<Index, Gradient>>> G(n_nodes);
  for (Index q = 0; q < n_points; ++q) {
    const auto nodes = mesh_.cell_nodes(points.cell[q]);
    const double* N = shape_.data() + std::size_t(q) * nen;
    const Eigen::Map<const Eigen::Matrix<double, nen, dim>> dN(gradients_.data() +
                                                               std::size_t(q) * nen * dim);
    for (int a = 0; a < nen; ++a) {
      const Index j = node_to_active_[nodes[a]];
      const double w = points.volume[q] * N[a];
      weight[j] += w;
      auto& row = G[j];
      for (int b = 0; b < nen; ++b) {
        const Index i = node_to_active_[nodes[b]];
        auto it = std::find_if(row.begin(), row.end(), [&](const auto& e) { return e.first == i; });
        if (it == row.end())
          row.emplace_back(i, w * dN.row(b).transpose());
        else
          it->second += w * dN.row(b).transpose();
      }
    }
  }

  wide_start_.assign(n_points + 1, 0);
  wide_nodes_.clear();
  wide_N_.clear();
  wide_gradients_.clear();
  std::vector<std::pair<Index, Gradient>> entries;
  for (Index p = 0; p < n_points; ++p) {
    const auto nodes = mesh_.cell_nodes(points.cell[p]);
    const double* N = shape_.data() + std::size_t(p) * nen;
    const Eigen::Map<const Eigen::Matrix<double, nen, dim>> dN(gradients_.data() +
                                                               std::size_t(p) * nen * dim);
    entries.clear();
    const double alpha = std::clamp(cell_bubble(mesh_.cell_type, points.local[p]), 0.0, 1.0);
    auto add = [&](Index i, const Gradient& g) {
      auto it =
          std::find_if(entries.begin(), entries.end(), [&](const auto& e) { return e.first == i; });
      if (it == entries.end())
        entries.emplace_back(i, g);
      else
        it->second += g;
    };
    for (int a = 0; a < nen; ++a) {
      const Index j = node_to_active_[nodes[a]];
      if (weight[j] > 0.0) {
        for (const auto& [i, g] : G[j]) add(i, ((1.0 - alpha) * N[a] / weight[j]) * g);
      } else {
        // No point weighs on node j: its share falls back to the point's own gradient.
        for (int b = 0; b < nen; ++b)
          add(node_to_active_[nodes[b]], (1.0 - alpha) * N[a] * dN.row(b).transpose());
      }
    }
    for (int b = 0; b < nen; ++b) add(node_to_active_[nodes[b]], alpha * dN.row(b).transpose());
    std::sort(entries.begin(), entries.end(),
              [](const auto& x, const auto& y) { return x.first < y.first; });
    for (const auto& [i, g] : entries) {
      wide_nodes_.push_back(i);
      double value = 0.0;
      for (int a = 0; a < nen; ++a)
        if (node_to_active_[nodes[a]] == i) value = N[a];
      wide_N_.push_back(value);
      for (int d = 0; d < dim; ++d) wide_gradients_.push_back(g(d));
    }
    wide_start_[p + 1] = static_cast<Index>(wide_nodes_.size());
  }
}

// ---------------------------------------------------------------------------------------------
// GIMP: weights averaged over each point's domain (docs/theory.md §9)
// ---------------------------------------------------------------------------------------------

void GridSystem::build_gimp_stencils(const MaterialPoints& points, std::vector<char>& is_active) {
  // Each point's domain: the seeded half-lengths stretched with the diagonal of its domain's F
  // (cpGIMP, eq. 9.4; with a volume average the domain follows the point's own motion, eq. 12.7),
  // clipped to the grid (eq. 9.5); weights and gradients eq. 9.1-9.3 on the grid at
  // the start of the step. Node ids are the mesh's here (initialise renumbers them); every
  // cell the domain overlaps is marked occupied.
  const RectilinearGrid& grid = *rectilinear_;
  const bool axisymmetric = settings_.kinematics == Kinematics::Axisymmetric;
  const Index n_points = points.size();
  wide_start_.assign(n_points + 1, 0);
  wide_nodes_.clear();
  wide_N_.clear();
  wide_gradients_.clear();
  GimpStencil s;
  for (Index p = 0; p < n_points; ++p) {
    const Vec3 half = particle_half_lengths(points.initial_half_size[p],
                                            points.domain_deformation(p, dim_), dim_);
    gimp_stencil(grid, points.position[p], half, points.cell[p], axisymmetric, s);
    wide_nodes_.insert(wide_nodes_.end(), s.nodes.begin(), s.nodes.end());
    wide_N_.insert(wide_N_.end(), s.N.begin(), s.N.end());
    wide_gradients_.insert(wide_gradients_.end(), s.gradients.begin(), s.gradients.end());
    wide_start_[p + 1] = static_cast<Index>(wide_nodes_.size());
    for (int k = s.first_cell[2]; k <= s.last_cell[2]; ++k)
      for (int j = s.first_cell[1]; j <= s.last_cell[1]; ++j)
        for (int i = s.first_cell[0]; i <= s.last_cell[0]; ++i) is_active[grid.cell(i, j, k)] = 1;
  }
}

template <int Dim>
bool GridSystem::wide_stencil_point_forces(const MaterialPoints& points, const Vector& du,
                                           Vector& f_int, SparseMatrix* tangent) {
  // Cell by cell, the points one after the other (their stencils overlap across cells of one
  // colour). With the volume average (theory §12) the averaged points of a cell see the union of
  // their stencils, their own weights padded with zeros, so that the average's rate and every
  // point's forces live on the same unknowns.
  using Dynamic = Stencil<Eigen::Dynamic, Dim>;
  const bool axisymmetric = settings_.kinematics == Kinematics::Axisymmetric;
  Dynamic s;
  KernelResult<Eigen::Dynamic, Dim> r;
  MixedKernelResult<Eigen::Dynamic, Dim> rm;
  AveragedVolumeChange<Eigen::Dynamic, Dim> average;
  Eigen::Matrix<double, Eigen::Dynamic, Dim> du_local;
  Eigen::VectorXd p_local, f_local;
  Eigen::MatrixXd K_local;
  std::vector<Index> dofs, cell_nodes, nodes;
  const int* outer = tangent ? tangent->outerIndexPtr() : nullptr;
  const int* inner = tangent ? tangent->innerIndexPtr() : nullptr;
  // Point p's weights over `over` (sorted active nodes holding its own stencil), into `out`.
  const auto fill_stencil = [&](Index p, const std::vector<Index>& over, Dynamic& out) {
    const Index begin = wide_start_[p], end = wide_start_[p + 1];
    const Index size = static_cast<Index>(over.size());
    if (size == end - begin) {  // its own stencil: a copy
      out.N = Eigen::Map<const Eigen::VectorXd>(wide_N_.data() + begin, size);
      out.dN_dX = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Dim, Eigen::RowMajor>>(
          wide_gradients_.data() + std::size_t(begin) * Dim, size, Dim);
      return;
    }
    out.N.setZero(size);
    out.dN_dX.setZero(size, Dim);
    for (Index a = begin; a < end; ++a) {
      const Index at = std::lower_bound(over.begin(), over.end(), wide_nodes_[a]) - over.begin();
      out.N(at) = wide_N_[a];
      for (int i = 0; i < Dim; ++i) out.dN_dX(at, i) = wide_gradients_[std::size_t(a) * Dim + i];
    }
  };
  const auto gather = [&](const std::vector<Index>& over) {
    du_local.resize(static_cast<Index>(over.size()), Dim);
    for (std::size_t a = 0; a < over.size(); ++a)
      for (int i = 0; i < Dim; ++i) du_local(a, i) = du(over[a] * Dim + i);
  };
  for (std::size_t ci = 0; ci < active_cells_.size(); ++ci) {
    const bool cell_average = averaging_ && union_start_[ci + 1] > union_start_[ci];
    if (cell_average) {
      cell_nodes.assign(union_nodes_.begin() + union_start_[ci],
                        union_nodes_.begin() + union_start_[ci + 1]);
      gather(cell_nodes);
      if (!average_volume_change(
              points, ci, du_local,
              [&](Index q) {
                Dynamic padded;
                fill_stencil(q, cell_nodes, padded);
                return padded;
              },
              average))
        return false;
    }
    for (Index p = cell_point_begin_[ci]; p < cell_point_end_[ci]; ++p) {
      const bool mixed = is_mixed(points, p);
      const bool averaged = cell_average && is_averaged(points, p);
      if (averaged) {
        nodes = cell_nodes;
      } else {
        nodes.assign(wide_nodes_.begin() + wide_start_[p],
                     wide_nodes_.begin() + wide_start_[p + 1]);
      }
      fill_stencil(p, nodes, s);
      gather(nodes);
      const Index ns = static_cast<Index>(nodes.size());
      const PointStartState start = start_state(points, p);
      const int n = static_cast<int>(ns) * Dim, local = n + (mixed ? static_cast<int>(ns) : 0);
      if (mixed) {
        // The pressure is interpolated with the point's own weights (eq. 11.1): its cell's (DDMP)
        // or its domain's (GIMP).
        p_local.resize(ns);
        for (Index a = 0; a < ns; ++a)
          p_local(a) = pressure_start_(nodes[a]) + pressure_scale_ * du(pressure_dof(nodes[a]));
        if (!integrate_mixed_point(s, start, du_local, p_local, axisymmetric, tangent != nullptr,
                                   rm, averaged ? &average : nullptr,
                                   settings_.mixed_field_pressure,
                                   settings_.mixed_incremental_pressure)) {
          note_inadmissible(p, rm.u.state.stress_update_failed);
          return false;
        }
        const double s_p = pressure_scale_;
        f_local.resize(local);
        f_local << rm.u.internal_force, s_p * rm.pressure_residual;
        if (tangent) {
          K_local.resize(local, local);
          K_local << rm.u.stiffness, s_p * rm.K_up, s_p * rm.K_pu, (s_p * s_p) * rm.K_pp;
        }
        commit(p, rm.u.state, rm.u.state_volume, rm.total_stress, rm.u.volume, rm.volume_mismatch);
      } else {
        if (!integrate_point(s, start, du_local, axisymmetric, tangent != nullptr, r,
                             averaged ? &average : nullptr)) {
          note_inadmissible(p, r.state.stress_update_failed);
          return false;
        }
        f_local = r.internal_force;
        if (tangent) K_local = r.stiffness;
        commit(p, r.state, r.state_volume, r.state.cauchy_stress, r.volume);
      }
      // Springs and point force laws act on the displacements, the first ns * Dim local unknowns.
      if (has_point_force(p))
        add_point_forces(p, s.N, s.dN_dX, du_local, tangent != nullptr, f_local, K_local);
      dofs.resize(local);
      for (int l = 0; l < local; ++l) dofs[l] = local_dof(nodes, static_cast<int>(ns), l);
      for (int l = 0; l < local; ++l) f_int(dofs[l]) += f_local(l);
      if (!tangent) continue;
      double* values = tangent->valuePtr();
      for (int lc = 0; lc < local; ++lc) {
        const Index col = free_index_[dofs[lc]];
        if (col < 0) continue;
        const int* at = inner + outer[col];
        const int* end = inner + outer[col + 1];
        // Stencil nodes are sorted and pressures come after displacements: rows ascend.
        for (int lr = 0; lr < local; ++lr) {
          const Index row = free_index_[dofs[lr]];
          if (row < 0) continue;
          at = std::lower_bound(at, end, row);
          values[at - inner] += K_local(lr, lc);
        }
      }
    }
  }
  return true;
}

void GridSystem::build_averaged_stencil_unions(const MaterialPoints& points) {
  // Per active cell, the active nodes of the wide stencils of its averaged points, ascending: the
  // unknowns the cell's volume average couples (theory §12).
  union_start_.assign(active_cells_.size() + 1, 0);
  union_nodes_.clear();
  std::vector<Index> nodes;
  for (std::size_t ci = 0; ci < active_cells_.size(); ++ci) {
    nodes.clear();
    for (Index p = cell_point_begin_[ci]; p < cell_point_end_[ci]; ++p)
      if (is_averaged(points, p))
        nodes.insert(nodes.end(), wide_nodes_.begin() + wide_start_[p],
                     wide_nodes_.begin() + wide_start_[p + 1]);
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    union_nodes_.insert(union_nodes_.end(), nodes.begin(), nodes.end());
    union_start_[ci + 1] = static_cast<Index>(union_nodes_.size());
  }
}

// ---------------------------------------------------------------------------------------------
// Phase 3: convect
// ---------------------------------------------------------------------------------------------

bool GridSystem::commit_state(MaterialPoints& points, const Vector& du) {
  // Each point reads its start state before its state is written, and belongs to one cell (or
  // one wide stencil pass), so writing through while evaluating is safe.
  commit_to_ = &points;
  Vector f_int;
  const bool admissible = internal_force(points, du, f_int, nullptr);
  commit_to_ = nullptr;
  return admissible;
}

void GridSystem::convect(MaterialPoints& points, const Vector& du, const Vector& velocity,
                         const Vector& acceleration, double dt, bool dynamic) {
  if (mixed_ && settings_.fitted_pressure_start) {
    // Eq. 11.11: the converged nodal pressure, where it was well supported, for the next start.
    last_pressure_.assign(mesh_.num_nodes(), std::numeric_limits<double>::quiet_NaN());
    const Vector p = nodal_pressure(du);
    for (std::size_t a = 0; a < active_nodes_.size(); ++a)
      if (pressure_supported_[a]) last_pressure_[active_nodes_[a]] = p(a);
  }
  commit_state(points, du);
  dispatch_cell_type(mesh_.cell_type, [&](auto e) {
    convect_typed<decltype(e)>(points, du, velocity, acceleration, dt, dynamic);
  });
}

template <class E>
void GridSystem::convect_typed(MaterialPoints& points, const Vector& du, const Vector& velocity,
                               const Vector& acceleration, double dt, bool dynamic) const {
  constexpr int dim = E::dim;
  const Index n_points = points.size();
#pragma omp parallel for schedule(static) if (n_points > 4096)
  for (Index p = 0; p < n_points; ++p) {
    // Eq. 7.1 with the point's weights of this step (cell or wide stencil).
    Vec3 dx = Vec3::Zero(), dv = Vec3::Zero(), a = Vec3::Zero();
    for_each_weight(points, p, [&](Index node, double N) {
      for (int i = 0; i < dim; ++i) {
        dx(i) += N * du(node * dim + i);
        dv(i) += N * (velocity(node * dim + i) - velocity_(node * dim + i));
        a(i) += N * acceleration(node * dim + i);
      }
    });
    points.position[p] += dx;
    points.displacement[p] += dx;
    points.phase_displacement[p] += dx;
    if (dynamic) {
      points.velocity[p] += dv;  // FLIP: the grid's velocity change, not its velocity
      points.acceleration[p] = a;
    } else {
      points.velocity[p] = dx / dt;
      points.acceleration[p].setZero();
    }
  }
}

}  // namespace geompm

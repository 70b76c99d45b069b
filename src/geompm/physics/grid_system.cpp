#include "geompm/physics/grid_system.hpp"

#include <algorithm>
#include <cmath>

#include "geompm/mesh/cell_dispatch.hpp"
#include "geompm/mesh/cell_geometry.hpp"
#include "geompm/mesh/element.hpp"
#include "geompm/physics/point_kernel.hpp"

namespace geompm {

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
  interpolation_ = make_interpolation(settings_.interpolation, mesh, settings_.kinematics);
  wide_stencil_ = interpolation_->wide();
}

Vec3 GridSystem::interpolate(const MaterialPoints& points, Index p, const Vector& nodal) const {
  Vec3 value = Vec3::Zero();
  for_each_weight(points, p, [&](Index node, double N) {
    for (int i = 0; i < dim_; ++i) value(i) += N * nodal(node * dim_ + i);
  });
  return value;
}

void GridSystem::distribute(const Communicator& communicator, std::vector<int> cell_part) {
  communicator_ = &communicator;
  cell_part_ = std::move(cell_part);
}

void GridSystem::share_active_cells(std::vector<char>& is_active) const {
  if (!communicator_->distributed()) return;
  std::vector<int> flags(is_active.begin(), is_active.end());
  communicator_->max(flags.data(), flags.size());
  std::copy(flags.begin(), flags.end(), is_active.begin());
}

std::span<const Index> GridSystem::averaged_stencil_union(Index ci) const {
  if (union_start_.empty()) return {};
  return {union_nodes_.data() + union_start_[ci],
          static_cast<std::size_t>(union_start_[ci + 1] - union_start_[ci])};
}

// ---------------------------------------------------------------------------------------------
// Phase 1: initialise
// ---------------------------------------------------------------------------------------------

void GridSystem::initialise(MaterialPoints& points) {
  activate_cells(points);
  // Shape functions and reference gradients at each point, on the grid of this step.
  const Index n_points = points.size(), n_active = static_cast<Index>(active_cells_.size());
  shape_.assign(std::size_t(n_points) * nen_, 0.0);
  gradients_.assign(std::size_t(n_points) * nen_ * dim_, 0.0);
  cell_fill_.assign(n_active, 0.0);
  cell_mixed_fill_.assign(n_active, 0.0);
  cell_size_.assign(n_points, 0.0);
  for_each_cell_typed(
      mesh_, n_active, [&](Index ci) { return active_cells_[ci]; },
      [&](auto e, Index ci) { shape_cell<decltype(e)>(points, ci); }, n_active > 256);
  // A cell's points are all on the process that owns it: the others add nothing to its fill.
  if (communicator_->distributed()) {
    communicator_->sum(cell_fill_);
    communicator_->sum(cell_mixed_fill_);
  }

  interpolation_->after_activation(
      points,
      {mesh_, node_to_active_, static_cast<Index>(active_nodes_.size()), shape_, gradients_,
       *communicator_},
      wide_);
  union_start_.clear();
  union_nodes_.clear();
  if (wide_stencil() && averaging_) build_averaged_stencil_unions(points);
  if (mesh_.mixed())
    dim_ == 3 ? map_to_nodes<0, 3>(points) : map_to_nodes<0, 2>(points);
  else
    dispatch_cell_type(mesh_.cell_type, [&](auto e) {
      using E = decltype(e);
      map_to_nodes<E::nodes, E::dim>(points);
    });
}

void GridSystem::activate_cells(MaterialPoints& points) {
  points.sort_by_cell();
  const Index n_points = points.size();
  const Index n_cells = mesh_.num_cells();

  // Active cells: occupied cells, then `buffer_layers` rings of neighbours (seed §3.2: empty
  // buffer cells catch points that move out of the body, e.g. above a free surface). With GIMP
  // a cell that a point's domain overlaps is occupied too: the nodes of the point's stencil are
  // its nodes.
  std::vector<char> is_active(n_cells, 0);
  for (Index p = 0; p < n_points; ++p) is_active[points.cell[p]] = 1;
  interpolation_->before_activation(points, is_active, wide_);
  share_active_cells(is_active);  // every process activates the cells of every process's points
  std::vector<Index> frontier;
  for (Index c = 0; c < n_cells; ++c)
    if (is_active[c]) frontier.push_back(c);
  for (int layer = 0; layer < settings_.buffer_layers && !frontier.empty(); ++layer) {
    std::vector<Index> next;
    for (Index c : frontier)
      for (Index nb : topology_.cell_neighbours.row(c))
        if (!is_active[nb]) {
          is_active[nb] = 1;
          next.push_back(nb);
        }
    frontier.swap(next);
  }
  // FEM cells take part in every step, with or without points near them (docs/theory.md §19).
  for (Index c = 0; c < n_cells; ++c)
    if (fem_cell(c)) is_active[c] = 1;
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
  colour_active_cells();
}

template <class E>
void GridSystem::shape_cell(const MaterialPoints& points, Index ci) {
  constexpr int nen = E::nodes, dim = E::dim;
  const bool radial = settings_.kinematics == Kinematics::Axisymmetric;
  const Index c = active_cells_[ci];
  const Eigen::Matrix<double, E::nodes, E::dim> X =
      cell_node_coordinates<cell_type_of<E>>(mesh_, c).transpose();
  double occupied = 0.0, occupied_mixed = 0.0;
  for (Index p = cell_point_begin_[ci]; p < cell_point_end_[ci]; ++p) {
    const auto s = make_stencil<E>(X, points.local[p].template head<dim>());
    Eigen::Map<typename E::Values>(shape_.data() + std::size_t(p) * nen_) = s.N;
    Eigen::Map<Eigen::Matrix<double, nen, dim>>(gradients_.data() + std::size_t(p) * nen_ * dim) =
        s.dN_dX;
    occupied += points.volume[p];
    if (is_mixed(points, p)) occupied_mixed += points.volume[p];
  }
  const double measure = cell_measure(mesh_, c, radial);
  cell_fill_[ci] = fem_cell(c) ? 1.0 : std::min(1.0, occupied / measure);
  cell_mixed_fill_[ci] = std::min(1.0, occupied_mixed / measure);
  const double size = std::pow(cell_measure(mesh_, c, false), 1.0 / dim);
  for (Index p = cell_point_begin_[ci]; p < cell_point_end_[ci]; ++p) cell_size_[p] = size;
}

template <int nen, int dim>
void GridSystem::map_to_nodes(const MaterialPoints& points) {
  // Mass, momentum and acceleration to the nodes (seed eq. 9), in point order (deterministic).
  const Index n_nodes = static_cast<Index>(active_nodes_.size());
  mass_ = Vector::Zero(n_nodes);
  velocity_ = Vector::Zero(std::size_t(n_nodes) * dim_);
  acceleration_ = Vector::Zero(std::size_t(n_nodes) * dim_);
  for (Index p = 0; p < points.size(); ++p)
    for_each_weight_typed<nen>(points, p, [&](Index node, double N) {
      const double w = points.mass[p] * N;
      mass_(node) += w;
      for (int i = 0; i < dim; ++i) {
        velocity_(node * dim + i) += w * points.velocity[p](i);
        acceleration_(node * dim + i) += w * points.acceleration[p](i);
      }
    });
  if (communicator_->distributed()) {  // nodes shared between processes: sum every share
    communicator_->sum(mass_.data(), mass_.size());
    communicator_->sum(velocity_.data(), velocity_.size());
    communicator_->sum(acceleration_.data(), acceleration_.size());
  }
  const double tiny = n_nodes > 0 ? 1e-14 * std::max(mass_.maxCoeff(), 0.0) : 0.0;
  for (Index a = 0; a < n_nodes; ++a)
    for (int i = 0; i < dim; ++i) {
      const Index d = a * dim + i;
      if (mass_(a) > tiny) {
        velocity_(d) /= mass_(a);
        acceleration_(d) /= mass_(a);
      } else {
        velocity_(d) = acceleration_(d) = 0.0;
      }
    }
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
        nodes.insert(nodes.end(), wide_.nodes.begin() + wide_.start[p],
                     wide_.nodes.begin() + wide_.start[p + 1]);
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    union_nodes_.insert(union_nodes_.end(), nodes.begin(), nodes.end());
    union_start_[ci + 1] = static_cast<Index>(union_nodes_.size());
  }
}

// ---------------------------------------------------------------------------------------------
// Phase 3: convect
// ---------------------------------------------------------------------------------------------

void GridSystem::convect(MaterialPoints& points, const Vector& du, const Vector& velocity,
                         const Vector& acceleration, double dt, bool dynamic) const {
  if (mesh_.mixed()) {
    if (dim_ == 3)
      convect_typed<0, 3>(points, du, velocity, acceleration, dt, dynamic);
    else
      convect_typed<0, 2>(points, du, velocity, acceleration, dt, dynamic);
    return;
  }
  dispatch_cell_type(mesh_.cell_type, [&](auto e) {
    using E = decltype(e);
    convect_typed<E::nodes, E::dim>(points, du, velocity, acceleration, dt, dynamic);
  });
}

template <int nen, int dim>
void GridSystem::convect_typed(MaterialPoints& points, const Vector& du, const Vector& velocity,
                               const Vector& acceleration, double dt, bool dynamic) const {
  const Index n_points = points.size();
#pragma omp parallel for schedule(static) if (n_points > 4096)
  for (Index p = 0; p < n_points; ++p) {
    // Eq. 7.1 with the point's weights of this step (cell or wide stencil).
    Vec3 dx = Vec3::Zero(), dv = Vec3::Zero(), a = Vec3::Zero();
    for_each_weight_typed<nen>(points, p, [&](Index node, double N) {
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

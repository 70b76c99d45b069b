#include "geompm/physics/grid_system.hpp"

#include <algorithm>
#include <cmath>

#include "geompm/mesh/cell_geometry.hpp"
#include "geompm/mesh/element.hpp"
#include "geompm/physics/gimp_weights.hpp"
#include "geompm/physics/point_kernel.hpp"

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

Vec3 GridSystem::interpolate(const MaterialPoints& points, Index p, const Vector& nodal) const {
  Vec3 value = Vec3::Zero();
  for_each_weight(points, p, [&](Index node, double N) {
    for (int i = 0; i < dim_; ++i) value(i) += N * nodal(node * dim_ + i);
  });
  return value;
}

void GridSystem::place_weights(const MaterialPoints& points, Index p, const Vec3& offset,
                               PlaceWeights& out) const {
  out.nodes.clear();
  out.W.clear();
  const auto add = [&](Index node, double N, const double* gradient) {
    double w = N;
    for (int d = 0; d < dim_; ++d) w += gradient[d] * offset(d);
    out.nodes.push_back(node);
    out.W.push_back(w);
  };
  if (wide_stencil()) {
    for (Index a = wide_start_[p]; a < wide_start_[p + 1]; ++a)
      add(wide_nodes_[a], wide_N_[a], wide_gradients_.data() + std::size_t(a) * dim_);
    return;
  }
  const auto nodes = mesh_.cell_nodes(points.cell[p]);
  const double* G = gradients_.data() + std::size_t(p) * nen_ * dim_;
  for (int a = 0; a < nen_; ++a) {
    double gradient[3] = {0, 0, 0};
    for (int d = 0; d < dim_; ++d) gradient[d] = G[d * nen_ + a];
    add(node_to_active_[nodes[a]], shape_[std::size_t(p) * nen_ + a], gradient);
  }
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

  if (settings_.interpolation == GridInterpolation::DualDomain)
    build_dual_domain_stencils<E>(points);
  union_start_.clear();
  union_nodes_.clear();
  if (wide_stencil() && averaging_) build_averaged_stencil_unions(points);
  map_to_nodes(points);
}

void GridSystem::map_to_nodes(const MaterialPoints& points) {
  // Mass, momentum and acceleration to the nodes (seed eq. 9), in point order (deterministic).
  const Index n_nodes = static_cast<Index>(active_nodes_.size());
  mass_ = Vector::Zero(n_nodes);
  velocity_ = Vector::Zero(std::size_t(n_nodes) * dim_);
  acceleration_ = Vector::Zero(std::size_t(n_nodes) * dim_);
  for (Index p = 0; p < points.size(); ++p)
    for_each_weight(points, p, [&](Index node, double N) {
      const double w = points.mass[p] * N;
      mass_(node) += w;
      for (int i = 0; i < dim_; ++i) {
        velocity_(node * dim_ + i) += w * points.velocity[p](i);
        acceleration_(node * dim_ + i) += w * points.acceleration[p](i);
      }
    });
  const double tiny = n_nodes > 0 ? 1e-14 * std::max(mass_.maxCoeff(), 0.0) : 0.0;
  for (Index a = 0; a < n_nodes; ++a)
    for (int i = 0; i < dim_; ++i) {
      const Index d = a * dim_ + i;
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

void GridSystem::convect(MaterialPoints& points, const Vector& du, const Vector& velocity,
                         const Vector& acceleration, double dt, bool dynamic) const {
  const int dim = dim_;
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

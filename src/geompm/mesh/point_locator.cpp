#include "geompm/mesh/point_locator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geompm/mesh/cell_geometry.hpp"
#include "geompm/mesh/mesh_topology.hpp"

namespace geompm {

namespace {

/// Relative widening of each cell's box, so that a point on a face or at a node (or off it by
/// round-off) falls in the buckets of every cell that touches it.
constexpr double box_pad = 1e-8;

/// Cells per bucket is kept near one by sizing buckets like cells; this caps the bucket count
/// for meshes whose cells have very different sizes.
constexpr double max_buckets_per_cell = 8.0;

/// CSR from (row, value) pairs given as a count pass and a fill pass over the same generator.
template <class ForEachPair>
void build_csr(Index rows, ForEachPair&& for_each_pair, std::vector<Index>& start,
               std::vector<Index>& values) {
  start.assign(static_cast<std::size_t>(rows) + 1, 0);
  for_each_pair([&](Index row, Index) { ++start[row + 1]; });
  for (Index r = 0; r < rows; ++r) start[r + 1] += start[r];
  values.resize(start[rows]);
  std::vector<Index> next(start.begin(), start.end() - 1);
  for_each_pair([&](Index row, Index value) { values[next[row]++] = value; });
}

}  // namespace

PointLocator::PointLocator(const Mesh& mesh) : mesh_(mesh) {
  const Index num_cells = mesh.num_cells();
  const int dim = mesh.dim();
  lower_.setZero();
  upper_.setZero();
  buckets_.setOnes();
  bucket_size_.setOnes();
  bucket_start_.assign(2, 0);
  neighbour_start_.assign(static_cast<std::size_t>(num_cells) + 1, 0);
  if (num_cells == 0) return;

  // Padded cell boxes, their union, and the mean cell extent.
  cell_boxes_.resize(static_cast<std::size_t>(num_cells) * 2 * dim);
  Vec3 mean_extent = Vec3::Zero();
  Vec3 mesh_lower = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 mesh_upper = -mesh_lower;
  for (Index c = 0; c < num_cells; ++c) {
    auto [lower, upper] = cell_bounding_box(mesh, c);
    mean_extent += upper - lower;
    const double pad = box_pad * (upper - lower).norm();
    lower.array() -= pad;
    upper.array() += pad;
    double* box = cell_boxes_.data() + static_cast<std::size_t>(c) * 2 * dim;
    for (int i = 0; i < dim; ++i) box[i] = lower[i], box[dim + i] = upper[i];
    mesh_lower = mesh_lower.cwiseMin(lower);
    mesh_upper = mesh_upper.cwiseMax(upper);
  }
  mean_extent /= num_cells;

  // Buckets about the size of a mean cell, so that each holds a few candidates. The grid
  // starts half a bucket before the mesh: on a regular grid of cells the bucket faces then
  // cut cells in the middle instead of running along cell faces, where the padded boxes
  // would put every cell into three buckets per axis instead of two.
  const Vec3 extent = mesh_upper - mesh_lower;
  const double cap = max_buckets_per_cell * num_cells + 64.0;
  const auto count = [&](int i) { return std::ceil(extent[i] / bucket_size_[i] + 0.5); };
  double total = 1.0;
  for (int i = 0; i < dim; ++i) {
    bucket_size_[i] = mean_extent[i] > 0.0 ? mean_extent[i] : (extent[i] > 0.0 ? extent[i] : 1.0);
    total *= count(i);
  }
  if (total > cap) {  // cells of very different sizes, or far apart: fewer, larger buckets
    const double grow = std::pow(total / cap, 1.0 / dim);
    for (int i = 0; i < dim; ++i) bucket_size_[i] *= grow;
  }
  for (int i = 0; i < dim; ++i) buckets_[i] = static_cast<int>(std::min(count(i), cap));
  for (int i = 0; i < dim; ++i) {
    lower_[i] = mesh_lower[i] - 0.5 * bucket_size_[i];
    upper_[i] = mesh_upper[i];
  }

  const auto bucket_of = [&](int axis, double x) {
    return std::clamp(static_cast<int>(std::floor((x - lower_[axis]) / bucket_size_[axis])), 0,
                      buckets_[axis] - 1);
  };
  const Index num_buckets = buckets_.prod();
  build_csr(
      num_buckets,
      [&](auto&& emit) {
        int first[3] = {0, 0, 0}, last[3] = {0, 0, 0};
        for (Index c = 0; c < num_cells; ++c) {
          const double* box = cell_boxes_.data() + static_cast<std::size_t>(c) * 2 * dim;
          for (int i = 0; i < dim; ++i) {
            first[i] = bucket_of(i, box[i]);
            last[i] = bucket_of(i, box[dim + i]);
          }
          for (int k = first[2]; k <= last[2]; ++k)
            for (int j = first[1]; j <= last[1]; ++j)
              for (int i = first[0]; i <= last[0]; ++i)
                emit(i + buckets_[0] * (j + buckets_[1] * k), c);
        }
      },
      bucket_start_, bucket_cells_);

  // Neighbours: cells that share at least one node.
  MeshTopology topology = build_mesh_topology(mesh);
  neighbour_start_ = std::move(topology.cell_neighbours.start);
  neighbour_cells_ = std::move(topology.cell_neighbours.entries);
}

namespace {

/// Whether cell c of type T holds `x` (its padded box of `boxes` first, from one cache line;
/// then the inverse of its map): fills `location`.
template <CellType T>
bool typed_cell_holds(const Mesh& mesh, const double* boxes, Index c, const Vec3& x,
                      Location& location) {
  constexpr int dim = Element<T>::dim;
  const double* box = boxes + static_cast<std::size_t>(c) * 2 * dim;
  const typename Element<T>::Local point = x.head<dim>();
  for (int i = 0; i < dim; ++i)
    if (!(point[i] >= box[i] && point[i] <= box[dim + i])) return false;
  const auto xi = map_to_reference<T>(cell_node_coordinates<T>(mesh, c), point);
  if (!xi || !Element<T>::contains(*xi, reference_tolerance)) return false;
  location.cell = c;
  location.xi.setZero();
  location.xi.head<dim>() = *xi;
  return true;
}

}  // namespace

std::optional<Location> PointLocator::locate(const Vec3& x, Index hint) const {
  if (mesh_.num_cells() == 0) return std::nullopt;
  if (mesh_.mixed())  // per cell: its type
    return search(x, hint, [&](Index c, Location& location) {
      return dispatch_cell_type(mesh_.type_of(c), [&](auto e) {
        return typed_cell_holds<cell_type_of<decltype(e)>>(mesh_, cell_boxes_.data(), c, x,
                                                           location);
      });
    });
  return dispatch_cell_type(mesh_.cell_type, [&](auto e) {
    return search(x, hint, [&](Index c, Location& location) {
      return typed_cell_holds<cell_type_of<decltype(e)>>(mesh_, cell_boxes_.data(), c, x, location);
    });
  });
}

template <class Holds>
std::optional<Location> PointLocator::search(const Vec3& x, Index hint, Holds&& holds) const {
  const Index num_cells = mesh_.num_cells();
  const int dim = mesh_.dim();
  Location location;
  // Most points stay in their cell or move to a neighbour within a step.
  if (hint >= 0 && hint < num_cells) {
    if (holds(hint, location)) return location;
    for (Index k = neighbour_start_[hint]; k < neighbour_start_[hint + 1]; ++k)
      if (holds(neighbour_cells_[k], location)) return location;
  }
  int bucket[3] = {0, 0, 0};
  for (int i = 0; i < dim; ++i) {
    if (!(x[i] >= lower_[i] && x[i] <= upper_[i])) return std::nullopt;  // also NaN
    bucket[i] = std::min(static_cast<int>((x[i] - lower_[i]) / bucket_size_[i]), buckets_[i] - 1);
  }
  const Index b = bucket[0] + buckets_[0] * (bucket[1] + buckets_[1] * bucket[2]);
  for (Index k = bucket_start_[b]; k < bucket_start_[b + 1]; ++k)
    if (holds(bucket_cells_[k], location)) return location;
  return std::nullopt;
}

}  // namespace geompm

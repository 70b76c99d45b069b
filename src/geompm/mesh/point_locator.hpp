// Finds the cell that contains a physical point, for seeding and for relocating material points
// after each step. A uniform bucket grid over the cells' bounding boxes keeps a query O(1) on
// average (no scan over cells), so that 10^6 points relocate in well under a second; the cell a
// point was in before is tried first, since most points stay in or next to it.
#pragma once

#include <optional>
#include <vector>

#include "geompm/mesh/mesh.hpp"

namespace geompm {

struct Location {
  Index cell = -1;
  Vec3 xi = Vec3::Zero();  // reference coordinates in that cell
};

class PointLocator {
 public:
  explicit PointLocator(const Mesh& mesh);

  /// The cell containing x, trying `hint` (a cell id, or -1) and its neighbours first.
  /// nullopt when x is outside the mesh. Thread-safe (const).
  std::optional<Location> locate(const Vec3& x, Index hint = -1) const;

  const Mesh& mesh() const { return mesh_; }

 private:
  /// The search (hint, its neighbours, then the bucket of x) with holds(c, location) testing a
  /// cell: typed once for a uniform mesh, per cell for a mixed one.
  template <class Holds>
  std::optional<Location> search(const Vec3& x, Index hint, Holds&& holds) const;

  const Mesh& mesh_;
  Vec3 lower_, upper_;
  Eigen::Vector3i buckets_;
  Vec3 bucket_size_;
  std::vector<Index> bucket_start_;  // CSR: bucket -> candidate cells
  std::vector<Index> bucket_cells_;
  std::vector<double> cell_boxes_;      // per cell: padded lower[dim], upper[dim], tested first
  std::vector<Index> neighbour_start_;  // CSR: cell -> cells sharing a node
  std::vector<Index> neighbour_cells_;
};

}  // namespace geompm

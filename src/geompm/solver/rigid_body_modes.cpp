#include "geompm/solver/rigid_body_modes.hpp"

#include <Eigen/Geometry>  // cross

namespace geompm {

Eigen::MatrixXd rigid_body_modes(const LinearSolverHints& hints) {
  const int dim = hints.block_size;
  const int rotations = dim == 3 ? 3 : dim == 2 ? 1 : 0;
  const Index rows = static_cast<Index>(hints.unknown_node.size());
  Eigen::MatrixXd modes = Eigen::MatrixXd::Zero(rows, dim + rotations);
  // About the centroid, so that the rotations are not dominated by a translation far from 0.
  Vec3 centre = Vec3::Zero();
  for (const Vec3& x : hints.node_coordinates) centre += x;
  if (!hints.node_coordinates.empty()) centre /= double(hints.node_coordinates.size());
  for (Index row = 0; row < rows; ++row) {
    const Index node = hints.unknown_node[row];
    if (node < 0) continue;
    const int i = hints.unknown_component[row];
    const Vec3 r = hints.node_coordinates[node] - centre;
    modes(row, i) = 1.0;
    // Rotation about axis a: u = e_a x r; component i of it.
    for (int k = 0; k < rotations; ++k) {
      const int axis = dim == 3 ? k : 2;
      modes(row, dim + k) = Vec3::Unit(axis).cross(r)(i);
    }
  }
  return modes;
}

}  // namespace geompm

// The rigid-body modes from the linear solver's hints (solver/rigid_body_modes.hpp): a free
// spring network's stiffness has them as its null space, in 2D and 3D, whatever rows a
// constraint took out of the matrix, and the rows of another field (pressure) are zero.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <vector>

#include "geompm/solver/rigid_body_modes.hpp"

namespace geompm {
namespace {

// The stiffness of springs between every pair of `nodes` (a truss), dim unknowns per node,
// node-major, followed by `extra` unknowns of another field with a unit diagonal.
Eigen::MatrixXd truss(const std::vector<Vec3>& nodes, int dim, int extra) {
  const int n = int(nodes.size()) * dim;
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n + extra, n + extra);
  for (std::size_t a = 0; a < nodes.size(); ++a)
    for (std::size_t b = a + 1; b < nodes.size(); ++b) {
      const Eigen::VectorXd t = (nodes[b] - nodes[a]).normalized().head(dim);
      const Eigen::MatrixXd kab = t * t.transpose();
      k.block(a * dim, a * dim, dim, dim) += kab;
      k.block(b * dim, b * dim, dim, dim) += kab;
      k.block(a * dim, b * dim, dim, dim) -= kab;
      k.block(b * dim, a * dim, dim, dim) -= kab;
    }
  for (int e = 0; e < extra; ++e) k(n + e, n + e) = 1.0;
  return k;
}

LinearSolverHints hints(const std::vector<Vec3>& nodes, int dim, int extra) {
  LinearSolverHints h;
  h.block_size = dim;
  h.node_coordinates = nodes;
  for (std::size_t a = 0; a < nodes.size(); ++a)
    for (int i = 0; i < dim; ++i) {
      h.unknown_node.push_back(Index(a));
      h.unknown_component.push_back(i);
    }
  for (int e = 0; e < extra; ++e) {
    h.unknown_node.push_back(-1);
    h.unknown_component.push_back(-1);
  }
  return h;
}

void expect_null_space(const std::vector<Vec3>& nodes, int dim, int modes_expected) {
  const int extra = 2;
  const Eigen::MatrixXd k = truss(nodes, dim, extra);
  const Eigen::MatrixXd modes = rigid_body_modes(hints(nodes, dim, extra));
  ASSERT_EQ(modes.cols(), modes_expected);
  ASSERT_EQ(modes.rows(), k.rows());
  EXPECT_LT((k * modes).norm(), 1e-12 * k.norm() * modes.norm());
  EXPECT_EQ(modes.bottomRows(extra).norm(), 0.0);
  // Independent: the modes span modes_expected dimensions.
  EXPECT_EQ(Eigen::FullPivLU<Eigen::MatrixXd>(modes).rank(), modes_expected);
  // A rotation is no translation: the truss resists a stretch, which is no mode.
  Eigen::VectorXd stretch = Eigen::VectorXd::Zero(k.rows());
  for (std::size_t a = 0; a < nodes.size(); ++a) stretch(a * dim) = nodes[a].x();
  EXPECT_GT((k * stretch).norm(), 1e-3);
}

TEST(RigidBodyModes, AreTheNullSpaceOfAFreeTrussIn2D) {
  expect_null_space({Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0.5, 1.5, 0), Vec3(2.2, 1.1, 0)}, 2, 3);
}

TEST(RigidBodyModes, AreTheNullSpaceOfAFreeTrussIn3D) {
  expect_null_space(
      {Vec3(0, 0, 0), Vec3(1, 0, 0.2), Vec3(0, 1.3, 0), Vec3(0.1, 0.2, 0.9), Vec3(1.1, 0.9, 1.2)},
      3, 6);
}

TEST(RigidBodyModes, FollowTheRowsAConstraintLeft) {
  // Node 0's x is constrained: its row is not in the matrix; the others keep their values.
  const std::vector<Vec3> nodes{Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0.5, 1.5, 0)};
  LinearSolverHints all = hints(nodes, 2, 0), reduced = all;
  reduced.unknown_node.erase(reduced.unknown_node.begin());
  reduced.unknown_component.erase(reduced.unknown_component.begin());
  const Eigen::MatrixXd full = rigid_body_modes(all), kept = rigid_body_modes(reduced);
  EXPECT_EQ(kept, full.bottomRows(full.rows() - 1));
}

}  // namespace
}  // namespace geompm

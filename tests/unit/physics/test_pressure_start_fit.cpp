// The fitted start of the nodal pressure (theory eq. 11.11): exact for linear fields at every
// node, boundary and corner nodes included, on any cell type; the node-to-node patterns damped
// by the closed-form factors of the 3 x 3 patch on a uniform grid.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numeric>

#include "geompm/mesh/structured_mesh.hpp"
#include "geompm/physics/pressure_start_fit.hpp"

namespace geompm {
namespace {

struct Grid {
  Mesh mesh;
  std::vector<Index> cells, nodes, node_to_active;
};

Grid grid_of(CellType type, int dim, bool graded) {
  StructuredMeshSpec spec;
  spec.cell_type = type;
  for (int i = 0; i < dim; ++i)
    spec.axes[i] = graded ? std::vector<AxisSegment>{{1.0, 3, 1.0}, {2.0, 3, 2.5}}
                          : std::vector<AxisSegment>{{1.0, 8, 1.0}};
  Grid g;
  g.mesh = generate_structured_mesh(spec);
  g.cells.resize(g.mesh.num_cells());
  std::iota(g.cells.begin(), g.cells.end(), Index(0));
  g.nodes.resize(g.mesh.num_nodes());
  std::iota(g.nodes.begin(), g.nodes.end(), Index(0));
  g.node_to_active = g.nodes;
  return g;
}

template <class Field>
Eigen::VectorXd fitted(const Grid& g, Field&& field, std::vector<char> fit = {}) {
  std::vector<double> last(g.mesh.num_nodes());
  for (Index n = 0; n < g.mesh.num_nodes(); ++n) last[n] = field(g.mesh.nodes[n]);
  if (fit.empty()) fit.assign(g.nodes.size(), 1);
  Eigen::VectorXd start = Eigen::VectorXd::Constant(Index(g.nodes.size()), -99.0);
  fit_pressure_start(g.mesh, g.cells, g.nodes, g.node_to_active, last, fit, start);
  return start;
}

TEST(PressureStartFit, KeepsLinearFieldsAtEveryNode) {
  const auto linear = [](const Vec3& x) { return 3.0 - 2.0 * x(0) + 0.7 * x(1) + 1.3 * x(2); };
  for (auto [type, dim] : {std::pair{CellType::Quad4, 2}, std::pair{CellType::Tri3, 2},
                           std::pair{CellType::Hex8, 3}, std::pair{CellType::Tet4, 3}}) {
    const Grid g = grid_of(type, dim, true);  // graded: unequal spacing around the nodes
    const Eigen::VectorXd start = fitted(g, linear);
    for (Index n = 0; n < g.mesh.num_nodes(); ++n)
      EXPECT_NEAR(start(n), linear(g.mesh.nodes[n]), 1e-12) << int(type) << " " << n;
  }
}

TEST(PressureStartFit, DampsTheCheckerboardAndTheStripes) {
  // Interior nodes of a uniform Quad4 grid: the fit's value is the mean over the 3 x 3 patch
  // (its gradient terms vanish by symmetry): for a checkerboard, 5 of the 9 values have the
  // centre's sign and 4 the other, so it keeps 1/9 of its amplitude; a stripe alternating
  // between rows (3 values of the centre's sign, 6 of the other) keeps -1/3.
  const Grid g = grid_of(CellType::Quad4, 2, false);
  const double h = 1.0 / 8.0;
  const auto parity = [h](double x) { return int(std::lround(x / h)) % 2 == 0 ? 1.0 : -1.0; };
  const auto checkerboard = [&](const Vec3& x) { return parity(x(0)) * parity(x(1)); };
  const auto stripes = [&](const Vec3& x) { return parity(x(1)); };
  const Eigen::VectorXd damped = fitted(g, checkerboard), striped = fitted(g, stripes);
  int interior = 0;
  for (Index n = 0; n < g.mesh.num_nodes(); ++n) {
    const Vec3& x = g.mesh.nodes[n];
    if (x(0) < h / 2 || x(0) > 1 - h / 2 || x(1) < h / 2 || x(1) > 1 - h / 2) {
      // Boundary nodes: damped too, though not by the interior's factors.
      EXPECT_LT(std::abs(damped(n)), 1.0);
      continue;
    }
    ++interior;
    EXPECT_NEAR(damped(n), checkerboard(x) / 9.0, 1e-12);
    EXPECT_NEAR(striped(n), -stripes(x) / 3.0, 1e-12);
  }
  EXPECT_EQ(interior, 49);
}

TEST(PressureStartFit, LeavesNodesItCannotFit) {
  const Grid g = grid_of(CellType::Quad4, 2, false);
  const auto field = [](const Vec3& x) { return x(0) * x(0); };
  std::vector<char> fit(g.nodes.size(), 1);
  fit[0] = 0;  // not to be fitted: keeps what it had
  std::vector<double> last(g.mesh.num_nodes());
  for (Index n = 0; n < g.mesh.num_nodes(); ++n) last[n] = field(g.mesh.nodes[n]);
  last[10] = std::numeric_limits<double>::quiet_NaN();  // no last value: keeps what it had
  // The corner node (8 x 8 cells: node 80 at x = y = 1) with two of its three neighbours
  // unknown has no more than dim + 1 known values: it takes its own last value.
  last[79] = last[71] = std::numeric_limits<double>::quiet_NaN();
  Eigen::VectorXd start = Eigen::VectorXd::Constant(Index(g.nodes.size()), -99.0);
  fit_pressure_start(g.mesh, g.cells, g.nodes, g.node_to_active, last, fit, start);
  EXPECT_EQ(start(0), -99.0);
  EXPECT_EQ(start(10), -99.0);
  EXPECT_EQ(start(80), last[80]);
  EXPECT_NE(start(40), last[40]);  // an interior node of a curved field moves
}

}  // namespace
}  // namespace geompm

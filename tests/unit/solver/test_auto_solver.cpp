// `auto` (solver/auto_solver.cpp) picks the direct solver below its limit of unknowns and AMG
// from there on; by default the limit depends on the dimension (5·10^5 in 2D, 10^4 in 3D,
// docs/performance.md note 21), which the displacement block size of the hints tells it.
#include <gtest/gtest.h>

#include <vector>

#include "geompm/solver/linear_solver.hpp"

namespace geompm {
namespace {

// Three uncoupled copies (the displacement components) of the 7-point Laplacian on an n^3 grid
// of nodes, shifted to be well conditioned: 3 n^3 unknowns, symmetric positive definite.
SparseMatrix vector_laplacian(int n) {
  const Index nodes = Index(n) * n * n;
  std::vector<Eigen::Triplet<double>> entries;
  const auto node = [n](int i, int j, int k) { return (Index(k) * n + j) * n + i; };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) {
          const Index row = 3 * node(i, j, k) + c;
          entries.emplace_back(row, row, 6.1);
          const int at[3] = {i, j, k};
          for (int axis = 0; axis < 3; ++axis)
            for (const int step : {-1, 1}) {
              int next[3] = {i, j, k};
              next[axis] = at[axis] + step;
              if (next[axis] < 0 || next[axis] >= n) continue;
              entries.emplace_back(row, 3 * node(next[0], next[1], next[2]) + c, -1.0);
            }
        }
  SparseMatrix a(3 * nodes, 3 * nodes);
  a.setFromTriplets(entries.begin(), entries.end());
  return a;
}

LinearSolverHints hints_with_block_size(const SparseMatrix& a, int block_size) {
  LinearSolverHints hints;
  hints.symmetric = true;
  hints.block_size = block_size;
  const Index nodes = a.rows() / block_size;
  for (Index p = 0; p < nodes; ++p) hints.node_coordinates.emplace_back(double(p), 0.0, 0.0);
  for (Index row = 0; row < a.rows(); ++row) {
    hints.unknown_node.push_back(row / block_size);
    hints.unknown_component.push_back(int(row % block_size));
  }
  return hints;
}

// The Krylov iterations `auto` reports for one solve (a direct solve reports 1), after checking
// the solution.
int auto_solve(const SparseMatrix& a, int block_size, Index direct_limit = -1) {
  LinearSolverOptions options;
  options.direct_limit = direct_limit;
  auto solver = create_linear_solver("auto", options);
  solver->analyse(a, hints_with_block_size(a, block_size));
  solver->setup(a);
  const Vector b = Vector::Ones(a.rows());
  Vector x;
  const int iterations = solver->solve(b, x, 1e-10);
  EXPECT_LT((a * x - b).norm(), 1e-8 * b.norm());
  return iterations;
}

TEST(AutoSolver, InThreeDimensionsAmgTakesOverFromTenThousandUnknowns) {
  const SparseMatrix a = vector_laplacian(16);  // 12288 unknowns
  ASSERT_GT(a.rows(), default_direct_limit_3d);
  EXPECT_GT(auto_solve(a, 3), 1);                   // 3D: AMG
  EXPECT_EQ(auto_solve(a, 2), 1);                   // the same size in 2D: direct
  EXPECT_EQ(auto_solve(a, 3, 20000), 1);            // a limit given applies in 3D too
  const SparseMatrix small = vector_laplacian(12);  // 5184 unknowns
  EXPECT_EQ(auto_solve(small, 3), 1);
}

}  // namespace
}  // namespace geompm

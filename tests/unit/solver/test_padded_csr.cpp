// The layout the PETSc backend gives PETSc (solver/padded_csr.hpp): rows by node blocks, an
// identity row for each constrained displacement component, the other fields after; the values
// copied straight from Eigen's compressed columns. Checked against the dense matrix.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <vector>

#include "geompm/solver/padded_csr.hpp"

namespace geompm {
namespace {

// 3 nodes of 2 components, node 1's x constrained (not a row); then 2 pressure rows. geompm's
// rows: 0 = (0,x), 1 = (0,y), 2 = (1,y), 3 = (2,x), 4 = (2,y), 5, 6 = pressure.
LinearSolverHints hints() {
  LinearSolverHints h;
  h.block_size = 2;
  h.node_coordinates = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  h.unknown_node = {0, 0, 1, 2, 2, -1, -1};
  h.unknown_component = {0, 1, 1, 0, 1, -1, -1};
  h.fields = {{"displacement", {0, 1, 2, 3, 4}}, {"pressure", {5, 6}}};
  return h;
}

SparseMatrix matrix() {
  Eigen::MatrixXd dense(7, 7);
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j) dense(i, j) = (i + j) % 3 == 0 ? 0.0 : 1.0 + i + 10 * j;
  for (int i = 0; i < 7; ++i) dense(i, i) = 100.0 + i;
  return dense.sparseView();
}

Eigen::MatrixXd padded_dense(const PaddedCsr& csr, const std::vector<double>& values) {
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(csr.rows, csr.rows);
  for (int r = 0; r < csr.rows; ++r)
    for (int k = csr.row_start[r]; k < csr.row_start[r + 1]; ++k) {
      if (k > csr.row_start[r]) {
        EXPECT_LT(csr.column[k - 1], csr.column[k]);  // ascending
      }
      dense(r, csr.column[k]) = values[k];
    }
  return dense;
}

TEST(PaddedCsr, PadsConstrainedComponentsWithIdentityRowsOfTheDiagonalsSize) {
  const SparseMatrix a = matrix();
  const PaddedCsr csr = PaddedCsr::build(a, hints());
  EXPECT_EQ(csr.rows, 8);
  EXPECT_EQ(csr.displacement_rows, 6);
  EXPECT_EQ(csr.padded_row, (std::vector<int>{0, 1, 3, 4, 5, 6, 7}));
  std::vector<double> values(csr.column.size());
  csr.fill(a, values.data());
  const Eigen::MatrixXd padded = padded_dense(csr, values);
  const Eigen::MatrixXd dense(a);
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j)
      EXPECT_EQ(padded(csr.padded_row[i], csr.padded_row[j]), dense(i, j)) << i << "," << j;
  // Row 2, node 1's x: decoupled, with the mean of |diagonal|.
  EXPECT_DOUBLE_EQ(padded(2, 2), dense.diagonal().cwiseAbs().mean());
  EXPECT_EQ(padded.row(2).cwiseAbs().sum(), padded(2, 2));
  EXPECT_EQ(padded.col(2).cwiseAbs().sum(), padded(2, 2));
  // Vectors go there and back; the padding row holds 0.
  const Vector b = Vector::LinSpaced(7, 1.0, 7.0);
  std::vector<double> to(csr.rows, -1.0);
  csr.scatter(b, to.data());
  EXPECT_EQ(to[2], 0.0);
  Vector back;
  csr.gather(to.data(), back);
  EXPECT_EQ(back, b);
  EXPECT_EQ(csr.rows_of({5, 6}), (std::vector<int>{6, 7}));
}

TEST(PaddedCsr, RefillTakesTheNewValuesOfTheSamePattern) {
  SparseMatrix a = matrix();
  const PaddedCsr csr = PaddedCsr::build(a, hints());
  a.coeffs() *= -3.0;
  std::vector<double> values(csr.column.size());
  csr.fill(a, values.data());
  const Eigen::MatrixXd padded = padded_dense(csr, values);
  EXPECT_EQ(padded(csr.padded_row[4], csr.padded_row[1]), Eigen::MatrixXd(a)(4, 1));
}

TEST(PaddedCsr, TellsSymmetricFromUnsymmetricValues) {
  Eigen::MatrixXd dense(3, 3);
  dense << 4, 1, 0, 1, 4, 2, 0, 2, 4;
  SparseMatrix a = dense.sparseView();
  const std::vector<int> transpose = transpose_entries(a);
  EXPECT_TRUE(is_symmetric(a, transpose));
  a.coeffRef(1, 2) += 1e-6;
  EXPECT_FALSE(is_symmetric(a, transpose));
}

}  // namespace
}  // namespace geompm

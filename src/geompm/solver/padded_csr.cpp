#include "geompm/solver/padded_csr.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace geompm {

namespace {

// Row of each of geompm's rows in the padded matrix: displacement unknowns at node-major block
// positions, the others after all nodes' blocks, in their order.
std::vector<int> padded_rows(const LinearSolverHints& hints, Index n, int& displacement_rows) {
  const int bs = std::max(1, hints.block_size);
  displacement_rows = static_cast<int>(hints.node_coordinates.size()) * bs;
  std::vector<int> row(n);
  int next = displacement_rows;
  for (Index r = 0; r < n; ++r) {
    const bool displacement = r < Index(hints.unknown_node.size()) && hints.unknown_node[r] >= 0;
    row[r] = displacement ? int(hints.unknown_node[r]) * bs + hints.unknown_component[r] : next++;
  }
  return row;
}

}  // namespace

PaddedCsr PaddedCsr::build(const SparseMatrix& pattern, const LinearSolverHints& hints) {
  if (!pattern.isCompressed() || pattern.rows() != pattern.cols())
    throw std::invalid_argument("PaddedCsr: expected a square, compressed matrix");
  PaddedCsr csr;
  const Index n = pattern.rows();
  csr.padded_row = padded_rows(hints, n, csr.displacement_rows);
  csr.rows =
      csr.displacement_rows + int(std::count_if(csr.padded_row.begin(), csr.padded_row.end(),
                                                [&](int r) { return r >= csr.displacement_rows; }));
  // A padded row no unknown maps to is a constrained component: an identity row.
  std::vector<char> used(csr.rows, 0);
  for (const int r : csr.padded_row) used[r] = 1;
  std::vector<int> count(csr.rows + 1, 0);
  const int* outer = pattern.outerIndexPtr();
  const int* inner = pattern.innerIndexPtr();
  for (Index k = 0; k < pattern.nonZeros(); ++k) ++count[csr.padded_row[inner[k]] + 1];
  for (int r = 0; r < csr.rows; ++r)
    if (!used[r]) ++count[r + 1];
  std::partial_sum(count.begin(), count.end(), count.begin());
  csr.row_start = count;
  csr.column.resize(count.back());
  csr.source.resize(count.back());
  std::vector<int> next(count.begin(), count.end() - 1);
  for (Index j = 0; j < n; ++j)
    for (int k = outer[j]; k < outer[j + 1]; ++k) {
      const int at = next[csr.padded_row[inner[k]]]++;
      csr.column[at] = csr.padded_row[j];
      csr.source[at] = k;
      if (inner[k] == j) csr.diagonal.push_back(k);
    }
  for (int r = 0; r < csr.rows; ++r)
    if (!used[r]) {
      const int at = next[r]++;
      csr.column[at] = r;
      csr.source[at] = -1;
    }
  // AIJ wants each row's columns ascending; the padding keeps displacement columns in order but
  // not the other fields' relative to them.
  std::vector<std::pair<int, int>> row;
  for (int r = 0; r < csr.rows; ++r) {
    row.clear();
    for (int k = csr.row_start[r]; k < csr.row_start[r + 1]; ++k)
      row.emplace_back(csr.column[k], csr.source[k]);
    std::sort(row.begin(), row.end());
    for (int k = csr.row_start[r], i = 0; k < csr.row_start[r + 1]; ++k, ++i)
      std::tie(csr.column[k], csr.source[k]) = row[i];
  }
  return csr;
}

void PaddedCsr::fill(const SparseMatrix& matrix, double* to) const {
  const double* from = matrix.valuePtr();
  double mean = 0.0;
  for (const int k : diagonal) mean += std::abs(from[k]);
  mean = diagonal.empty() || mean == 0.0 ? 1.0 : mean / double(diagonal.size());
  for (std::size_t k = 0; k < source.size(); ++k) to[k] = source[k] >= 0 ? from[source[k]] : mean;
}

void PaddedCsr::scatter(const Vector& from, double* to) const {
  std::fill(to, to + rows, 0.0);
  for (std::size_t r = 0; r < padded_row.size(); ++r) to[padded_row[r]] = from[Index(r)];
}

void PaddedCsr::gather(const double* from, Vector& to) const {
  to.resize(Index(padded_row.size()));
  for (std::size_t r = 0; r < padded_row.size(); ++r) to[Index(r)] = from[padded_row[r]];
}

std::vector<int> PaddedCsr::rows_of(const std::vector<Index>& unknowns) const {
  std::vector<int> rows;
  rows.reserve(unknowns.size());
  for (const Index u : unknowns) rows.push_back(padded_row[u]);
  std::sort(rows.begin(), rows.end());
  return rows;
}

std::vector<int> transpose_entries(const SparseMatrix& pattern) {
  const int* outer = pattern.outerIndexPtr();
  const int* inner = pattern.innerIndexPtr();
  std::vector<int> transpose(pattern.nonZeros(), -1);
  for (Index j = 0; j < pattern.outerSize(); ++j)
    for (int k = outer[j]; k < outer[j + 1]; ++k) {
      // Entry (i, j); its transpose (j, i) is row j of column i (rows ascending in a column).
      const int i = inner[k];
      const int* at = std::lower_bound(inner + outer[i], inner + outer[i + 1], int(j));
      if (at != inner + outer[i + 1] && *at == j) transpose[k] = int(at - inner);
    }
  return transpose;
}

bool is_symmetric(const SparseMatrix& matrix, const std::vector<int>& transpose) {
  const double* v = matrix.valuePtr();
  const Index n = matrix.nonZeros();
  double largest = 0.0;
  for (Index k = 0; k < n; ++k) largest = std::max(largest, std::abs(v[k]));
  const double tolerance = 1e-12 * largest;
  for (Index k = 0; k < n; ++k)
    if (std::abs(v[k] - (transpose[k] >= 0 ? v[transpose[k]] : 0.0)) > tolerance) return false;
  return true;
}

}  // namespace geompm

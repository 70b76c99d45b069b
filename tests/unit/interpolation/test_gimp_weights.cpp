// GIMP weights on graded grids (docs/theory.md §9): partition of unity and exact reproduction of
// linear fields (eqs. 9.6), gradients against finite differences of the weights, the closed form
// of Bardenhagen & Kober (2004) on a uniform grid, clipping at the mesh boundary and at the axis,
// and the tensor-product stencils in 2D and 3D.
#include "geompm/interpolation/gimp_weights.hpp"

#include <gtest/gtest.h>

#include <random>

#include "geompm/mesh/structured_mesh.hpp"

namespace geompm {
namespace {

const std::vector<double> kLines = {0.0, 0.5, 1.2, 2.0, 3.1, 4.0, 4.3, 5.0};  // graded

int cell_of(const std::vector<double>& lines, double x) {
  int k = 0;
  while (k + 2 < static_cast<int>(lines.size()) && x >= lines[k + 1]) ++k;
  return k;
}

// Weight of node i (0 if it has none) for the domain centre +- half.
double weight(const std::vector<double>& lines, double centre, double half, int i) {
  AxisWeights w;
  gimp_axis_weights(lines, centre, half, cell_of(lines, centre), w);
  const int at = i - w.first;
  return at >= 0 && at < static_cast<int>(w.S.size()) ? w.S[at] : 0.0;
}

TEST(GimpWeights, PartitionOfUnityAndLinearFieldsOnAGradedGrid) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const double x = kLines.front() + u(rng) * (kLines.back() - kLines.front());
    // Up to 1.5 times the largest cell: the domain may span several cells (and gets clipped).
    const double half = clip_half_length(x, 1.6 * u(rng), kLines.front(), kLines.back());
    AxisWeights w;
    gimp_axis_weights(kLines, x, half, cell_of(kLines, x), w);
    double sum = 0, first = 0, g_sum = 0, g_first = 0;
    for (std::size_t a = 0; a < w.S.size(); ++a) {
      const double X = kLines[w.first + a];
      EXPECT_GE(w.S[a], 0.0);
      sum += w.S[a];
      first += w.S[a] * X;
      g_sum += w.G[a];
      g_first += w.G[a] * X;
    }
    EXPECT_NEAR(sum, 1.0, 1e-13) << "x = " << x << ", l = " << half;
    EXPECT_NEAR(first, x, 1e-13) << "x = " << x << ", l = " << half;  // clipped symmetrically
    EXPECT_NEAR(g_sum, 0.0, 1e-12);
    EXPECT_NEAR(g_first, 1.0, 1e-12);
    // The stencil holds exactly the nodes whose hat function overlaps the domain.
    EXPECT_LE(kLines[w.first], x - half + 1e-12);
    EXPECT_GE(kLines[w.first + w.S.size() - 1], x + half - 1e-12);
  }
}

TEST(GimpWeights, GradientIsTheDerivativeOfTheWeight) {
  // Eq. 9.3: for a domain that is not clipped, G_i = dS_i / dx_p.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double eps = 1e-6;
  int checked = 0;
  for (int trial = 0; trial < 500; ++trial) {
    const double x = 0.3 + u(rng) * 4.4;
    const double half = 0.05 + 0.5 * u(rng);
    if (x - half < kLines.front() + 2 * eps || x + half > kLines.back() - 2 * eps) continue;
    AxisWeights w;
    gimp_axis_weights(kLines, x, half, cell_of(kLines, x), w);
    for (std::size_t a = 0; a < w.S.size(); ++a) {
      const int i = w.first + static_cast<int>(a);
      const double fd =
          (weight(kLines, x + eps, half, i) - weight(kLines, x - eps, half, i)) / (2 * eps);
      EXPECT_NEAR(w.G[a], fd, 1e-6) << "x = " << x << ", l = " << half << ", node " << i;
    }
    ++checked;
  }
  EXPECT_GT(checked, 300);
}

TEST(GimpWeights, MatchTheUniformGridClosedForm) {
  // Bardenhagen & Kober (2004), uGIMP on a uniform grid of spacing h, domain half-length l < h/2,
  // r = |x_p - x_i|: S = 1 - (r^2 + l^2) / (2 h l) for r < l, 1 - r/h for l <= r < h - l,
  // (h + l - r)^2 / (4 h l) for h - l <= r < h + l, else 0.
  const double h = 0.5, l = 0.15;
  std::vector<double> lines;
  for (int i = 0; i <= 10; ++i) lines.push_back(i * h);
  auto closed_form = [&](double r) {
    r = std::abs(r);
    if (r < l) return 1.0 - (r * r + l * l) / (2 * h * l);
    if (r < h - l) return 1.0 - r / h;
    if (r < h + l) return (h + l - r) * (h + l - r) / (4 * h * l);
    return 0.0;
  };
  for (double x = 0.2; x < 4.8; x += 0.0137)
    for (int i = 0; i <= 10; ++i)
      EXPECT_NEAR(weight(lines, x, l, i), closed_form(x - lines[i]), 1e-13) << x << " " << i;
}

TEST(GimpWeights, ZeroLengthDomainGivesTheHatFunctions) {
  AxisWeights w;
  gimp_axis_weights(kLines, 1.5, 0.0, 2, w);  // cell [1.2, 2.0]
  ASSERT_EQ(w.first, 2);
  ASSERT_EQ(w.S.size(), 2u);
  EXPECT_NEAR(w.S[0], 0.5 / 0.8, 1e-15);
  EXPECT_NEAR(w.S[1], 0.3 / 0.8, 1e-15);
  EXPECT_NEAR(w.G[0], -1.0 / 0.8, 1e-15);
  EXPECT_NEAR(w.G[1], 1.0 / 0.8, 1e-15);
}

TEST(GimpWeights, DomainsAreClippedAtTheMeshAndTheAxis) {
  EXPECT_DOUBLE_EQ(clip_half_length(0.1, 0.4, 0.0, 5.0), 0.1);
  EXPECT_NEAR(clip_half_length(4.8, 0.4, 0.0, 5.0), 0.2, 1e-15);
  EXPECT_DOUBLE_EQ(clip_half_length(2.0, 0.4, 0.0, 5.0), 0.4);
  EXPECT_DOUBLE_EQ(clip_half_length(-1e-13, 0.4, 0.0, 5.0), 0.0);

  // Axisymmetry: a grid reaching r < 0 still never gives a domain across the axis.
  StructuredMeshSpec spec;
  spec.cell_type = CellType::Quad4;
  spec.origin = Vec3(-1.0, 0.0, 0.0);
  spec.axes[0] = {{3.0, 3, 1.0}};
  spec.axes[1] = {{2.0, 2, 1.0}};
  std::string why;
  const auto grid = find_rectilinear_grid(generate_structured_mesh(spec), why);
  ASSERT_TRUE(grid) << why;
  GimpStencil s;
  const Index cell = grid->cell(1, 0, 0);  // [0, 1] x [0, 1]
  gimp_stencil(*grid, Vec3(0.2, 0.5, 0), Vec3(0.5, 0.5, 0), cell, true, s);
  for (Index n : s.nodes) EXPECT_GE(grid->lines[0][n % 4], 0.0);  // 4 nodes a row: x >= 0 only
  EXPECT_EQ(s.first_cell[0], 1);
  gimp_stencil(*grid, Vec3(0.2, 0.5, 0), Vec3(0.5, 0.5, 0), cell, false, s);
  EXPECT_EQ(s.first_cell[0], 0);  // plane strain: the domain reaches into x < 0
}

TEST(GimpWeights, HalfLengthsFollowTheDiagonalOfF) {
  Mat3 F = Mat3::Identity();
  F(0, 0) = 1.2;
  F(1, 1) = 0.5;
  F(0, 1) = 0.7;  // shear leaves the half-lengths alone
  const Vec3 l = particle_half_lengths(Vec3(0.25, 0.5, 0.125), F, 2);
  EXPECT_DOUBLE_EQ(l(0), 0.3);
  EXPECT_DOUBLE_EQ(l(1), 0.25);
  EXPECT_DOUBLE_EQ(l(2), 0.0);
  F(1, 1) = -0.1;
  EXPECT_DOUBLE_EQ(particle_half_lengths(Vec3(0.25, 0.5, 0.125), F, 2)(1), 0.0);
}

// The tensor-product stencil: unity, linear fields and their gradients, in 2D and 3D.
void check_stencils(CellType type) {
  StructuredMeshSpec spec;
  spec.cell_type = type;
  spec.origin = Vec3(0.0, -1.0, 2.0);
  spec.axes[0] = {{2.0, 4, 3.0}};
  spec.axes[1] = {{1.0, 2, 1.0}, {2.0, 3, 0.5}};
  spec.axes[2] = {{1.0, 3, 2.0}};
  const Mesh mesh = generate_structured_mesh(spec);
  std::string why;
  const auto grid = find_rectilinear_grid(mesh, why);
  ASSERT_TRUE(grid) << why;
  const int dim = mesh.dim();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  GimpStencil s;
  std::size_t widest = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Index c = static_cast<Index>(u(rng) * mesh.num_cells()) % mesh.num_cells();
    Vec3 x = Vec3::Zero(), half = Vec3::Zero();
    for (int d = 0; d < dim; ++d) {
      const int k = grid->cell_index[c][d];
      const double lo = grid->lines[d][k], hi = grid->lines[d][k + 1];
      x(d) = lo + u(rng) * (hi - lo);
      half(d) = 0.5 * u(rng) * (hi - lo);  // at most half the point's cell
    }
    gimp_stencil(*grid, x, half, c, false, s);
    double sum = 0;
    Vec3 first = Vec3::Zero();
    Mat3 grad = Mat3::Zero();  // sum_a x_a (x) grad N_a
    for (std::size_t a = 0; a < s.nodes.size(); ++a) {
      if (a > 0) {
        EXPECT_LT(s.nodes[a - 1], s.nodes[a]);
      }
      sum += s.N[a];
      first += s.N[a] * mesh.nodes[s.nodes[a]];
      for (int i = 0; i < dim; ++i)
        for (int j = 0; j < dim; ++j)
          grad(i, j) += mesh.nodes[s.nodes[a]](i) * s.gradients[a * dim + j];
    }
    EXPECT_NEAR(sum, 1.0, 1e-13);
    EXPECT_LT(head_norm(first - x, dim), 1e-12);
    EXPECT_LT((grad.topLeftCorner(dim, dim) - Mat3::Identity().topLeftCorner(dim, dim)).norm(),
              1e-11);
    widest = std::max(widest, s.nodes.size());
  }
  // Some domains cross a grid line along every axis: 3 nodes per axis.
  EXPECT_GE(widest, std::size_t(dim == 2 ? 9 : 27));
}

TEST(GimpWeights, StencilsReproduceLinearFieldsIn2D) { check_stencils(CellType::Quad4); }
TEST(GimpWeights, StencilsReproduceLinearFieldsIn3D) { check_stencils(CellType::Hex8); }

}  // namespace
}  // namespace geompm

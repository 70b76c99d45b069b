// The reference elements: shape functions, gradients and quadrature rules.
#include "geompm/mesh/element.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "geompm/mesh/cell_geometry.hpp"
#include "mesh_test_support.hpp"

namespace geompm {
namespace {

template <class E>
class ElementTest : public ::testing::Test {
 protected:
  static constexpr CellType type = cell_type_of<E>;
  using Local = typename E::Local;

  /// Random points of a box around the reference cell: the identities below hold everywhere
  /// (for the pyramid below zeta = 0.8, away from the plane zeta = 1 where its rational term has
  /// its pole and central differences lose their accuracy).
  Local random_point() {
    std::uniform_real_distribution<double> unit(-1.5, 1.5);
    Local xi;
    for (int i = 0; i < E::dim; ++i) xi[i] = unit(rng_);
    if constexpr (type == CellType::Pyramid5) xi[2] = std::min(xi[2], 0.8);
    return xi;
  }
  std::mt19937 rng_{2024};
};

using AllElements =
    ::testing::Types<Element<CellType::Tri3>, Element<CellType::Tri6>, Element<CellType::Quad4>,
                     Element<CellType::Tet4>, Element<CellType::Hex8>, Element<CellType::Pyramid5>>;

class ElementName {
 public:
  template <class E>
  static std::string GetName(int) {
    return to_string(cell_type_of<E>);
  }
};
TYPED_TEST_SUITE(ElementTest, AllElements, ElementName);

TYPED_TEST(ElementTest, ShapeFunctionsArePartitionOfUnityWithZeroSumGradients) {
  using E = TypeParam;
  for (int k = 0; k < 200; ++k) {
    const auto xi = this->random_point();
    EXPECT_NEAR(E::shape(xi).sum(), 1.0, 1e-14);
    EXPECT_LT(E::shape_gradients(xi).colwise().sum().norm(), 1e-13);
  }
}

TYPED_TEST(ElementTest, GradientsMatchCentralDifferences) {
  using E = TypeParam;
  const double step = 1e-6;
  for (int k = 0; k < 50; ++k) {
    const auto xi = this->random_point();
    const typename E::Gradients exact = E::shape_gradients(xi);
    for (int i = 0; i < E::dim; ++i) {
      typename E::Local plus = xi, minus = xi;
      plus[i] += step;
      minus[i] -= step;
      const typename E::Values difference = (E::shape(plus) - E::shape(minus)) / (2.0 * step);
      EXPECT_LT((difference - exact.col(i)).norm(), 1e-8) << "direction " << i;
    }
  }
}

TYPED_TEST(ElementTest, ShapeFunctionsAreKroneckerAtNodes) {
  using E = TypeParam;
  for (int a = 0; a < E::nodes; ++a) {
    const typename E::Values n = E::shape(E::node(a));
    for (int b = 0; b < E::nodes; ++b) EXPECT_NEAR(n[b], a == b ? 1.0 : 0.0, 1e-15);
  }
}

TYPED_TEST(ElementTest, NodesAndCentroidAreInTheReferenceCell) {
  using E = TypeParam;
  EXPECT_TRUE(E::contains(E::centroid(), 0.0));
  for (int a = 0; a < E::nodes; ++a) EXPECT_TRUE(E::contains(E::node(a), 1e-14)) << a;
  // Just outside each node (away from the centroid) only a tolerance lets it in.
  for (int a = 0; a < E::nodes; ++a) {
    const typename E::Local outside = E::node(a) + 1e-6 * (E::node(a) - E::centroid());
    EXPECT_FALSE(E::contains(outside, 1e-9)) << a;
    EXPECT_TRUE(E::contains(outside, 1e-5)) << a;
  }
}

TYPED_TEST(ElementTest, QuadratureWeightsArePositiveAndSumToTheReferenceMeasure) {
  using E = TypeParam;
  double sum = 0.0;
  for (int q = 0; q < E::quadrature_size(); ++q) {
    EXPECT_GT(E::quadrature_weight(q), 0.0);
    EXPECT_TRUE(E::contains(E::quadrature_point(q), 0.0));
    sum += E::quadrature_weight(q);
  }
  EXPECT_NEAR(sum, testing::reference_measure(this->type), 1e-14);
}

double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }

/// Exact integral of xi^p eta^q zeta^r over the reference cell.
double exact_monomial_integral(CellType type, int p, int q, int r) {
  switch (type) {
    case CellType::Tri3:
    case CellType::Tri6:
      return factorial(p) * factorial(q) / factorial(p + q + 2);
    case CellType::Tet4:
      return factorial(p) * factorial(q) * factorial(r) / factorial(p + q + r + 3);
    case CellType::Pyramid5: {
      // The square |xi|, |eta| <= 1 - zeta at each height: int zeta^r (1 - zeta)^(p+q+2).
      const auto line = [](int k) { return k % 2 == 0 ? 2.0 / (k + 1) : 0.0; };
      return line(p) * line(q) * factorial(r) * factorial(p + q + 2) / factorial(p + q + r + 3);
    }
    default: {
      const auto line = [](int k) { return k % 2 == 0 ? 2.0 / (k + 1) : 0.0; };
      return line(p) * line(q) * (type == CellType::Hex8 ? line(r) : 1.0);
    }
  }
}

TYPED_TEST(ElementTest, QuadratureIsExactForTheMassMatrixDegree) {
  using E = TypeParam;
  const CellType type = this->type;
  // Mass matrix N_a N_b: total degree 2 (Tri3, Tet4), 4 (Tri6); degree 2 in each
  // direction for Quad4/Hex8, whose Gauss rule is exact to 3 in each direction. The pyramid's
  // rule is exact for polynomials of total degree 3 (its rational mass matrix: pyramid_test).
  const bool tensor = type == CellType::Quad4 || type == CellType::Hex8;
  const int degree = type == CellType::Tri6 ? 4 : (tensor || type == CellType::Pyramid5) ? 3 : 2;
  const int max_r = E::dim == 3 ? degree : 0;
  for (int p = 0; p <= degree; ++p)
    for (int q = 0; q <= degree; ++q)
      for (int r = 0; r <= max_r; ++r) {
        if (!tensor && p + q + r > degree) continue;
        double sum = 0.0;
        for (int k = 0; k < E::quadrature_size(); ++k) {
          const auto xi = E::quadrature_point(k);
          sum += E::quadrature_weight(k) * std::pow(xi[0], p) * std::pow(xi[1], q) *
                 (E::dim == 3 ? std::pow(xi[E::dim - 1], r) : 1.0);
        }
        EXPECT_NEAR(sum, exact_monomial_integral(type, p, q, r), 1e-14)
            << "monomial " << p << " " << q << " " << r;
      }
}

TYPED_TEST(ElementTest, MassMatrixSumsToTheReferenceMeasure) {
  using E = TypeParam;
  double sum = 0.0;  // sum_ab int N_a N_b = int (sum_a N_a)^2 = measure
  for (int q = 0; q < E::quadrature_size(); ++q) {
    const typename E::Values n = E::shape(E::quadrature_point(q));
    sum += E::quadrature_weight(q) * (n * n.transpose()).sum();
  }
  EXPECT_NEAR(sum, testing::reference_measure(this->type), 1e-14);
}

TEST(ElementTest, TrianglesAcceptExactlyTheReferenceTriangle) {
  using E = Element<CellType::Tri3>;
  EXPECT_TRUE(E::contains({0.5, 0.5}, 0.0));
  EXPECT_FALSE(E::contains({0.5, 0.5 + 1e-9}, 1e-10));
  EXPECT_TRUE(E::contains({0.5, 0.5 + 1e-11}, 1e-10));
  EXPECT_FALSE(E::contains({-1e-9, 0.3}, 1e-10));
  EXPECT_FALSE(E::contains({0.3, -1e-9}, 1e-10));
  EXPECT_TRUE(E::contains({-1e-11, 0.3}, 1e-10));
}

TEST(ElementTest, Tri6MidSideNodesFollowGmshOrder) {
  using E = Element<CellType::Tri6>;
  EXPECT_TRUE(E::node(3).isApprox(Eigen::Vector2d(0.5, 0.0)));  // edge 0-1
  EXPECT_TRUE(E::node(4).isApprox(Eigen::Vector2d(0.5, 0.5)));  // edge 1-2
  EXPECT_TRUE(E::node(5).isApprox(Eigen::Vector2d(0.0, 0.5)));  // edge 2-0
}

TEST(ElementTest, HexNodesFollowGmshOrder) {
  using E = Element<CellType::Hex8>;
  EXPECT_EQ(E::node(0), Eigen::Vector3d(-1, -1, -1));
  EXPECT_EQ(E::node(2), Eigen::Vector3d(1, 1, -1));
  EXPECT_EQ(E::node(4), Eigen::Vector3d(-1, -1, 1));
  EXPECT_EQ(E::node(6), Eigen::Vector3d(1, 1, 1));
}

}  // namespace
}  // namespace geompm

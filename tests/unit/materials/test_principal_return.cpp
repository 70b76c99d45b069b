// The shared machinery of the principal-stress return: the tangent of a function given by its
// principal values (eq. M.7), also at repeated principal values, and the list of faces.
#include <gtest/gtest.h>

#include <bit>

#include "geompm/core/tensor.hpp"
#include "geompm/materials/principal_return.hpp"
#include "material_test_support.hpp"

namespace geompm {
namespace {

using test_support::random_rotation;
using test_support::with_axes;

// An isotropic function whose principal values depend on all three principal arguments:
// tau_a = alpha (sum_b x_b)^2 + beta x_a + gamma x_a^3.
constexpr double alpha = 3.0, beta = 2.0, gamma = 5.0;

Vec3 principal_tau(const Vec3& x) {
  const double s = x.sum();
  return (alpha * s * s + beta * x.array() + gamma * x.array().cube()).matrix();
}
Mat3 principal_dtau(const Vec3& x) {
  Mat3 c = Mat3::Constant(2 * alpha * x.sum());
  for (int a = 0; a < 3; ++a) c(a, a) += beta + 3 * gamma * x(a) * x(a);
  return c;
}
Mat3 tau_of(const Mat3& eps) {
  const SymmetricEigen e = symmetric_eigen(eps);
  return e.vectors * principal_tau(e.values).asDiagonal() * e.vectors.transpose();
}

TEST(PrincipalFunctionDerivative, MatchesFiniteDifferencesWithDistinctAndRepeatedValues) {
  std::mt19937 rng(7);
  const std::vector<Vec3> principal = {
      {0.3, -0.1, 0.05}, {0.2, 0.2, -0.1}, {-0.1, 0.2, -0.1}, {0.1, 0.1, 0.1}};
  for (const Vec3& x : principal) {
    const Mat3 eps = with_axes(x, random_rotation(rng));
    const SymmetricEigen e = symmetric_eigen(eps);
    const Tensor4 d =
        principal_function_derivative4(e, principal_tau(e.values), principal_dtau(e.values));
    const double h = 1e-6;
    Tensor4 fd;
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l) {
        Mat3 de = Mat3::Zero();
        de(k, l) += 0.5 * h;
        de(l, k) += 0.5 * h;
        fd.col(pair_index(k, l)) = flatten(tau_of(eps + de) - tau_of(eps - de)) / (2 * h);
      }
    EXPECT_LT((fd - d).norm() / d.norm(), 1e-7) << "principal values " << x.transpose();
  }
}

TEST(PrincipalFunctionDerivative, ReducesToTheIsotropicFunctionDerivative) {
  std::mt19937 rng(3);
  const Mat3 eps = with_axes(Vec3(0.2, -0.05, 0.11), random_rotation(rng));
  const SymmetricEigen e = symmetric_eigen(eps);
  const auto f = [](double x) { return std::exp(2 * x); };
  const auto df = [](double x) { return 2 * std::exp(2 * x); };
  const Vec3 tau(f(e.values(0)), f(e.values(1)), f(e.values(2)));
  const Mat3 c = Vec3(df(e.values(0)), df(e.values(1)), df(e.values(2))).asDiagonal();
  EXPECT_LT(
      (principal_function_derivative4(e, tau, c) - isotropic_function_derivative(e, f, df)).norm(),
      1e-12);
}

TEST(PrincipalReturn, FacesAreListedPlanesFirst) {
  const auto sets = active_sets_up_to_three(6);
  EXPECT_EQ(sets.size(), 6u + 15u + 20u);
  EXPECT_EQ(sets.front(), 0b1u);
  for (std::size_t k = 1; k < sets.size(); ++k)
    EXPECT_LE(std::popcount(sets[k - 1]), std::popcount(sets[k]));
}

TEST(PrincipalReturn, DescendingOrder) {
  std::mt19937 rng(5);
  const Mat3 q = random_rotation(rng);
  const SymmetricEigen e = principal_descending(with_axes(Vec3(-1, 3, 2), q));
  EXPECT_NEAR(e.values(0), 3, 1e-12);
  EXPECT_NEAR(e.values(1), 2, 1e-12);
  EXPECT_NEAR(e.values(2), -1, 1e-12);
  EXPECT_LT(
      (e.vectors * e.values.asDiagonal() * e.vectors.transpose() - with_axes(Vec3(-1, 3, 2), q))
          .norm(),
      1e-12);
}

}  // namespace
}  // namespace geompm

// Newton's backtracking (docs/theory.md §4.4) on R(x) = -atan(x), the classic case where plain
// Newton from |x0| > 1.39 overshoots further each iteration and diverges, while halving an
// overshooting correction brings it into the quadratic basin around the root x = 0.
#include <gtest/gtest.h>

#include <cmath>

#include "geompm/solver/newton.hpp"

namespace geompm {
namespace {

class Arctangent final : public NonlinearProblem {
 public:
  bool evaluate(const Vector& x, Vector& residual, double& force_scale,
                SparseMatrix* tangent) override {
    residual = Vector::Constant(1, -std::atan(x(0)));
    force_scale = 1.0;
    if (tangent) {
      *tangent = SparseMatrix(1, 1);
      tangent->insert(0, 0) = 1.0 / (1.0 + x(0) * x(0));  // K = -dR/dx
    }
    return true;
  }
  double increment_norm(const Vector& x) const override { return std::max(std::abs(x(0)), 1.0); }
};

NewtonResult solve_from(double x0, int halvings, Vector& x) {
  Arctangent problem;
  auto solver = create_linear_solver("sparse_lu");
  NewtonSettings settings;
  settings.max_iterations = 30;
  settings.residual_tolerance = 1e-12;
  settings.displacement_tolerance = 1e-12;
  settings.max_halvings = halvings;
  x = Vector::Constant(1, x0);
  SparseMatrix tangent;
  return solve_newton(problem, *solver, settings, x, tangent);
}

TEST(NewtonBacktracking, PlainNewtonDivergesOnTheArctangent) {
  Vector x;
  EXPECT_FALSE(solve_from(2.0, 0, x).converged);
}

TEST(NewtonBacktracking, HalvingTheOvershootFindsTheRoot) {
  Vector x;
  const NewtonResult result = solve_from(2.0, 4, x);
  ASSERT_TRUE(result.converged) << result.failure;
  EXPECT_NEAR(x(0), 0.0, 1e-12);
  EXPECT_GT(result.halvings, 0);
  EXPECT_LT(result.iterations, 15);
}

}  // namespace
}  // namespace geompm

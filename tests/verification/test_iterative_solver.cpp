// Inexact Newton with an AMG-preconditioned Krylov solver (numerics.linear_solver: petsc_gamg,
// docs/theory.md §4.8) converges to the direct solver's results: the first quarter of the
// Mohr-Coulomb strip footing example (plastic from its first steps, a footing of stiff
// prescribed-motion springs beside soft empty cells), run with UMFPACK and with GAMG, takes the
// same steps and its histories agree within 1e-6 of each column's largest value, the Newton
// tolerance being 1e-8. The iteration counts may differ (a loose linear solve may cost a Newton
// iteration) and are not compared.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "run_model.hpp"

namespace geompm {
namespace {

testing::ModelRun footing_with(const std::string& solver) {
  auto spec = testing::read_example("mohr_coulomb_footing/mohr_coulomb_footing.yaml");
  spec.phases.front().duration = 0.25;  // 10 steps of 0.025
  spec.numerics.linear_solver = solver;
  return testing::run_spec(spec, "iterative_footing_" + solver);
}

TEST(IterativeSolver, GamgNewtonHistoriesMatchUmfpacks) {
  const auto direct = footing_with("umfpack");
  const auto iterative = footing_with("petsc_gamg");
  EXPECT_EQ(iterative.summary.steps, direct.summary.steps);
  EXPECT_EQ(iterative.summary.cutbacks, direct.summary.cutbacks);
  EXPECT_EQ(iterative.summary.linear_solver, "petsc_gamg");
  // Krylov iterations: more than one a Newton solve (it is not the direct solver).
  EXPECT_GT(iterative.summary.linear_iterations, 3 * iterative.summary.iterations);
  for (const std::string column : {"time", "settlement", "force"}) {
    SCOPED_TRACE(column);
    const auto a = direct.column(column), b = iterative.column(column);
    ASSERT_EQ(a.size(), b.size());
    double largest = 0.0, difference = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k) {
      largest = std::max(largest, std::abs(a[k]));
      difference = std::max(difference, std::abs(a[k] - b[k]));
    }
    EXPECT_LE(difference, 1e-6 * largest);
  }
  // The force has reached the plastic range (q/c = 2F/(B c) above 6; N_c = 14.83).
  EXPECT_GT(-2.0 * direct.column("force").back(), 6.0);
}

}  // namespace
}  // namespace geompm

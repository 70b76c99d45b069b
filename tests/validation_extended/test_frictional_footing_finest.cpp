// The extended validation tier (ctest label validation_extended; not in CI, whose 2 cores would
// spend half of the suite's time limit on these two alone; docs/validation.md says how to run it).
// - N_q on the finest strip mesh of docs/validation.md §9 (h = B/80): within +5 % of
//   Prandtl-Reissner's 18.40 at a settlement of 0.01 B, with at most 10 Newton iterations a step
//   (about 17 minutes on one core beside another test).
// - N_gamma at phi = 20 deg on h = B/10, B/20, B/40 (docs/validation.md §9): above Martin's value,
//   falling and flattening with the mesh (about 9 minutes on one core, most of it on B/40).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "example_text.hpp"
#include "frictional_footing.hpp"
#include "strip_mesh.hpp"

namespace geompm {
namespace {

using namespace testing::frictional_footing;

TEST(FrictionalFootingValidation, SurchargeNqWithinFivePercentOfPrandtlReissnerAtBOver80) {
  // The finest mesh of docs/validation.md §9 (h = B/80, 40 cells under the half-width): 4.1 %
  // above N_q = 18.40 at 0.01 B. The target, as for the Tresca strip: within +5 %. Pushed only to
  // 0.0105 B (the report's run goes on to where Newton fails at the smallest step, about 0.011 B),
  // so the Newton count below is of the steps up to there.
  const NqReading finest = nq_at_one_percent(40, "nq_b80");
  EXPECT_GT(finest.nq, kNq);  // above N_q, as measured (no bound theorem with moving points)
  EXPECT_LT(finest.nq, 1.05 * kNq);
  EXPECT_LE(finest.most_newton_iterations, 10);
}

TEST(FrictionalFootingValidation, SelfWeightNgammaAtPhi20FallsAndFlattensWithTheMesh) {
  // The rough N_gamma footing with phi = psi = 20 deg (docs/validation.md §9, N_gamma at phi = 20),
  // where associated flow dilates at sin 20 = 0.34 of the shear rate instead of 0.5, with
  // backtracking (`line_search: 6`), each mesh pushed 0.006 B. Martin (2005), rough, phi = 20 deg:
  // N_gamma = 2.84 (as commonly quoted). Measured at 0.004 B: 6.77, 5.31, 4.30 on h = B/10, B/20,
  // B/40 (+139, +87, +51 %); from 0.004 to 0.006 B the load rises by 11.2, 6.5 and 1.8 % (this
  // test pushes every mesh 0.006 B; validation.md §9's runs, pushed further on the coarser
  // meshes, differ a little).
  constexpr double kNgammaRough20 = 2.84;
  const auto text = [](int n) {
    auto t = testing::replace_once(
        testing::example_text("frictional_footing/frictional_footing_ngamma.yaml"),
        "vtk: {every: 10}", "vtk: {every: 0}");
    t = testing::replace_once(t, "phi: 30, psi: 30,", "phi: 20, psi: 20,");
    t = testing::replace_once(t, "\"-0.007*t\"", "\"-0.006*t\"");
    t = testing::replace_once(
        t, "newton: {predictor: extrapolated, max_iterations: 20,",
        "newton: {predictor: extrapolated, max_iterations: 20, line_search: 6,");
    // As measured: 1e-6 of the steel block's E in the empty cells, 2e-4 of the sand's.
    t = testing::with_numerics(t, "empty_cell_stiffness", "2.0e-4");
    return testing::strip_mesh(t, n);
  };
  std::vector<double> q, rise;
  for (int n : {5, 10, 20}) {
    const auto push = run_push(text(n), "ngamma20_b" + std::to_string(2 * n), kGammaScale);
    ASSERT_FALSE(push.stopped) << "h = B/" << 2 * n;
    ASSERT_NEAR(push.s.back(), 0.006, 1e-6);
    q.push_back(push.at(0.004));
    rise.push_back(push.q.back() / q.back() - 1.0);
    std::printf(
        "[N_gamma, phi = 20, h = B/%d] %.2f at 0.004 B (%+.0f %% of %.2f), rising %+.1f %% "
        "to 0.006 B\n",
        2 * n, q.back(), (q.back() / kNgammaRough20 - 1) * 100, kNgammaRough20, rise.back() * 100);
    // Associated flow on low-order cells over-estimates the limit load.
    EXPECT_GT(q.back(), kNgammaRough20);
  }
  // Less on finer meshes ...
  EXPECT_LT(q[1], q[0]);
  EXPECT_LT(q[2], q[1]);
  // ... and the curves flatten: on h = B/40 nearly a limit load.
  EXPECT_LT(rise[1], rise[0]);
  EXPECT_LT(rise[2], rise[1]);
  EXPECT_LT(std::abs(rise[2]), 0.03);
}

}  // namespace
}  // namespace geompm

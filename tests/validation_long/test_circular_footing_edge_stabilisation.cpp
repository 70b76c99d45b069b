// Long validation cases (ctest label validation_long): the rigid circular footings on h = D/40,
// which stop before 0.1 D with the examples' 10 Newton iterations a step (smooth at 0.063 D, and
// at 0.069 D with 20: Newton's corrections move the node on the footing's edge that a single soil
// point at its support's far corner holds; rough at 0.042 D; docs/validation.md §7), carried to
// 0.1 D by the cures of docs/theory.md §6: springs at the nodes the points barely support
// (eq. 6.2; smooth, with up to 20 iterations, about 4 minutes on one core) or the ghost penalty on
// the body's edge cells (eq. 6.3; with the cap of 10 and the energy line search: smooth about 2.5
// minutes, rough about 3).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "example_text.hpp"
#include "run_model.hpp"
#include "strip_mesh.hpp"

namespace geompm {
namespace {

// Cox, Eason & Hopkins (1961), rigid circular punch on Tresca soil: N_c = 5.69 smooth, 6.05
// rough (tabulated by Houlsby & Wroth 1983). The target, as for the strip (docs/references.md §3):
// within +5 % at 0.1 D, here also the mean over 0.08-0.1 D (the curves oscillate as points cross
// cells).
constexpr double kSmoothCircle = 5.69;
constexpr double kRoughCircle = 6.05;

/// Runs the rigid circular footing of examples/circular_footing/`example` on h = D/40 with
/// `newton` in place of the example's Newton settings before its tolerances and `numerics` as its
/// numerics, and checks q/s_u against `n_c`.
void check_d40(const std::string& example, double n_c, const std::string& newton,
               const std::string& numerics, const std::string& name) {
  auto text = testing::strip_mesh(testing::example_text("circular_footing/" + example), 20);
  text = testing::replace_once(text, "vtk: {every: 10}", "vtk: {every: 0}");
  // The example's Newton settings up to its tolerances give way to `newton`.
  const std::size_t from = text.find("newton: {"), to = text.find("residual_tolerance", from);
  ASSERT_NE(to, std::string::npos) << "the example no longer has its Newton settings";
  text.replace(from, to - from, "newton: {" + newton + ", ");
  text += "numerics: {" + numerics + "}\n";
  const auto run = testing::run_spec(read_model_from_string(text, name + ".yaml"), name);
  const auto settlement = run.column("settlement"), force = run.column("force");
  std::vector<double> q_window;
  double q_end = 0.0;
  for (std::size_t k = 0; k < settlement.size(); ++k) {
    const double s = -settlement[k], q = -8.0 * force[k];  // D = 1 m: q / s_u = -8 force
    if (s >= 0.08 - 1e-6) q_window.push_back(q);
    q_end = q;
  }
  ASSERT_NEAR(-settlement.back(), 0.1, 1e-6) << "the run stopped before 0.1 D";
  double mean = 0.0;
  for (const double q : q_window) mean += q / q_window.size();
  double most_iterations = 0.0;
  for (const double n : run.column("newton_iterations"))
    most_iterations = std::max(most_iterations, n);
  std::printf(
      "[%s, D/40, %s, %s] q/s_u %.3f at 0.1 D, %.3f over 0.08-0.1 D, at most %d iterations a "
      "step\n",
      example.c_str(), newton.c_str(), numerics.c_str(), q_end, mean,
      static_cast<int>(most_iterations));
  for (const double q : {q_end, mean}) {
    EXPECT_GE(q, n_c);
    EXPECT_LE(q, 1.05 * n_c);
  }
}

TEST(CircularFootingValidation, SparseNodeSpringsCarryTheSmoothRigidFootingToCoxEasonHopkins) {
  // Measured 5.72 at 0.1 D and 5.83 over 0.08-0.1 D (at most 19 iterations a step), with 1e-6 of
  // E in the empty cells, as both smooth studies here were (with the default 1e-4 this run stops
  // at 0.09 D, a point turning inside out, and the ghost-penalty one ends at 6.07, +6.7 %).
  check_d40("circular_footing_smooth.yaml", kSmoothCircle, "line_search: 6, max_iterations: 20",
            "sparse_node_stiffness: 1.0e-2, empty_cell_stiffness: 1.0e-6",
            "circular_smooth_d40_sparse");
}

TEST(CircularFootingValidation, GhostPenaltyCarriesTheSmoothRigidFootingToCoxEasonHopkins) {
  // With the example's cap of 10 iterations a step (the issue's), `ghost_penalty: 1.0e-2` on every
  // edge cell (`ghost_penalty_fill: 1`) and the energy line search (docs/theory.md §4.4; without
  // it the run stops at 0.081 D). Measured 5.89 at 0.1 D (+3.5 %) and 5.72 over 0.08-0.1 D
  // (+0.5 %), 72 steps; the penalty stiffens the fan at the footing's edge a little (docs/theory.md
  // §6). With the default fill limit (only edge cells at most half filled) it also reaches 0.1 D,
  // at 5.60 (-1.7 %: below the band at that instant of the cell-crossing noise) and 5.72 over the
  // window (docs/validation.md §7, where both are tabulated).
  check_d40("circular_footing_smooth.yaml", kSmoothCircle,
            "line_search: 6, energy_line_search: 0.1, max_iterations: 10",
            "ghost_penalty: 1.0e-2, ghost_penalty_fill: 1, empty_cell_stiffness: 1.0e-6",
            "circular_smooth_d40_ghost");
}

TEST(CircularFootingValidation, GhostPenaltyCarriesTheRoughRigidFootingToCoxEasonHopkins) {
  // The same search and gamma on the rough rigid footing, which stops at 0.042 D under the cap of
  // 10 without them, with the default fill limit: only edge cells at most half filled carry the
  // penalty. Measured 6.18 at 0.1 D (+2.2 %) and 6.29 over 0.08-0.1 D (+3.9 %), 89 steps (on every
  // edge cell: 6.08 and 6.28, 61 steps; with the penalty alone, no search: 5.66, -6.4 %).
  check_d40("circular_footing_rigid_rough.yaml", kRoughCircle,
            "line_search: 6, energy_line_search: 0.1, max_iterations: 10", "ghost_penalty: 1.0e-2",
            "circular_rough_d40_ghost");
}

}  // namespace
}  // namespace geompm

// The coupled pile of examples/coupling/pile_coupled.yaml (docs/theory.md §19; issue 43): a
// deformable pile pushed into Tresca clay with MPM cells within 0.3 m of it and FEM cells beyond
// gives the head force of its all-MPM twin (pile_all_mpm.yaml) within 2 % at every step to
// 0.05 D (measured: at most 0.11 %), with Newton at or below 10 iterations a step, and the MPM
// cells keep their shape (smallest angle above 80 degrees; 84.5 measured at 0.05 D).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "footing_run.hpp"
#include "geompm/io/model_reader.hpp"

namespace geompm {
namespace {

// The head's settlement (as Footing::settlement) and force (as Footing::q), per step.
using PileCurve = testing::Footing;

PileCurve run_pile(const std::string& file, std::vector<double>* smallest_angle = nullptr) {
  const std::string text = testing::replace_once(testing::example_text("coupling/" + file),
                                                 "vtk: {every: 5}", "vtk: {every: 0}");
  const auto run = testing::run_spec(read_model_from_string(text, file), file);
  if (smallest_angle) *smallest_angle = run.column("mesh_smallest_angle");
  PileCurve curve;
  for (double u : run.column("head_uy")) curve.settlement.push_back(-u);
  for (double f : run.column("head_force")) curve.q.push_back(-f);
  curve.iterations = run.column("newton_iterations");
  return curve;
}

TEST(CoupledPile, FollowsTheAllMpmHeadForce) {
  std::vector<double> smallest_angle;
  const PileCurve coupled = run_pile("pile_coupled.yaml", &smallest_angle);
  const PileCurve mpm = run_pile("pile_all_mpm.yaml");
  const double D = 0.25;
  ASSERT_NEAR(coupled.settlement.back(), 0.05 * D, 1e-12);
  double worst = 0.0;
  for (std::size_t k = 1; k < coupled.settlement.size(); ++k) {
    const double reference = mpm.q_at(coupled.settlement[k]);
    EXPECT_NEAR(coupled.q[k], reference, 0.02 * reference)
        << "at s/D = " << coupled.settlement[k] / D;
    worst = std::max(worst, std::abs(coupled.q[k] / reference - 1.0));
  }
  std::printf("coupled pile: head force within %.3f %% of the all-MPM pile\n", 100.0 * worst);
  EXPECT_LE(coupled.max_iterations(), 10);
  const double angle = *std::min_element(smallest_angle.begin() + 1, smallest_angle.end());
  std::printf("coupled pile: smallest angle of the MPM cells %.2f degrees\n", angle);
  EXPECT_GT(angle, 80.0);
}

}  // namespace
}  // namespace geompm

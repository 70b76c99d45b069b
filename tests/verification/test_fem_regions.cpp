// FEM regions and MPM-FEM coupling (docs/theory.md §19, seed §3.4) on footings:
// - the coupled strip footing (examples/coupling/strip_footing_coupled.yaml: a rough steel block,
//   MPM near it, FEM beyond, the MPM mesh relaxed after each step) gives the same
//   load-settlement curve as its all-MPM twin (strip_footing_all_mpm.yaml) within 2 % at every
//   step to 0.05 B (measured: at most 1.96 %, at a step where points cross cells), and its MPM
//   cells keep their shape (smallest angle 85.7 degrees at 0.05 B, docs/validation.md §19);
// - an all-FEM smooth strip footing on stiff Tresca clay (E = 1e4 s_u, so that the mechanism forms
//   at a settlement of a few thousandths of B, where the geometry has not changed: a small-strain
//   answer), driven by its base nodes on h = B/40, gives Prandtl's 2 + pi within 3 %;
// - the coupled strip footing on quad4 MPM cells over tri3 FEM cells (strip_footing_coupled_mixed)
//   follows the all-MPM curve of its mesh within 2 % (measured 1.40 %).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "footing_run.hpp"

namespace geompm {
namespace {

using testing::Footing;

TEST(FemRegionFootings, CoupledStripFootingFollowsTheAllMpmCurve) {
  const Footing& coupled = testing::run_footing(
      testing::no_vtk(testing::example_text("coupling/strip_footing_coupled.yaml")),
      "strip_footing_coupled", -2.0);
  const Footing& mpm = testing::run_footing(
      testing::no_vtk(testing::example_text("coupling/strip_footing_all_mpm.yaml")),
      "strip_footing_all_mpm", -2.0);
  ASSERT_NEAR(coupled.settlement.back(), 0.05, 1e-9);
  for (std::size_t k = 1; k < coupled.settlement.size(); ++k) {
    const double s = coupled.settlement[k];
    const double reference = mpm.q_at(s);
    EXPECT_NEAR(coupled.q[k], reference, 0.02 * reference) << "at s/B = " << s;
  }
  EXPECT_LE(coupled.max_iterations(), 10);
}

// The coupled footing on a mesh of two cell types (strip_footing_coupled_mixed.yaml: quad4 MPM near
// the footing over tri3 FEM beyond, seed §3.4's pipeline model) against the all-MPM model on the
// same mesh (the file without its FEM region): 2 % at every step, as the quad4 pair above.
TEST(FemRegionFootings, MixedCellCoupledStripFootingFollowsTheAllMpmCurve) {
  const std::string text =
      testing::no_vtk(testing::example_text("coupling/strip_footing_coupled_mixed.yaml"));
  const std::string far_field =
      "  far_field:\n    kind: fem\n"
      "    region: {polygon: [[0, 0], [5, 0], [5, 5], [1.5, 5], [1.5, 3.5], [0, 3.5]]}\n";
  const Footing& coupled = testing::run_footing(text, "strip_footing_coupled_mixed", -2.0);
  const Footing& mpm = testing::run_footing(testing::replace_once(text, far_field, ""),
                                            "strip_footing_mixed_all_mpm", -2.0);
  // Against the quad4 all-MPM model, for the record (docs/validation.md §19): the tri3 far field
  // is stiffer at nu = 0.49 than the quad4 cells' f_bar.
  const Footing& quad4 = testing::run_footing(
      testing::no_vtk(testing::example_text("coupling/strip_footing_all_mpm.yaml")),
      "strip_footing_all_mpm", -2.0);
  ASSERT_NEAR(coupled.settlement.back(), 0.05, 1e-9);
  double worst = 0.0, worst_quad4 = 0.0;
  for (std::size_t k = 1; k < coupled.settlement.size(); ++k) {
    const double s = coupled.settlement[k];
    const double reference = mpm.q_at(s);
    worst = std::max(worst, std::abs(coupled.q[k] / reference - 1.0));
    worst_quad4 = std::max(worst_quad4, std::abs(coupled.q[k] / quad4.q_at(s) - 1.0));
    EXPECT_NEAR(coupled.q[k], reference, 0.02 * reference) << "at s/B = " << s;
  }
  std::printf(
      "mixed-cell coupled footing: q/s_u %.4f at 0.05 B; largest difference %.2f %% from "
      "the all-MPM model on its mesh, %.2f %% from the quad4 all-MPM model\n",
      coupled.q.back(), 100.0 * worst, 100.0 * worst_quad4);
  EXPECT_LE(coupled.max_iterations(), 10);
}

// Smooth: the base nodes (0 <= x <= B/2 at y = 5) are driven down, free horizontally.
const char* kAllFemFooting = R"m(
analysis: {kinematics: plane_strain}
mesh:
  generate:
    cell: quad4
    origin: [0, 0]
    x: [{length: 1.0, cells: 40}, {length: 4.0, cells: 16, ratio: 4}]
    y: [{length: 4.0, cells: 16, ratio: 0.25}, {length: 1.0, cells: 40}]
regions:
  soil: {kind: fem, region: all}
node_sets:
  base: {box: {min: [0, 5], max: [0.5, 5]}}
materials:
  clay: {model: tresca, su: 1, E: 10000, nu: 0.49, density: 0, formulation: f_bar}
bodies:
  soil: {material: clay, region: all}
phases:
  - name: push
    duration: 1.0
    time_step: {initial: 0.05, min: 0.0001, max: 0.05}
    newton: {max_iterations: 15, residual_tolerance: 1.0e-8, displacement_tolerance: 1.0e-8}
    grid_motion: [{boundary: base, displacement: [~, "-0.004*t"]}]
    fixities:
      - {boundary: left, fix: normal}
      - {boundary: right, fix: normal}
      - {boundary: bottom, fix: all}
output:
  history:
    - {quantity: displacement, boundary: base, component: y, name: settlement}
    - {quantity: reaction, boundary: base, component: y, name: force}
    - {quantity: newton_iterations}
)m";

TEST(FemRegionFootings, AllFemStripFootingGivesPrandtl) {
  const Footing& f = testing::run_footing(kAllFemFooting, "all_fem_footing", -2.0);
  const double prandtl = 2.0 + M_PI;
  const double q = f.q_at(0.003);
  std::printf("all-FEM footing: q/s_u = %.4f at 0.003 B, %.4f at 0.004 B\n", q, f.q.back());
  EXPECT_NEAR(q, prandtl, 0.03 * prandtl);
}

}  // namespace
}  // namespace geompm

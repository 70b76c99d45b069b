// Long validation case (ctest label validation_long): the strip footings (mixed p-u, nu = 0.49)
// on h = B/40, the finest mesh of docs/validation.md §5 (case
// scripts/validation/cases/strip_footing_b40.json), a minute or two of one core each: the steel
// block of examples/strip_footing and the rigid structures of examples/structures, each with the
// incremental pressure equation and its fitted start (docs/theory.md eqs. 11.8-11.11), which
// keeps the load from sagging as the points cross the finer cells (with the total equation the
// rigid structures end 3.5 % and 5.9 % below Prandtl's 2 + pi at 0.1 B).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "footing_run.hpp"
#include "measured_settings.hpp"
#include "strip_mesh.hpp"

namespace geompm {
namespace {

constexpr double kPrandtl = 2.0 + M_PI;  // q_u / s_u of a rigid strip on Tresca soil

// The footing on h = B/40 with the incremental pressure equation and its fitted start (the steel
// block's example carries them, with the settings it was measured with, measured_settings.hpp).
const testing::Footing& fine_strip(const std::string& example) {
  std::string text = testing::example_text(example);
  const bool steel = example == "strip_footing/strip_footing.yaml";
  text = steel ? testing::as_measured_steel_block(text)
               : testing::with_numerics(testing::incremental_pressure(text), "mixed_pressure_start",
                                        "fitted");
  text = testing::strip_mesh(testing::no_vtk(text), 20);
  // The steel block's reaction acts down on it; the contact force on a structure up.
  return testing::run_footing(text, "strip_b40_" + example.substr(example.rfind('/') + 1),
                              steel ? -2.0 : 2.0);
}

TEST(StripFootingValidation, SteelBlockOnBOver40IsInTheBandAtATenthOfB) {
  const auto& f = fine_strip("strip_footing/strip_footing.yaml");
  const double q = f.q_at(0.1);
  std::printf("[steel block, h = B/40] q/s_u = %.3f at 0.1 B\n", q);
  EXPECT_GE(q, 5.14);
  EXPECT_LE(q, 5.40);
}

TEST(StripFootingValidation, RigidStructuresOnBOver40StayWithinFivePercentOfPrandtl) {
  // Issue 42's target for the rigid structures (within 5 % at 0.1 B), here on the finer mesh;
  // measured: smooth 5.145 at 0.1 B and 5.123 over 0.08-0.1 B, rough 4.996 and 5.037 (the
  // former penalty footings, with the same pressure settings: 5.128 and 5.127, within 0.3 %).
  for (const char* example :
       {"structures/strip_footing_smooth.yaml", "structures/strip_footing_rough.yaml"}) {
    const auto& f = fine_strip(example);
    const double q = f.q_at(0.1), mean = f.q_mean(0.08, 0.1);
    std::printf("[%s, h = B/40] q/s_u = %.3f at 0.1 B, %.3f over 0.08-0.1 B\n", example, q, mean);
    EXPECT_NEAR(q / kPrandtl, 1.0, 0.05) << example;
    EXPECT_NEAR(mean / kPrandtl, 1.0, 0.05) << example;
  }
}

}  // namespace
}  // namespace geompm

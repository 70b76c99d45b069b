// Long validation case (ctest label validation_long): the three strip footing examples (mixed
// p-u, nu = 0.49) on h = B/40, the finest mesh of docs/validation.md §5 (case
// scripts/validation/cases/strip_footing_b40.json), about 5-10 minutes of one core each. The
// verdict there: the steel block is in the band 5.14-5.40 at 0.1 B; the rigid footings land
// within 1 % of Prandtl's 2 + pi, just below it (5.128 and 5.127 measured), so the band is not
// reached by them (after the points cross cells they are the quadrature, docs/validation.md §5).
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

// The examples with the settings they were measured with (measured_settings.hpp).
const testing::Footing& fine_strip(const std::string& example) {
  std::string text = testing::example_text(example);
  text = example == "strip_footing/strip_footing.yaml"
             ? testing::as_measured_steel_block(text)
             : testing::as_measured_rigid_strip(text, example.find("smooth") != std::string::npos);
  text = testing::strip_mesh(testing::no_vtk(text), 20);
  return testing::run_footing(text, "strip_b40_" + example.substr(example.rfind('/') + 1), -2.0);
}

TEST(StripFootingValidation, SteelBlockOnBOver40IsInTheBandAtATenthOfB) {
  const auto& f = fine_strip("strip_footing/strip_footing.yaml");
  const double q = f.q_at(0.1);
  std::printf("[steel block, h = B/40] q/s_u = %.3f at 0.1 B\n", q);
  EXPECT_GE(q, 5.14);
  EXPECT_LE(q, 5.40);
}

TEST(StripFootingValidation, RigidFootingsOnBOver40EndWithinOnePercentOfPrandtl) {
  for (const char* example : {"strip_footing/strip_footing_smooth.yaml",
                              "strip_footing/strip_footing_rigid_rough.yaml"}) {
    const auto& f = fine_strip(example);
    const double q = f.q_at(0.1), mean = f.q_mean(0.08, 0.1);
    std::printf("[%s, h = B/40] q/s_u = %.3f at 0.1 B, %.3f over 0.08-0.1 B\n", example, q, mean);
    EXPECT_NEAR(q / kPrandtl, 1.0, 0.01) << example;
    EXPECT_NEAR(mean / kPrandtl, 1.0, 0.01) << example;
  }
}

}  // namespace
}  // namespace geompm

// The stiffness of the empty parts of cells and of sparse nodes (docs/theory.md §6) is relative
// to the smallest modulus of the materials the points carry, the soil's: neither a stiff body
// among the points (a steel block) nor a material that is only listed changes it.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "run_model.hpp"

namespace geompm {
namespace {

// The smooth rigid strip (a structure in contact; clay, E = 500 s_u; the footing is no body) pushed
// to 0.02 B: the heave beside the footing moves into empty cells, so their stiffness enters.
spec::Model short_smooth_strip() {
  auto spec = testing::read_example("structures/strip_footing_smooth.yaml");
  spec.phases.at(0).duration = 0.2;
  return spec;
}

spec::Material unused_steel() {
  spec::Material steel;
  steel.name = "unused_steel";
  steel.model = "linear_elastic";
  steel.parameters = {{"E", 1.0e7}, {"nu", 0.2}, {"density", 0.0}};
  return steel;
}

TEST(EmptyCellScale, IsTheSmallestModulusThePointsCarry) {
  auto spec = short_smooth_strip();
  EXPECT_DOUBLE_EQ(build_model(spec)->softest_modulus(), 500.0);
  spec.materials.push_back(unused_steel());
  EXPECT_DOUBLE_EQ(build_model(spec)->softest_modulus(), 500.0);
  spec.materials.back().parameters.at("E") = 1.0;  // softer, but still no point carries it
  EXPECT_DOUBLE_EQ(build_model(spec)->softest_modulus(), 500.0);
  // The steel block of the rough example is a body (E = 1e5 s_u): the clay's 500 s_u stays the
  // scale, the block's modulus is the largest.
  const auto block = testing::read_example("strip_footing/strip_footing.yaml");
  EXPECT_DOUBLE_EQ(build_model(block)->softest_modulus(), 500.0);
  EXPECT_DOUBLE_EQ(build_model(block)->largest_modulus(), 1.0e5);
}

TEST(EmptyCellScale, AnUnusedMaterialChangesNothing) {
  auto spec = short_smooth_strip();
  const auto without = testing::run_spec(spec, "empty_scale_without");
  spec.materials.push_back(unused_steel());
  const auto with = testing::run_spec(spec, "empty_scale_with");
  const std::vector<double> a = without.column("force");
  const std::vector<double> b = with.column("force");
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GT(a.size(), 2u);
  // Before the fix the steel made the empty cells 2e4 times stiffer and moved the load.
  for (std::size_t k = 0; k < a.size(); ++k) EXPECT_EQ(a[k], b[k]) << "row " << k;
  EXPECT_GT(std::abs(a.back()), 0.0);
}

}  // namespace
}  // namespace geompm

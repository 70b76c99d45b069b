// Results do not depend on the number of threads: assembly runs over cells of one colour at a
// time, so every sum is taken in the same order (docs/architecture.md).
#include <gtest/gtest.h>
#include <omp.h>

#include <string>

#include "run_model.hpp"

namespace geompm {
namespace {

// The oedometer on a mesh large enough that every parallel loop runs in parallel, with
// `interpolation`, run on one and on two threads: every point's stress and position and every
// history value must be the same to the bit.
void expect_thread_count_independent(spec::Interpolation interpolation, const std::string& name,
                                     bool fem_below = false) {
  auto spec = testing::read_example("oedometer/oedometer.yaml");
  if (fem_below) {  // the lower half FEM cells (docs/theory.md §19), assembled colour by colour
    spec::MeshRegion fem;
    fem.name = "lower";
    fem.kind = CellKind::Fem;
    fem.region.kind = spec::Region::Kind::Box;
    fem.region.max = Vec3(1.0, 0.5, 0.0);
    spec.regions.push_back(fem);
  }
  auto& grid = *spec.mesh.generate;
  grid.axes[0] = {AxisSegment{1.0, 48, 1.0}};
  grid.axes[1] = {AxisSegment{1.25, 60, 1.0}};
  spec.point_sets.at(0).region.min.y() = 0.99;
  spec.phases.at(0).duration = 0.3;
  spec.numerics.interpolation = interpolation;
  omp_set_num_threads(1);
  const auto one = testing::run_spec(spec, name + "_1");
  omp_set_num_threads(2);
  const auto two = testing::run_spec(spec, name + "_2");
  omp_set_num_threads(omp_get_num_procs());
  ASSERT_GT(one.model->points.size(), 4096);
  ASSERT_EQ(one.model->points.size(), two.model->points.size());
  double worst = 0.0;
  for (Index p = 0; p < one.model->points.size(); ++p) {
    worst = std::max(worst, (one.model->points.stress[p] - two.model->points.stress[p]).norm());
    worst = std::max(worst, (one.model->points.position[p] - two.model->points.position[p]).norm());
  }
  if (fem_below) {
    const MaterialPoints &g1 = one.model->fem->gauss_points(), &g2 = two.model->fem->gauss_points();
    ASSERT_GT(g1.size(), 4096);
    for (Index g = 0; g < g1.size(); ++g)
      worst = std::max(worst, (g1.stress[g] - g2.stress[g]).norm());
  }
  EXPECT_EQ(worst, 0.0);
  EXPECT_EQ(one.history.rows, two.history.rows);
}

TEST(Threads, OneAndTwoThreadsGiveIdenticalResults) {
  expect_thread_count_independent(spec::Interpolation::Standard, "threads");
}

// The wide stencils of GIMP overlap across cells: their points are integrated on all threads
// and scattered in point order (physics/point_integrator.cpp).
TEST(Threads, WideStencilsOnOneAndTwoThreadsGiveIdenticalResults) {
  expect_thread_count_independent(spec::Interpolation::Gimp, "threads_gimp");
}

// The FEM region's cells run on all threads too, one colour of the grid at a time.
TEST(Threads, FemCellsOnOneAndTwoThreadsGiveIdenticalResults) {
  expect_thread_count_independent(spec::Interpolation::Standard, "threads_fem", true);
}

}  // namespace
}  // namespace geompm

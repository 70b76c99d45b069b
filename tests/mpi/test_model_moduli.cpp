// The materials' moduli that scale the empty-cell stiffness and contact (Model::softest_modulus,
// largest_modulus) in a distributed run, under mpirun on 2 processes (ctest -L mpi): once the
// points are shared out, a process may hold no point of a material; given the processes, the
// points of every process count. The rough strip footing's steel block (a body of points on the
// clay, E = 1e5 against the clay's 500) kept by process 1 alone and the clay by process 0 alone:
// on their own points, process 0 would find 500 for both, process 1 1e5 for both.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "geompm/analysis/model.hpp"
#include "mpi_world.hpp"
#include "run_model.hpp"

namespace geompm {
namespace {

TEST(ModelModuli, CountThePointsOfEveryProcess) {
  const Communicator& world = testing::world();
  ASSERT_EQ(world.size(), 2) << "run under mpirun with 2 processes";
  auto model = build_model(testing::read_example("strip_footing/strip_footing.yaml"));
  Index steel = 0;
  while (model->spec.materials[steel].name != "steel") ++steel;
  std::vector<char> elsewhere(model->points.size());
  for (Index p = 0; p < model->points.size(); ++p)
    elsewhere[p] = (model->points.material[p] == steel) != (world.rank() == 1);
  model->points.remove(elsewhere);
  ASSERT_GT(model->points.size(), 0);

  EXPECT_DOUBLE_EQ(model->largest_modulus(world), 1.0e5);
  EXPECT_DOUBLE_EQ(model->softest_modulus(world), 500.0);
  // This process's points alone give its own material's modulus for both.
  const double own = world.rank() == 1 ? 1.0e5 : 500.0;
  EXPECT_DOUBLE_EQ(model->largest_modulus(), own);
  EXPECT_DOUBLE_EQ(model->softest_modulus(), own);
}

}  // namespace
}  // namespace geompm

#include <gtest/gtest.h>

#include <memory>

#include "geompm/solver/petsc_communicator.hpp"
#include "mpi_world.hpp"

namespace geompm::testing {

namespace {
std::unique_ptr<Communicator> processes;
}

const Communicator& world() { return *processes; }

}  // namespace geompm::testing

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  geompm::testing::processes = geompm::mpi_world_communicator("");
  const geompm::Communicator& world = geompm::testing::world();
  // Only process 0 reports; every process runs every test.
  if (world.rank() != 0)
    delete ::testing::UnitTest::GetInstance()->listeners().Release(
        ::testing::UnitTest::GetInstance()->listeners().default_result_printer());
  const int failed = RUN_ALL_TESTS();
  // A failure on any process fails the run.
  return world.all(failed == 0) ? 0 : 1;
}

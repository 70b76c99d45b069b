// Seeding on several processes (analysis/body_seeding.hpp), under mpirun on 2 and 3 processes
// (ctest -L mpi): built for the processes, each model holds from the start only the points of its
// own cells (none is created and dropped), the cut is the one the serial model's points give, and
// the points of every process gathered by id are the serial model's to the byte: the same ids,
// volumes, masses, initial stresses (given, K0), velocities, internal state and point sets. So a
// distributed run starts where the serial one starts, and a checkpoint restarts on any count.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "geompm/analysis/distribution.hpp"
#include "geompm/analysis/model.hpp"
#include "geompm/core/byte_archive.hpp"
#include "geompm/points/point_exchange.hpp"
#include "mpi_world.hpp"
#include "run_model.hpp"

namespace geompm {
namespace {

class DistributedSeeding : public ::testing::TestWithParam<const char*> {};

TEST_P(DistributedSeeding, HoldsOnlyItsOwnCellsPointsWithTheSerialIdsAndValues) {
  const Communicator& world = testing::world();
  const spec::Model spec = testing::read_example(GetParam());
  const auto serial = build_model(spec);
  const auto model = build_model(spec, world);
  ASSERT_TRUE(serial->cell_part.empty());

  // The cut the serial model's points give, the same on every process.
  EXPECT_EQ(model->cell_part, partition_by_points(*serial, world.size()));
  Index own = 0;
  for (Index c : serial->points.cell) own += model->cell_part[c] == world.rank();
  EXPECT_EQ(model->points.size(), own);
  for (Index p = 0; p < model->points.size(); ++p)
    ASSERT_EQ(model->cell_part[model->points.cell[p]], world.rank()) << "point " << p;
  // None twice: each point on one process (an FEM region's process may hold no point at all).
  EXPECT_EQ(world.sum(model->points.size()), serial->points.size());
  // Seeded in the serial order: ascending ids.
  for (Index p = 1; p < model->points.size(); ++p)
    ASSERT_LT(model->points.id[p - 1], model->points.id[p]);

  const MaterialPoints all = gather_points(model->points, world);
  if (world.rank() == 0) {
    EXPECT_EQ(all.size(), serial->points.size());
    EXPECT_EQ(all.id, serial->points.id);
    ByteWriter gathered, serial_points;
    all.save(gathered);
    serial->points.save(serial_points);
    EXPECT_TRUE(gathered.bytes() == serial_points.bytes()) << "a point's value differs";
  }
  EXPECT_EQ(model->seeds_inside_structures, serial->seeds_inside_structures);
  EXPECT_EQ(model->point_set_names, serial->point_set_names);
  // What `geompm run` prints counts every process's points.
  EXPECT_EQ(describe_model(*model, world), describe_model(*serial));
}

INSTANTIATE_TEST_SUITE_P(
    Examples, DistributedSeeding,
    ::testing::Values("column/column.yaml",                     // point sets, GIMP
                      "column/column_3d.yaml",                  // hexahedra
                      "earth_pressure/rankine_active.yaml",     // K0 procedure
                      "layered_ground/k0_layered.yaml",         // layers, K0 by layer
                      "vibrating_bar/vibrating_bar.yaml",       // initial velocity
                      "strip_footing/strip_footing.yaml",       // s_u by depth, two bodies
                      "structures/deformable_pile.yaml",        // seeds inside a structure
                      "coupling/pile_coupled.yaml",             // an FEM region, axisymmetric
                      "coupling/strip_footing_coupled.yaml"));  // FEM cells of a body

}  // namespace
}  // namespace geompm

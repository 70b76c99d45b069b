// The point store cut into subsets and put together again (what points/point_exchange sends
// between the processes of a distributed run): every field of every point travels, in the order
// asked, and the migration's bookkeeping on one process keeps or drops whole points.
#include <gtest/gtest.h>

#include <string>

#include "geompm/core/byte_archive.hpp"
#include "geompm/points/material_points.hpp"
#include "geompm/points/point_exchange.hpp"

namespace geompm {
namespace {

MaterialPoints numbered_points(int n) {
  MaterialPoints p;
  for (int k = 0; k < n; ++k) {
    const double s = 1.0 + k;
    p.add(k % 2, k % 3, Vec3(s, -s, 0.5 * s), 0.1 * s, 2.0, k, Vec3(0.1 * k, 0, 0),
          Vec3::Constant(0.2));
    p.sets[k] = 1u << (k % 4);
    p.stress[k] = Mat3::Constant(-s);
    p.internal[k] = {s, 2 * s, 3 * s, 4 * s};
    p.domain_stretch[k] = 1.0 + 0.01 * k;
  }
  return p;
}

// Every field's bytes, through the checkpoint serialisation (which visits every field).
std::string bytes_of(const MaterialPoints& points) {
  ByteWriter out;
  points.save(out);
  return out.take();
}

TEST(PointSubsets, SubsetThenAppendGivesBackEveryFieldInOrder) {
  const MaterialPoints all = numbered_points(7);
  MaterialPoints joined = all.subset({0, 1, 2});
  joined.append(all.subset({3, 4, 5, 6}));
  EXPECT_EQ(bytes_of(joined), bytes_of(all));
  // A subset in another order is those points in that order.
  const MaterialPoints picked = all.subset({5, 2});
  ASSERT_EQ(picked.size(), 2);
  EXPECT_EQ(picked.id[0], 5);
  EXPECT_EQ(picked.id[1], 2);
  EXPECT_EQ(picked.stress[0], all.stress[5]);
  EXPECT_EQ(picked.internal[1], all.internal[2]);
  EXPECT_EQ(picked.cell[0], 5);
}

TEST(PointSubsets, KeepOwnPointsKeepsThoseOfTheProcessCells) {
  MaterialPoints points = numbered_points(6);  // point k in cell k
  const std::vector<int> cell_part = {0, 1, 1, 0, 2, 1};
  keep_own_points(points, cell_part, 1);
  ASSERT_EQ(points.size(), 3);
  EXPECT_EQ(points.id, (std::vector<Index>{1, 2, 5}));
  EXPECT_EQ(points.mass[2], numbered_points(6).mass[5]);
}

TEST(PointSubsets, OneProcessMigratesNothingAndGathersEverything) {
  MaterialPoints points = numbered_points(4);
  const std::string before = bytes_of(points);
  EXPECT_EQ(migrate_points(points, {0, 0, 0, 0}, serial_communicator()), 0);
  EXPECT_EQ(bytes_of(points), before);
  EXPECT_EQ(bytes_of(gather_points(points, serial_communicator())), before);
}

}  // namespace
}  // namespace geompm

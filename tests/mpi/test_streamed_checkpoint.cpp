// A checkpoint written by several processes (points/streamed_points.hpp, io/checkpoint_file.hpp),
// under mpirun on 2 and 3 processes (ctest -L mpi): the points of every process, held in no
// particular order and with gaps in their ids (points removed as lost), pass to process 0 a window
// of ids at a time, and the section and the whole file it writes are to the byte those a serial
// run writes of the same points in id order (docs/checkpoint-format.md): the same layout, the same
// checksum, so that the file resumes on any process count. Also for the points an example seeds
// on the processes and its FEM region's Gauss points, each process's own.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "geompm/analysis/model.hpp"
#include "geompm/core/byte_archive.hpp"
#include "geompm/coupling/fem_region.hpp"
#include "geompm/io/checkpoint_file.hpp"
#include "geompm/points/streamed_points.hpp"
#include "mpi_world.hpp"
#include "run_model.hpp"

namespace geompm {
namespace {

// 70 000 points, every value of every array its own (from the id), every seventh point removed
// (ids with gaps), in id order: the serial store.
MaterialPoints every_point() {
  MaterialPoints points;
  for (Index p = 0; p < 70000; ++p) {
    const double s = 1.0 + p;
    points.add(p % 3, p % 2, Vec3(s, std::sin(s), std::cos(s)), 1e-3 * s, 2.0, p / 4,
               Vec3(0.5, -0.5, 0.25 * std::sin(s)), Vec3::Constant(0.1 + 1e-6 * s));
    points.sets[p] = static_cast<std::uint64_t>(p) * 2654435761u;
    points.displacement[p] = Vec3(std::sqrt(s), 1 / s, -s);
    points.phase_displacement[p] = 0.5 * points.displacement[p];
    points.velocity[p] = Vec3(std::log(s), s * s, 0.0);
    points.acceleration[p] = -points.velocity[p];
    points.stress[p] = Mat3::Constant(s) + Mat3::Identity() * std::sin(s);
    points.deformation_gradient[p] = Mat3::Identity() * (1 + 1e-7 * s);
    points.domain_stretch[p] = 1 - 1e-8 * s;
    points.volume_mismatch[p] = 1e-9 * s;
    points.elastic_left_cauchy_green[p] = Mat3::Constant(1 / s);
    points.internal[p] = {s, -s, 2 * s, std::exp(-1e-4 * s)};
  }
  std::vector<char> lost(points.size());
  for (Index p = 0; p < points.size(); ++p) lost[p] = p % 7 == 3;
  points.remove(lost);
  return points;
}

// This process's share of `all`: a point on the process its id's hash names, held in no id
// order (as points that migrated are appended).
MaterialPoints share(const MaterialPoints& all, const Communicator& world) {
  std::vector<Index> mine;
  for (Index p = 0; p < all.size(); ++p)
    if ((static_cast<std::uint32_t>(all.id[p]) * 2654435761u >> 7) % world.size() ==
        static_cast<std::uint32_t>(world.rank()))
      mine.push_back(p);
  std::stable_sort(mine.begin(), mine.end(),
                   [&](Index a, Index b) { return all.id[a] % 97 < all.id[b] % 97; });
  return all.subset(mine);
}

std::string saved(const MaterialPoints& points) {
  ByteWriter out;
  points.save(out);
  return out.take();
}

// The section's bytes on process 0 (empty elsewhere).
std::string streamed(const MaterialPoints& points, const std::vector<Index>& which, Index window) {
  std::string bytes;
  stream_saved_points(
      points, which, testing::world(), [&](std::string_view piece) { bytes.append(piece); },
      window);
  return bytes;
}

std::vector<Index> every_index(const MaterialPoints& points) {
  std::vector<Index> all(points.size());
  for (Index p = 0; p < points.size(); ++p) all[p] = p;
  return all;
}

std::string read_bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(StreamedCheckpoint, EveryProcesssPointsAreTheSerialSectionToTheByte) {
  const Communicator& world = testing::world();
  ASSERT_GE(world.size(), 2) << "run under mpirun with 2 or more processes";
  const MaterialPoints all = every_point();
  const MaterialPoints mine = share(all, world);
  ASSERT_GT(mine.size(), 0);
  ASSERT_LT(mine.size(), all.size());
  const std::string serial = saved(all);
  // Windows of 1000 ids (many windows, some with no point of a process) and the default one (a
  // single window here).
  for (const Index window : {Index{1000}, streamed_points_window}) {
    const std::string bytes = streamed(mine, every_index(mine), window);
    if (world.rank() == 0) {
      EXPECT_EQ(bytes.size(), saved_points_bytes(all.size()));
      EXPECT_TRUE(bytes == serial) << "window " << window << ": not the serial bytes";
    } else {
      EXPECT_TRUE(bytes.empty());
    }
  }
}

TEST(StreamedCheckpoint, SomeOfEachProcesssPoints) {
  // As the FEM region's Gauss points: each process passes those it keeps up to date.
  const Communicator& world = testing::world();
  const MaterialPoints all = every_point();
  const MaterialPoints mine = share(all, world);
  std::vector<Index> kept, which;
  for (Index p = 0; p < all.size(); ++p)
    if (all.id[p] % 3 != 0) kept.push_back(p);
  for (Index p = 0; p < mine.size(); ++p)
    if (mine.id[p] % 3 != 0) which.push_back(p);
  const std::string bytes = streamed(mine, which, 4096);
  if (world.rank() == 0) {
    EXPECT_TRUE(bytes == saved(all.subset(kept)));
  }
}

TEST(StreamedCheckpoint, OneProcessWritesItsStoresOrder) {
  // A serial run's points in its store's order (what it resumes from bit for bit), not sorted.
  const MaterialPoints all = every_point();
  const MaterialPoints scrambled = share(all, testing::world());
  std::vector<Index> which = every_index(scrambled);
  std::reverse(which.begin(), which.end());
  std::string bytes;
  stream_saved_points(
      scrambled, which, serial_communicator(), [&](std::string_view piece) { bytes.append(piece); },
      1000);
  EXPECT_TRUE(bytes == saved(scrambled.subset(which)));
}

TEST(StreamedCheckpoint, TheWholeFileIsTheSerialOne) {
  const Communicator& world = testing::world();
  const MaterialPoints all = every_point();
  ASSERT_EQ(all.size(), 60000);
  const MaterialPoints mine = share(all, world);
  const std::uint64_t hash = 0x1234abcdULL;
  // Process 0 names both files; the others take part in the streaming only.
  const std::filesystem::path dir =
      world.rank() == 0 ? testing::fresh_directory("streamed_checkpoint") : "";
  const std::filesystem::path streamed_file = dir / "streamed.bin",
                              serial_file = dir / "serial.bin";
  std::optional<CheckpointWriter> writer;
  if (world.rank() == 0) {
    writer.emplace(streamed_file, hash, 3);
    writer->section("run", "the run's bytes");
    writer->begin_section("points", saved_points_bytes(world.sum(mine.size())));
  } else {
    world.sum(mine.size());
  }
  stream_saved_points(
      mine, world, [&](std::string_view bytes) { writer->add(bytes); }, 5000);
  if (world.rank() != 0) return;
  writer->section("model", std::string(3, '\0'));
  writer->commit();
  write_checkpoint_file(
      serial_file, hash,
      {{"run", "the run's bytes"}, {"points", saved(all)}, {"model", std::string(3, '\0')}});
  const std::string written = read_bytes(streamed_file);
  EXPECT_TRUE(written == read_bytes(serial_file)) << "not the serial file";
  EXPECT_FALSE(std::filesystem::exists(checkpoint_temporary(streamed_file)));
  const CheckpointContents contents = read_checkpoint_file(streamed_file, hash, {"points"});
  EXPECT_EQ(contents.place("points").length, saved_points_bytes(all.size()));
}

class SeededCheckpoint : public ::testing::TestWithParam<const char*> {};

TEST_P(SeededCheckpoint, APointsAndGaussPointsSectionIsTheSerialModels) {
  // The points every process seeds for its own cells, and the FEM region's Gauss points of its
  // own cells, are to the byte the serial model's once streamed to process 0.
  const Communicator& world = testing::world();
  const spec::Model spec = testing::read_example(GetParam());
  const auto serial = build_model(spec);
  const auto model = build_model(spec, world);
  const std::string points = streamed(model->points, every_index(model->points), 2048);
  if (world.rank() == 0) {
    EXPECT_TRUE(points == saved(serial->points));
  }
  if (!serial->fem) return;
  model->fem->keep_own(model->cell_part, world.rank());
  const std::vector<Index> own = model->fem->own_gauss_points();
  EXPECT_EQ(world.sum(static_cast<Index>(own.size())), model->fem->gauss_points().size());
  const std::string gauss = streamed(model->fem->gauss_points(), own, 64);
  if (world.rank() == 0) {
    EXPECT_TRUE(gauss == saved(serial->fem->gauss_points()));
  }
}

INSTANTIATE_TEST_SUITE_P(Examples, SeededCheckpoint,
                         ::testing::Values("strip_footing/strip_footing.yaml",  // two bodies
                                           "coupling/pile_coupled.yaml"));      // an FEM region

}  // namespace
}  // namespace geompm

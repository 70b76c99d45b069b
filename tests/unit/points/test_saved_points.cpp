// A checkpoint's points read for some cells only (points/saved_points.hpp), as each process of a
// distributed run reads them when it resumes: the points of the cells a process owns, every field
// of each, in the file's order, whatever stands before and after the points in the file, across
// the slices the reader takes (70 000 points: more than one slice of 65 536).
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <string>

#include "geompm/core/byte_archive.hpp"
#include "geompm/core/error.hpp"
#include "geompm/points/saved_points.hpp"

namespace geompm {
namespace {

constexpr Index points_count = 70000;
const std::string before = "thirteen byte", after = "tail";

// Point k in cell k % 5, its fields telling it apart.
MaterialPoints points_in_five_cells() {
  MaterialPoints p;
  for (Index k = 0; k < points_count; ++k) {
    const double x = 0.001 * k;
    p.add(k % 2, k % 3, Vec3(x, 1 - x, 2 * x), 1 + x, 2.0, k % 5, Vec3(x, 0, 0), Vec3::Ones());
    p.stress[k] = Mat3::Constant(-x);
    p.internal[k][1] = x;
  }
  return p;
}

std::string saved(const MaterialPoints& points) {
  ByteWriter out;
  points.save(out);
  return out.take();
}

class SavedPointsFile : public ::testing::Test {
 protected:
  void SetUp() override {
    all_ = points_in_five_cells();
    bytes_ = saved(all_);
    std::ofstream(file_, std::ios::binary) << before << bytes_ << after;
  }
  void TearDown() override { std::filesystem::remove(file_); }
  SavedPoints reader(std::uint64_t length) const {
    return SavedPoints(file_, before.size(), length, "test: section 'points'");
  }

  std::filesystem::path file_ = std::filesystem::temp_directory_path() /
                                ("geompm_saved_points_" + std::to_string(::getpid()) + ".bin");
  MaterialPoints all_;
  std::string bytes_;
};

TEST_F(SavedPointsFile, EachProcessReadsTheWholePointsOfItsCellsOnly) {
  const SavedPoints points = reader(bytes_.size());
  EXPECT_EQ(points.size(), points_count);
  EXPECT_EQ(points.points_in_cell(6), (std::vector<double>{14000, 14000, 14000, 14000, 14000, 0}));
  const std::vector<int> cell_part = {0, 1, 2, 0, 1, 2};
  Index read = 0;
  for (int rank = 0; rank < 3; ++rank) {
    std::vector<Index> own;
    for (Index p = 0; p < all_.size(); ++p)
      if (cell_part[all_.cell[p]] == rank) own.push_back(p);
    const MaterialPoints mine = points.load(cell_part, rank);
    EXPECT_EQ(saved(mine), saved(all_.subset(own))) << "rank " << rank;
    read += mine.size();
  }
  EXPECT_EQ(read, points_count);
  EXPECT_EQ(saved(points.load({}, 0)), bytes_) << "every point without a cut";
}

TEST_F(SavedPointsFile, RefusesAPointBeyondTheMeshAndArraysThatDoNotFitTheSection) {
  const SavedPoints points = reader(bytes_.size());
  EXPECT_THROW(points.points_in_cell(4), InputError);  // cell 4 is not in a mesh of 4 cells
  EXPECT_THROW(reader(bytes_.size() - 1), InputError);
  try {
    reader(bytes_.size() + 1);
    ADD_FAILURE() << "a byte too many accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("test: section 'points': 1 bytes left over"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace geompm

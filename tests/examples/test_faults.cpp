// End-to-end: runs that meet a fault of their environment — a disk that fills up mid-run, an
// output directory that cannot be used, the half-written temporaries of a killed run — and what
// `vtk: {every: 0}` writes. For each: the exit code, a message that names the file and says why,
// and nothing half written (history.csv ends with a whole row).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "example_text.hpp"

namespace {

namespace fs = std::filesystem;

using namespace geompm::testing;

/// An elastic column of 1 x 2 cells under gravity in 250 steps: small files, but newton.csv grows
/// by a row per Newton iteration, to some 40 kB.
std::string column_model(const std::string& output) {
  return R"(title: Column under gravity (test_faults.cpp)
analysis: {kinematics: plane_strain}
mesh:
  generate:
    cell: quad4
    x: {length: 1, cells: 1}
    y: {length: 2, cells: 2}
materials:
  soil: {model: linear_elastic, E: 1000, nu: 0.3, density: 1}
bodies:
  soil:
    material: soil
    region: {box: {min: [0, 0], max: [1, 2]}}
phases:
  - name: gravity
    duration: 1
    time_step: 0.004
    gravity: {acceleration: [0, -10], ramp: true}
    fixities:
      - {boundary: bottom, fix: all}
      - {boundary: left, fix: normal}
      - {boundary: right, fix: normal}
)" + output;
}

class Faults : public GeompmRunTest<> {
 protected:
  /// geompm with `args` under a shell `prefix` (ulimit, trap) in the working directory.
  CommandResult geompm_under(const std::string& prefix, const std::vector<std::string>& args) {
    return run_geompm(args, work(), root_ / "capture", prefix);
  }
};

// The disk fills up mid-run (a file size limit of 20 blocks, 10 kB in dash and 20 kB in bash,
// with SIGXFSZ ignored so that the write fails with EFBIG as on a full disk; root is bound by it
// too): newton.csv outgrows it after some 120 or 240 iterations. The run stops with exit 3 naming
// the file; history.csv holds whole rows only.
TEST_F(Faults, DiskFullMidRunStopsTheRun) {
  write("model.yaml", column_model("output: {vtk: {every: 1000}}\n"));
  const auto r = geompm_under("trap '' XFSZ; ulimit -f 20",
                              {"run", "-q", "-t", "1", "-o", "out", "model.yaml"});
  ASSERT_TRUE(r.exited) << describe(r);
  EXPECT_EQ(r.exit_code, 3) << describe(r);
  EXPECT_TRUE(Contains(r.err, "run stopped: cannot write"));
  EXPECT_TRUE(Contains(r.err, "newton.csv"));
  EXPECT_TRUE(Contains(r.err, "File too large"));
  const std::string history = read_text(work() / "out" / "history.csv");
  ASSERT_FALSE(history.empty());
  EXPECT_EQ(history.back(), '\n') << "history.csv ends mid-row";
  const std::string newton = read_text(work() / "out" / "newton.csv");
  ASSERT_FALSE(newton.empty());
  EXPECT_EQ(newton.back(), '\n') << "newton.csv ends mid-row";
  const Csv rows = read_csv(work() / "out" / "history.csv");
  EXPECT_TRUE(rows.problem.empty()) << rows.problem;
  EXPECT_LT(rows.rows.size(), 251u) << "the run should have stopped before its end";
  const std::string summary = read_text(work() / "out" / "summary.json");
  EXPECT_TRUE(Contains(summary, "\"status\": \"stopped\""));
}

// history.csv on a full disk from its first line (/dev/full: ENOSPC for root too).
TEST_F(Faults, HistoryOnAFullDiskStopsTheRun) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  write("model.yaml", column_model(""));
  fs::create_directories(work() / "out");
  fs::create_symlink("/dev/full", work() / "out" / "history.csv");
  const auto r = geompm({"run", "-q", "-t", "1", "-o", "out", "model.yaml"});
  ASSERT_TRUE(r.exited) << describe(r);
  EXPECT_EQ(r.exit_code, 3) << describe(r);
  EXPECT_TRUE(Contains(r.err, "history.csv"));
  EXPECT_TRUE(Contains(r.err, "No space left on device"));
}

// -o names an existing file, a path through a file, a directory that cannot be written: bad
// input (exit 2) with the reason, not an internal error.
TEST_F(Faults, UnusableOutputDirectory) {
  write("model.yaml", column_model(""));
  write("notes.txt", "not a directory\n");
  const auto on_file = geompm({"run", "-q", "-o", "notes.txt", "model.yaml"});
  ASSERT_TRUE(on_file.exited) << describe(on_file);
  EXPECT_EQ(on_file.exit_code, 2) << describe(on_file);
  EXPECT_TRUE(Contains(on_file.err, "error: notes.txt: cannot use it as the output directory"));
  EXPECT_TRUE(Contains(on_file.err, "an existing file, not a directory"));
  EXPECT_EQ(read_text(work() / "notes.txt"), "not a directory\n");

  const auto through_file = geompm({"run", "-q", "-o", "notes.txt/out", "model.yaml"});
  ASSERT_TRUE(through_file.exited) << describe(through_file);
  EXPECT_EQ(through_file.exit_code, 2) << describe(through_file);
  EXPECT_TRUE(Contains(through_file.err, "'notes.txt' is a file, not a directory"));

  // geompm mesh -o, the same: Gmsh used to fail only when it wrote, as an internal error.
  const auto mesh = geompm({"mesh", "--size", "1", "1", "--h", "0.5", "-o", "notes.txt/m.msh"});
  ASSERT_TRUE(mesh.exited) << describe(mesh);
  EXPECT_EQ(mesh.exit_code, 2) << describe(mesh);
  EXPECT_TRUE(Contains(mesh.err, "error: notes.txt: cannot use it as the output directory"));

  // Root writes into a read-only directory regardless; the check is for everyone else.
  if (geteuid() != 0) {
    fs::create_directories(work() / "locked");
    ::chmod((work() / "locked").c_str(), 0555);
    const auto locked = geompm({"run", "-q", "-o", "locked/out", "model.yaml"});
    ::chmod((work() / "locked").c_str(), 0755);
    ASSERT_TRUE(locked.exited) << describe(locked);
    EXPECT_EQ(locked.exit_code, 2) << describe(locked);
    EXPECT_TRUE(Contains(locked.err, "Permission denied"));
  }
  EXPECT_FALSE(Contains(on_file.err + through_file.err, "internal error"));
}

// A killed run leaves the temporaries of the files it was writing; the next run removes them.
TEST_F(Faults, StaleTemporariesAreRemoved) {
  write("model.yaml", column_model("output: {vtk: {every: 50}}\n"));
  fs::create_directories(work() / "out" / "vtk");
  std::ofstream(work() / "out" / ".points.pvd.tmp-99999-0") << "<half";
  std::ofstream(work() / "out" / "vtk" / ".points_000001.vtu.tmp-99999-3") << "<half";
  const auto r = geompm({"run", "-q", "-t", "1", "-o", "out", "model.yaml"});
  ASSERT_TRUE(r.exited && r.exit_code == 0) << describe(r);
  for (const auto& dir : {work() / "out", work() / "out" / "vtk"})
    for (const auto& entry : fs::directory_iterator(dir))
      EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << entry.path();
}

// vtk: {every: 0} means never: no ParaView file at all, not even the initial state's.
TEST_F(Faults, VtkEveryZeroWritesNoParaViewFile) {
  write("model.yaml", column_model("output: {vtk: {every: 0}}\n"));
  const auto r = geompm({"run", "-q", "-t", "1", "-o", "out", "model.yaml"});
  ASSERT_TRUE(r.exited && r.exit_code == 0) << describe(r);
  EXPECT_FALSE(fs::exists(work() / "out" / "points.pvd"));
  EXPECT_FALSE(fs::exists(work() / "out" / "grid.pvd"));
  int vtu = 0;
  if (fs::exists(work() / "out" / "vtk"))
    for (const auto& entry : fs::directory_iterator(work() / "out" / "vtk")) {
      ++vtu;
      ADD_FAILURE() << "wrote " << entry.path();
    }
  EXPECT_EQ(vtu, 0);
  EXPECT_TRUE(fs::is_regular_file(work() / "out" / "history.csv"));
}

}  // namespace

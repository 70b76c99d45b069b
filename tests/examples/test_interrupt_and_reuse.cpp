// End-to-end: Ctrl-C (SIGINT) ends a run cleanly, with its plots, summary.json and a checkpoint
// for what was done and exit code 3; and a new run in an output folder an earlier run wrote
// removes that run's files first, so that the folder never mixes two runs (--resume keeps them).
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "cli_support.hpp"
#include "example_text.hpp"
#include "process_support.hpp"

namespace {

namespace fs = std::filesystem;
using namespace geompm::testing;

/// The vibrating bar, run for 100 times its example's duration: minutes, unless interrupted.
std::string long_bar() {
  return replace_once(example_text("vibrating_bar/vibrating_bar.yaml"), "duration: 50",
                      "duration: 5000");
}

/// Rows of history.csv below its header (0 while it does not exist).
std::size_t history_rows(const fs::path& file) {
  const std::string text = read_text(file);
  std::size_t lines = 0;
  for (char c : text) lines += c == '\n';
  return lines > 0 ? lines - 1 : 0;
}

/// The files of `dir` and of `dir`/vtk, relative to `dir`.
std::set<std::string> files_in(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.is_regular_file()) names.insert(fs::relative(entry.path(), dir).string());
  return names;
}

/// The files a series (points.pvd) names.
std::set<std::string> series_files(const fs::path& pvd) {
  const std::string text = read_text(pvd);
  static const std::regex file(R"re(file="([^"]+)")re");
  std::set<std::string> names;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), file); it != std::sregex_iterator();
       ++it)
    names.insert((*it)[1].str());
  return names;
}

class Interrupt : public GeompmRunTest<> {};

TEST_F(Interrupt, CtrlCStopsTheRunCleanlyWithPlotsSummaryAndExitCode3) {
  write("run.yaml", long_bar());
  GeompmProcess run({"run", "-t", "1", "-o", "out", "run.yaml"}, work(), root_ / "capture");
  ASSERT_TRUE(run.started());
  // Interrupt once a few steps are written (at most a minute on a loaded machine).
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (run.running() && history_rows(work() / "out" / "history.csv") < 5 &&
         std::chrono::steady_clock::now() < give_up)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_TRUE(run.running()) << "the run ended before it could be interrupted";
  run.signal(SIGINT);
  const CommandResult r = run.wait();

  ASSERT_TRUE(r.exited) << describe(r);
  EXPECT_EQ(r.exit_code, 3) << describe(r);
  EXPECT_TRUE(Contains(r.err, "interrupted (SIGINT)"));
  const fs::path out = work() / "out";
  const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
  EXPECT_EQ(summary["status"], "stopped");
  EXPECT_NE(summary["reason"].get<std::string>().find("interrupted (SIGINT)"), std::string::npos);
  // What was done is all there: the summary counts the history's steps, the plots are drawn,
  // and a checkpoint of the last step lets --resume go on.
  const std::size_t rows = history_rows(out / "history.csv");
  EXPECT_GE(rows, 5u);
  EXPECT_EQ(summary["steps"].get<std::size_t>() + 1, rows);
  EXPECT_LT(summary["time"].get<double>(), 5000.0);
  for (const char* plot : {"centre_of_mass_velocity.png", "energy.png"})
    EXPECT_TRUE(fs::is_regular_file(out / plot)) << plot;
  EXPECT_TRUE(fs::is_regular_file(out / "checkpoint.bin"));
}

class ReusedOutputFolder : public GeompmRunTest<> {};

TEST_F(ReusedOutputFolder, ANewRunRemovesTheEarlierRunsFilesAndKeepsOthers) {
  // First run: the example, ParaView files every 10 steps, two plots.
  const std::string bar = example_text("vibrating_bar/vibrating_bar.yaml");
  write("first.yaml", bar);
  auto r = geompm({"run", "-q", "-t", "1", "-o", "out", "first.yaml"});
  ASSERT_TRUE(r.exited && r.exit_code == 0) << describe(r);
  const fs::path out = work() / "out";
  ASSERT_TRUE(fs::is_regular_file(out / "vtk" / "points_000500.vtu"));
  std::ofstream(out / "notes.txt") << "the engineer's own notes\n";

  // Second run, shorter, with a plot of another name: nothing of the first may remain.
  std::string second = replace_once(bar, "duration: 50", "duration: 2");
  second = replace_once(second, "file: energy.png", "file: energies.png");
  write("second.yaml", second);
  r = geompm({"run", "-t", "1", "-o", "out", "second.yaml"});
  ASSERT_TRUE(r.exited && r.exit_code == 0) << describe(r);
  EXPECT_TRUE(Contains(r.err, "files of an earlier run from out"));

  std::set<std::string> expected = {"notes.txt",
                                    "history.csv",
                                    "newton.csv",
                                    "summary.json",
                                    "checkpoint.bin",
                                    "points.pvd",
                                    "centre_of_mass_velocity.png",
                                    "energies.png"};
  for (const std::string& vtu : series_files(out / "points.pvd")) expected.insert(vtu);
  EXPECT_EQ(files_in(out), expected);
  EXPECT_EQ(history_rows(out / "history.csv"), 21u);  // 2 s in steps of 0.1 s, and step 0
}

}  // namespace

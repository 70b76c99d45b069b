// End-to-end: every model under examples/ passes `geompm check` and runs with `geompm run`,
// writing a history, ParaView series whose files exist, and every plot the model lists.
//
// The examples are found by globbing examples/*/*.yaml when the test program starts (test
// discovery runs it before each ctest run), so a new example is covered without editing this file.
//
// Each example's history.csv must also equal its reference in tests/reference_histories/ (every
// column within 1e-10 of the column's largest magnitude): the engine's reshaping, and any change
// that is not meant to change results, must leave every example's curve as it was. A change that
// is meant to change results regenerates the references with GEOMPM_WRITE_REFERENCES=1 set while
// this test runs, and says why in its commit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "geompm/io/model_reader.hpp"
#include "reference_history.hpp"

namespace {

namespace fs = std::filesystem;

using namespace geompm::testing;

// ---------------------------------------------------------------------------------------------
// Reading what a run wrote (history.csv: cli_support.hpp).

/// Checks the 8-byte PNG signature and a non-empty IHDR chunk.
::testing::AssertionResult IsPng(const fs::path& file) {
  if (!fs::is_regular_file(file)) return ::testing::AssertionFailure() << file << " is missing";
  const std::string bytes = read_text(file);
  static const std::string signature("\x89PNG\r\n\x1a\n", 8);
  if (bytes.size() < 33 || bytes.compare(0, 8, signature) != 0)
    return ::testing::AssertionFailure() << file << " does not start with the PNG signature";
  if (bytes.compare(12, 4, "IHDR") != 0)
    return ::testing::AssertionFailure() << file << " has no IHDR chunk first";
  auto be32 = [&](std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t k = 0; k < 4; ++k) v = (v << 8) | static_cast<unsigned char>(bytes[at + k]);
    return v;
  };
  if (be32(16) == 0 || be32(20) == 0)
    return ::testing::AssertionFailure() << file << " has a zero image size";
  return ::testing::AssertionSuccess();
}

struct PvdEntry {
  double time;
  std::string file;
};

std::vector<PvdEntry> read_pvd(const fs::path& file) {
  const std::string text = read_text(file);
  static const std::regex dataset(R"re(<DataSet\s+timestep="([^"]*)"[^>]*\sfile="([^"]*)")re");
  std::vector<PvdEntry> entries;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), dataset);
       it != std::sregex_iterator(); ++it)
    entries.push_back({std::stod((*it)[1].str()), (*it)[2].str()});
  return entries;
}

/// Every file a .pvd series names exists next to it and is a VTK XML file; the times increase.
/// The points series starts with the initial state; the grid, which has no solution fields
/// before the first step, starts with a step.
void expect_series(const fs::path& pvd, double final_time, bool starts_with_initial_state) {
  SCOPED_TRACE(pvd.string());
  ASSERT_TRUE(fs::is_regular_file(pvd)) << pvd << " is missing";
  const auto text = read_text(pvd);
  EXPECT_TRUE(Contains(text, "<VTKFile type=\"Collection\""));
  const auto entries = read_pvd(pvd);
  ASSERT_GE(entries.size(), starts_with_initial_state ? 2u : 1u) << text;
  for (std::size_t k = 0; k < entries.size(); ++k) {
    const fs::path vtu = pvd.parent_path() / entries[k].file;
    EXPECT_EQ(vtu.extension(), ".vtu") << entries[k].file;
    ASSERT_TRUE(fs::is_regular_file(vtu))
        << "the series names " << entries[k].file << ", which does not exist";
    const std::string content = read_text(vtu);
    EXPECT_TRUE(Contains(content.substr(0, 200), "<VTKFile")) << vtu;
    EXPECT_TRUE(Contains(content, "</VTKFile>")) << vtu << " is cut short";
    if (k > 0) {
      EXPECT_GT(entries[k].time, entries[k - 1].time) << entries[k].file;
    }
  }
  if (starts_with_initial_state) {
    EXPECT_EQ(entries.front().time, 0.0);
  } else {
    EXPECT_GT(entries.front().time, 0.0);
  }
  EXPECT_NEAR(entries.back().time, final_time, 1e-9 * std::max(1.0, std::abs(final_time)))
      << "the series should end with the state at the end of the last phase";
}

// ---------------------------------------------------------------------------------------------
// The examples.

fs::path source_dir() { return fs::path(GEOMPM_SOURCE_DIR); }

/// Every column of `run` within `tolerance` of `reference`, relative to the column's largest
/// magnitude in the reference (so that a quantity passing through zero is measured against its
/// own scale, not against round-off).
void expect_same_history(const Csv& run, const Csv& reference, double tolerance) {
  ASSERT_TRUE(reference.problem.empty()) << reference.problem;
  ASSERT_EQ(run.header, reference.header);
  ASSERT_EQ(run.rows.size(), reference.rows.size()) << "a different number of steps";
  for (std::size_t c = 0; c < reference.header.size(); ++c) {
    double scale = 0.0, largest = 0.0;
    std::size_t at = 0;
    for (const auto& row : reference.rows) scale = std::max(scale, std::abs(row[c]));
    for (std::size_t k = 0; k < reference.rows.size(); ++k) {
      const double difference = std::abs(run.rows[k][c] - reference.rows[k][c]);
      if (difference > largest) {
        largest = difference;
        at = k;
      }
    }
    EXPECT_LE(largest, tolerance * std::max(scale, 1e-300))
        << "column " << reference.header[c] << ", row " << at << ": " << run.rows[at][c]
        << " against the reference's " << reference.rows[at][c] << " (column scale " << scale
        << ")";
  }
}

/// examples/*/*.yaml, relative to examples/, sorted.
std::vector<std::string> find_examples() {
  std::vector<std::string> found;
  std::error_code error;
  const fs::path root = source_dir() / "examples";
  for (const auto& dir : fs::directory_iterator(root, error)) {
    if (!dir.is_directory()) continue;
    for (const auto& file : fs::directory_iterator(dir.path(), error))
      if (file.is_regular_file() && file.path().extension() == ".yaml")
        found.push_back(fs::relative(file.path(), root).generic_string());
  }
  std::sort(found.begin(), found.end());
  return found;
}

std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param.substr(0, info.param.size() - std::string(".yaml").size());
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

class Example : public GeompmRunTest<::testing::TestWithParam<std::string>> {};

TEST(Examples, AreFound) {
  const auto examples = find_examples();
  EXPECT_FALSE(examples.empty()) << "no examples/*/*.yaml under " << source_dir();
  EXPECT_NE(std::find(examples.begin(), examples.end(), "oedometer/oedometer.yaml"),
            examples.end());
}

TEST_P(Example, ChecksAndRuns) {
  const fs::path model = source_dir() / "examples" / GetParam();
  const geompm::spec::Model spec = geompm::read_model(model.string());

  // check: valid, and it runs nothing (no output directory, no file at all in the directory).
  const auto check = geompm({"check", model.string()});
  ASSERT_TRUE(check.exited && check.exit_code == 0) << describe(check);
  EXPECT_TRUE(Contains(check.out, "model is valid"));
  EXPECT_TRUE(fs::is_empty(work())) << "geompm check wrote into its working directory";

  // run
  const fs::path out = work() / "out";
  const auto run = geompm({"run", "-q", "-t", "1", "-o", out.string(), model.string()});
  ASSERT_TRUE(run.exited && run.exit_code == 0) << describe(run);
  EXPECT_TRUE(Contains(run.err, "results in " + out.string())) << describe(run);

  double duration = 0;
  for (const auto& phase : spec.phases) duration += phase.duration;

  // history.csv: time, step, then the model's columns; the initial state and every step.
  const Csv history = read_csv(out / "history.csv");
  ASSERT_TRUE(history.problem.empty()) << history.problem;
  ASSERT_GE(history.header.size(), 2u);
  EXPECT_EQ(history.header[0], "time");
  EXPECT_EQ(history.header[1], "step");
  EXPECT_EQ(history.header.size(), 2 + spec.output.histories.size());
  ASSERT_GE(history.rows.size(), 2u) << "expected the initial state and at least one step";
  for (std::size_t k = 0; k < history.rows.size(); ++k) {
    for (double v : history.rows[k]) {
      EXPECT_TRUE(std::isfinite(v)) << "row " << k;
    }
    EXPECT_EQ(history.rows[k][1], static_cast<double>(k)) << "step numbers count the rows";
    if (k > 0) {
      EXPECT_GT(history.rows[k][0], history.rows[k - 1][0]) << "row " << k;
    }
  }
  EXPECT_EQ(history.rows.front()[0], 0.0);
  EXPECT_NEAR(history.rows.back()[0], duration, 1e-9 * std::max(1.0, duration))
      << "the history should end at the end of the last phase";

  // The same curve as before.
  const fs::path reference = reference_history_path(GetParam());
  if (std::getenv("GEOMPM_WRITE_REFERENCES")) {
    fs::create_directories(reference.parent_path());
    fs::copy_file(out / "history.csv", reference, fs::copy_options::overwrite_existing);
  } else {
    ASSERT_TRUE(fs::is_regular_file(reference))
        << reference << " is missing: run this test with GEOMPM_WRITE_REFERENCES=1 to write it";
    expect_same_history(history, read_csv(reference), 1e-10);
  }

  // ParaView series.
  if (spec.output.vtk_every > 0) {
    expect_series(out / "points.pvd", history.rows.back()[0], true);
    if (spec.output.vtk_grid)
      expect_series(out / "grid.pvd", history.rows.back()[0], false);
    else
      EXPECT_FALSE(fs::exists(out / "grid.pvd")) << "output.vtk.grid is false";
  }

  // Plots.
  for (const auto& plot : spec.output.plots) EXPECT_TRUE(IsPng(out / plot.file)) << plot.file;
}

INSTANTIATE_TEST_SUITE_P(All, Example, ::testing::ValuesIn(find_examples()), test_name);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(Example);

}  // namespace

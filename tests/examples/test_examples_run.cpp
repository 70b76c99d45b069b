// End-to-end: every model under examples/ passes `geompm check` and runs with `geompm run`,
// writing a history, ParaView series whose files exist, and every plot the model lists.
//
// The examples are found by globbing examples/*/*.yaml when the test program starts (test
// discovery runs it before each ctest run), so a new example is covered without editing this file.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "geompm/io/model_reader.hpp"

namespace {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------------
// Running the geompm executable.

struct CommandResult {
  bool exited = false;  // ended by exit() (not by a signal)
  int exit_code = -1;   // WEXITSTATUS when exited
  int signal = 0;       // WTERMSIG when killed by a signal
  std::string out, err;
};

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) {
    if (c == '\'')
      q += "'\\''";
    else
      q.push_back(c);
  }
  q.push_back('\'');
  return q;
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Runs geompm with `args` in the directory `cwd`; stdout and stderr are captured into files of
/// `capture` (outside `cwd`, so that they never look like output of the run).
CommandResult run_geompm(const std::vector<std::string>& args, const fs::path& cwd,
                         const fs::path& capture) {
  const fs::path out = capture / "stdout.txt", err = capture / "stderr.txt";
  // Appended piece by piece: GCC 12 warns (-Wrestrict, wrongly) about "literal" + string.
  std::string command = "cd ";
  for (const std::string& piece :
       {shell_quote(cwd.string()), std::string(" && exec "), shell_quote(GEOMPM_BINARY)})
    command += piece;
  for (const auto& a : args) {
    command += ' ';
    command += shell_quote(a);
  }
  command += " </dev/null >";
  command += shell_quote(out.string());
  command += " 2>";
  command += shell_quote(err.string());
  const int status = std::system(command.c_str());
  CommandResult r;
  if (status != -1 && WIFEXITED(status)) {
    r.exited = true;
    r.exit_code = WEXITSTATUS(status);
  } else if (status != -1 && WIFSIGNALED(status)) {
    r.signal = WTERMSIG(status);
  }
  r.out = read_text(out);
  r.err = read_text(err);
  fs::remove(out);
  fs::remove(err);
  return r;
}

std::string describe(const CommandResult& r) {
  std::ostringstream s;
  if (r.exited)
    s << "exit code " << r.exit_code;
  else
    s << "killed by signal " << r.signal;
  s << "\n--- stdout ---\n" << r.out << "\n--- stderr ---\n" << r.err;
  return s.str();
}

::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << part << "' not found in:\n" << text;
}

// ---------------------------------------------------------------------------------------------
// Reading what a run wrote.

struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  std::string problem;  // empty when the file parsed

  std::ptrdiff_t column(const std::string& name) const {
    const auto it = std::find(header.begin(), header.end(), name);
    return it == header.end() ? -1 : it - header.begin();
  }
};

std::vector<std::string> split(const std::string& line, char separator) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, separator)) cells.push_back(cell);
  if (!line.empty() && line.back() == separator) cells.emplace_back();
  return cells;
}

Csv read_csv(const fs::path& file) {
  Csv csv;
  std::ifstream in(file);
  if (!in) {
    csv.problem = "cannot open " + file.string();
    return csv;
  }
  std::string line;
  if (!std::getline(in, line)) {
    csv.problem = "no header line";
    return csv;
  }
  csv.header = split(line, ',');
  for (int number = 2; std::getline(in, line); ++number) {
    const auto cells = split(line, ',');
    if (cells.size() != csv.header.size()) {
      csv.problem = "line " + std::to_string(number) + " has " + std::to_string(cells.size()) +
                    " values, the header " + std::to_string(csv.header.size());
      return csv;
    }
    std::vector<double> row;
    for (const auto& cell : cells) {
      std::size_t used = 0;
      double value = 0;
      try {
        value = std::stod(cell, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != cell.size()) {
        csv.problem = "line " + std::to_string(number) + ": '" + cell + "' is not a number";
        return csv;
      }
      row.push_back(value);
    }
    csv.rows.push_back(std::move(row));
  }
  return csv;
}

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

class Example : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "_" + info->name();
    for (char& c : name)
      if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    root_ = fs::temp_directory_path() /
            ("geompm_e2e_" + name + "_" + std::to_string(static_cast<long>(getpid())));
    fs::remove_all(root_);
    fs::create_directories(root_ / "work");
    fs::create_directories(root_ / "capture");
  }
  void TearDown() override {
    if (HasFailure())
      std::cerr << "[ kept     ] " << root_ << "\n";
    else
      fs::remove_all(root_);
  }

  fs::path work() const { return root_ / "work"; }
  CommandResult geompm(const std::vector<std::string>& args) const {
    return run_geompm(args, work(), root_ / "capture");
  }

  fs::path root_;
};

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

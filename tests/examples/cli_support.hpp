// Support for the end-to-end tests of tests/examples/: running the geompm executable in a
// scratch directory per test, and reading what a run wrote (history.csv).
//
// Header-only (every function `inline`): all the .cpp files of this directory are linked into
// one test executable. Needs the compile definition GEOMPM_BINARY (the geompm executable).
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace geompm::testing {

// ---------------------------------------------------------------------------------------------
// Running the geompm executable.

struct CommandResult {
  bool exited = false;  // ended by exit() (not by a signal)
  int exit_code = -1;   // WEXITSTATUS when exited
  int signal = 0;       // WTERMSIG when killed by a signal
  std::string out, err;
};

inline std::string shell_quote(const std::string& s) {
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

inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Runs geompm with `args` in the directory `cwd`; stdout and stderr are captured into files of
/// `capture` (outside `cwd`, so that they never look like output of the run). `prefix`: shell
/// commands run first in the same shell (a `ulimit`, a `trap`).
inline CommandResult run_geompm(const std::vector<std::string>& args,
                                const std::filesystem::path& cwd,
                                const std::filesystem::path& capture,
                                const std::string& prefix = "") {
  const std::filesystem::path out = capture / "stdout.txt", err = capture / "stderr.txt";
  // Appended piece by piece: GCC 12 warns (-Wrestrict, wrongly) about "literal" + string.
  std::string command = "cd ";
  for (const std::string& piece : {shell_quote(cwd.string()), std::string(" && "),
                                   prefix.empty() ? std::string() : prefix + "; ",
                                   std::string("exec "), shell_quote(GEOMPM_BINARY)})
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
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

inline std::string describe(const CommandResult& r) {
  std::ostringstream s;
  if (r.exited)
    s << "exit code " << r.exit_code;
  else
    s << "killed by signal " << r.signal;
  s << "\n--- stdout ---\n" << r.out << "\n--- stderr ---\n" << r.err;
  return s.str();
}

inline ::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << part << "' not found in:\n" << text;
}

// ---------------------------------------------------------------------------------------------
// A scratch directory per test: `work()` is where geompm runs (and where the test writes its
// input files), `root_ / "capture"` holds geompm's stdout and stderr. Removed after a test that
// passed, kept (and named on stderr) after one that failed. `Base` is ::testing::Test or
// ::testing::TestWithParam<...>.

template <class Base = ::testing::Test>
class GeompmRunTest : public Base {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "_" + info->name();
    for (char& c : name)
      if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    root_ = std::filesystem::temp_directory_path() /
            ("geompm_e2e_" + name + "_" + std::to_string(static_cast<long>(getpid())));
    std::filesystem::remove_all(root_);
    std::filesystem::create_directories(work());
    std::filesystem::create_directories(root_ / "capture");
  }
  void TearDown() override {
    if (::testing::Test::HasFailure())
      std::cerr << "[ kept     ] " << root_ << "\n";
    else
      std::filesystem::remove_all(root_);
  }

  std::filesystem::path work() const { return root_ / "work"; }

  /// Writes `text` to the file `name` of the working directory (and remembers the name).
  void write(const std::string& name, const std::string& text) {
    std::ofstream(work() / name, std::ios::binary) << text;
    written_.insert(name);
  }

  CommandResult geompm(const std::vector<std::string>& args) const {
    return run_geompm(args, work(), root_ / "capture");
  }

  /// The files in the working directory that the test did not write itself.
  std::set<std::string> unexpected_files() const {
    std::set<std::string> extra;
    for (const auto& entry : std::filesystem::directory_iterator(work())) {
      const std::string name = entry.path().filename().string();
      if (!written_.count(name)) extra.insert(name);
    }
    return extra;
  }

  std::set<std::string> written_;
  std::filesystem::path root_;
};

// ---------------------------------------------------------------------------------------------
// Reading what a run wrote.

struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  std::string problem;  // empty when the file parsed

  /// The index of a column, -1 if there is no such column.
  std::ptrdiff_t index_of(const std::string& name) const {
    const auto it = std::find(header.begin(), header.end(), name);
    return it == header.end() ? -1 : it - header.begin();
  }

  /// The values of a column (empty, with a test failure, if there is no such column).
  std::vector<double> column(const std::string& name) const {
    const std::ptrdiff_t index = index_of(name);
    std::vector<double> values;
    if (index < 0) {
      ADD_FAILURE() << "history.csv has no column '" << name << "'";
      return values;
    }
    for (const auto& row : rows) values.push_back(row[index]);
    return values;
  }
};

/// The cells of `line`; a separator at the end of the line is followed by an empty cell.
inline std::vector<std::string> split(const std::string& line, char separator) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, separator)) cells.push_back(cell);
  if (!line.empty() && line.back() == separator) cells.emplace_back();
  return cells;
}

/// A CSV file of numbers with a header line; `problem` says why the file did not parse.
inline Csv read_csv(const std::filesystem::path& file) {
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

}  // namespace geompm::testing

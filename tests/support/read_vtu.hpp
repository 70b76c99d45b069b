// Reads a .vtu file with meshio (an independent reader, through tests/tools/read_vtu.py, run
// with /usr/bin/python3, which has python3-meshio) for the tests that check what geompm wrote.
#pragma once

#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace geompm::testing {

struct ReadArray {
  std::string dtype;
  int components = 0;
  std::vector<std::vector<double>> rows;
};

struct ReadVtu {
  std::vector<std::vector<double>> points;
  std::map<std::string, std::vector<std::vector<double>>> cells;  // meshio type -> cells
  std::map<std::string, ReadArray> point_data;
  std::map<std::string, ReadArray> cell_data;  // of the first (only) cell block
};

inline std::vector<double> numbers(const std::string& line) {
  std::vector<double> values;
  std::istringstream in(line);
  std::string word;
  while (in >> word) values.push_back(std::stod(word));
  return values;
}

/// Runs tests/tools/read_vtu.py with `arguments`; returns its output, or the exit status as a
/// negative number in `status`.
inline std::string run_reader(const std::string& arguments, int& status) {
  const std::string command = std::string("/usr/bin/python3 '") + GEOMPM_SOURCE_DIR +
                              "/tests/tools/read_vtu.py' " + arguments + " 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) throw std::runtime_error("cannot run " + command);
  std::string output;
  char buffer[4096];
  while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) output.append(buffer, n);
  status = ::pclose(pipe);
  return output;
}

/// Checks the appended raw layout (block sizes tile the data exactly) without meshio; returns
/// "LAYOUT <points> <cells> <arrays>".
inline std::string check_layout(const std::filesystem::path& file) {
  int status = 0;
  const std::string output = run_reader("--check-layout '" + file.string() + "'", status);
  if (status != 0) throw std::runtime_error("layout check failed:\n" + output);
  return output.substr(0, output.find('\n'));
}

/// Reads with meshio and parses its line-based output (see tests/tools/read_vtu.py).
inline ReadVtu read_with_meshio(const std::filesystem::path& file) {
  check_layout(file);
  int status = 0;
  // Appended piece by piece: GCC 12 warns (-Wrestrict, wrongly) about "literal" + string.
  std::string quoted = "'";
  quoted += file.string();
  quoted += '\'';
  const std::string output = run_reader(quoted, status);
  if (status != 0) throw std::runtime_error("read_vtu.py failed:\n" + output);

  ReadVtu vtu;
  std::istringstream in(output);
  std::string line;
  auto read_rows = [&](std::size_t count) {
    std::vector<std::vector<double>> rows;
    for (std::size_t i = 0; i < count; ++i) {
      if (!std::getline(in, line)) throw std::runtime_error("truncated output:\n" + output);
      rows.push_back(numbers(line));
    }
    return rows;
  };
  bool ended = false;
  while (std::getline(in, line)) {
    std::istringstream header(line);
    std::string kind;
    header >> kind;
    if (kind == "POINTS") {
      std::size_t count;
      header >> count;
      vtu.points = read_rows(count);
    } else if (kind == "CELLS") {
      std::string type;
      std::size_t count;
      header >> type >> count;
      vtu.cells[type] = read_rows(count);
    } else if (kind == "POINT_DATA" || kind == "CELL_DATA") {
      int block = 0;
      if (kind == "CELL_DATA") header >> block;
      ReadArray array;
      std::size_t count;
      std::string name;
      header >> array.dtype >> array.components >> count >> std::ws;
      std::getline(header, name);
      array.rows = read_rows(count);
      if (kind == "POINT_DATA")
        vtu.point_data[name] = array;
      else if (block == 0)
        vtu.cell_data[name] = array;
    } else if (kind == "END") {
      ended = true;
    } else {
      throw std::runtime_error("unexpected line '" + line + "' in:\n" + output);
    }
  }
  if (!ended) throw std::runtime_error("no END in:\n" + output);
  return vtu;
}

}  // namespace geompm::testing

#include "geompm/io/history_writer.hpp"

#include <fmt/format.h>

#include <sstream>

#include "geompm/core/error.hpp"

namespace geompm {

HistoryWriter::HistoryWriter(const std::filesystem::path& file,
                             const std::vector<std::string>& columns)
    : file_(file), out_(file, std::ios::trunc), columns_(columns.size()) {
  if (!out_) throw RunError("cannot write history file " + file.string());
  for (std::size_t i = 0; i < columns.size(); ++i) out_ << (i ? "," : "") << columns[i];
  out_ << '\n' << std::flush;
}

void HistoryWriter::append(const std::vector<double>& values) {
  for (std::size_t i = 0; i < values.size() && i < columns_; ++i)
    out_ << (i ? "," : "") << fmt::format("{:.10g}", values[i]);
  out_ << '\n' << std::flush;  // a stopped run keeps every finished step
}

std::size_t CsvTable::column(const std::string& name, const std::string& file) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return i;
  std::string known;
  for (const auto& c : columns) known += (known.empty() ? "" : ", ") + c;
  throw InputError(file + ": no column '" + name + "'; the columns are: " + known);
}

CsvTable read_csv(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string() + ": cannot open the file");
  CsvTable table;
  std::string line;
  if (!std::getline(in, line)) throw InputError(file.string() + ": empty file, expected a header");
  {
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) table.columns.push_back(cell);
  }
  int line_number = 1;
  while (std::getline(in, line)) {
    ++line_number;
    if (line.empty()) continue;
    std::vector<double> row;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) {
      try {
        std::size_t used = 0;
        row.push_back(std::stod(cell, &used));
      } catch (const std::exception&) {
        throw InputError(
            fmt::format("{}:{}: '{}' is not a number", file.string(), line_number, cell));
      }
    }
    if (row.size() != table.columns.size())
      throw InputError(fmt::format("{}:{}: {} values, expected {} (one per column)", file.string(),
                                   line_number, row.size(), table.columns.size()));
    table.rows.push_back(std::move(row));
  }
  return table;
}

}  // namespace geompm

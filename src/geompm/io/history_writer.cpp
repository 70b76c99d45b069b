#include "geompm/io/history_writer.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <sstream>

#include "geompm/core/error.hpp"
#include "geompm/io/yaml_access.hpp"  // did_you_mean

namespace geompm {

HistoryWriter::HistoryWriter(const std::filesystem::path& file,
                             const std::vector<std::string>& columns)
    : file_(file), out_(file, std::ios::trunc | std::ios::binary), columns_(columns.size()) {
  if (!out_) throw RunError("cannot write history file " + file.string());
  std::string header;
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (i) header += ',';
    header += columns[i];
  }
  header += '\n';
  write(header);
}

void HistoryWriter::check_resumable(const std::filesystem::path& file, std::uintmax_t size) {
  std::error_code error;
  const std::uintmax_t found = std::filesystem::file_size(file, error);
  if (error || found < size)
    throw InputError(fmt::format(
        "{}: {} at the checkpoint it had {} bytes; cannot resume without the history written "
        "up to the checkpoint (run again without --resume)",
        file.string(), error ? "missing;" : fmt::format("{} bytes, but", found), size));
}

HistoryWriter::HistoryWriter(const std::filesystem::path& file,
                             const std::vector<std::string>& columns, std::uintmax_t size)
    : file_(file), columns_(columns.size()), size_(size) {
  check_resumable(file, size);
  // What the stopped run wrote after its checkpoint is written again by the resumed run.
  std::filesystem::resize_file(file, size);
  out_.open(file, std::ios::app | std::ios::binary);
  if (!out_) throw RunError("cannot write history file " + file.string());
}

void HistoryWriter::append(const std::vector<double>& values) {
  std::string row;
  for (std::size_t i = 0; i < values.size() && i < columns_; ++i) {
    if (i) row += ',';  // (not "," + text: GCC 12 warns, wrongly, -Wrestrict)
    row += fmt::format("{:.10g}", values[i]);
  }
  row += '\n';
  write(row);  // flushed: a stopped run keeps every finished step
}

// A full disk or a file size limit must stop the run (RunError, exit 3), not let it finish with
// a history cut mid-line: the stream is checked after every flush, and a row written in part is
// cut off again, so that the file ends with the last whole row.
void HistoryWriter::write(const std::string& text) {
  errno = 0;
  out_ << text << std::flush;
  if (out_) {
    size_ += text.size();
    return;
  }
  const int reason = errno;
  out_.close();
  std::error_code ignored;
  std::filesystem::resize_file(file_, size_, ignored);
  throw RunError(fmt::format(
      "cannot write {}: {}; the file holds every row written before (is the disk full?)",
      file_.string(), reason ? std::strerror(reason) : "the write failed"));
}

std::size_t CsvTable::column(const std::string& name, const std::string& file) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return i;
  std::string known;
  for (const auto& c : columns) known += (known.empty() ? "" : ", ") + c;
  throw InputError(file + ": no column '" + name + "'" + yaml::did_you_mean(name, columns) +
                   "; the columns are: " + known);
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

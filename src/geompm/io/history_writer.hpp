// CSV histories: one row per converged step, flushed at once so that a stopped run keeps every
// finished step.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace geompm {

class HistoryWriter {
 public:
  /// Creates (truncates) `file` and writes the header line.
  HistoryWriter(const std::filesystem::path& file, const std::vector<std::string>& columns);
  /// Appends one row (as many values as columns; full precision) and flushes.
  void append(const std::vector<double>& values);
  const std::filesystem::path& path() const { return file_; }

 private:
  std::filesystem::path file_;
  std::ofstream out_;
  std::size_t columns_;
};

/// A CSV table read back (header + numeric rows); throws InputError naming the file and line.
struct CsvTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  /// Index of a column by name; throws InputError listing the columns if absent.
  std::size_t column(const std::string& name, const std::string& file) const;
};
CsvTable read_csv(const std::filesystem::path& file);

}  // namespace geompm

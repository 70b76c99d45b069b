// CSV histories: one row per converged step, flushed at once so that a stopped run keeps every
// finished step. A resumed run (checkpoints) cuts the file back to its length at the checkpoint
// and appends from there, as if it had never stopped.
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace geompm {

class HistoryWriter {
 public:
  /// Creates (truncates) `file` and writes the header line.
  HistoryWriter(const std::filesystem::path& file, const std::vector<std::string>& columns);
  /// Goes on with the existing `file` cut back to its first `size` bytes (its size() at a
  /// checkpoint, header included). Throws InputError if the file is missing or shorter.
  HistoryWriter(const std::filesystem::path& file, const std::vector<std::string>& columns,
                std::uintmax_t size);
  /// Throws the InputError the resuming constructor would: `file` missing or under `size` bytes.
  static void check_resumable(const std::filesystem::path& file, std::uintmax_t size);
  /// Appends one row (as many values as columns; full precision) and flushes. Throws RunError
  /// if the row cannot be written (the file is cut back to its last whole row).
  void append(const std::vector<double>& values);
  const std::filesystem::path& path() const { return file_; }
  /// Bytes in the file so far.
  std::uintmax_t size() const { return size_; }

 private:
  void write(const std::string& text);

  std::filesystem::path file_;
  std::ofstream out_;
  std::size_t columns_;
  std::uintmax_t size_ = 0;
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

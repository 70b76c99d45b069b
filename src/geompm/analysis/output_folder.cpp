#include "geompm/analysis/output_folder.hpp"

#include <algorithm>
#include <array>
#include <string>

namespace geompm {

namespace {

namespace fs = std::filesystem;

bool written_by_a_run(const fs::path& file, bool in_vtk_folder) {
  const std::string name = file.filename().string(), ext = file.extension().string();
  if (in_vtk_folder) return ext == ".vtu" || ext == ".vtp" || ext == ".pvtu";
  static const std::array<const char*, 5> names = {"history.csv", "newton.csv", "summary.json",
                                                   "checkpoint.bin", "checkpoint.bin.tmp"};
  return ext == ".vtu" || ext == ".vtp" || ext == ".pvd" || ext == ".png" ||
         std::find(names.begin(), names.end(), name) != names.end();
}

void remove_files(const fs::path& dir, bool in_vtk_folder, std::vector<fs::path>& removed) {
  std::vector<fs::path> doomed;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.is_regular_file() && written_by_a_run(entry.path(), in_vtk_folder))
      doomed.push_back(entry.path());
  std::sort(doomed.begin(), doomed.end());
  for (const fs::path& file : doomed)
    if (fs::remove(file)) removed.push_back(file);
}

}  // namespace

std::vector<fs::path> remove_previous_run(const fs::path& dir) {
  std::vector<fs::path> removed;
  if (!fs::is_directory(dir)) return removed;
  const bool earlier_run = fs::exists(dir / "history.csv") || fs::exists(dir / "summary.json") ||
                           fs::exists(dir / "points.pvd") || fs::exists(dir / "checkpoint.bin");
  if (!earlier_run) return removed;
  remove_files(dir, false, removed);
  if (fs::is_directory(dir / "vtk")) {
    remove_files(dir / "vtk", true, removed);
    std::error_code ignored;
    fs::remove(dir / "vtk", ignored);  // only if empty; the run creates it again
  }
  return removed;
}

}  // namespace geompm

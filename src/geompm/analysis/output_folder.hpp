// A new run in an output folder an earlier run wrote: the earlier run's files go first, so that
// the folder never mixes two runs (a longer earlier run would otherwise leave its later VTU
// files, plots of curves no longer asked for, its checkpoint and summary).
#pragma once

#include <filesystem>
#include <vector>

namespace geompm {

/// Removes from `dir` the files a geompm run writes: *.vtu, *.vtp, *.pvd, *.png, history.csv,
/// newton.csv, summary.json, checkpoint.bin (and its temporary), and the *.vtu / *.vtp / *.pvtu
/// of `dir`/vtk. Nothing else: other files stay, and a folder that holds no sign of a geompm run
/// (history.csv, summary.json, points.pvd or checkpoint.bin) is left as it is. Returns the
/// files removed.
std::vector<std::filesystem::path> remove_previous_run(const std::filesystem::path& dir);

}  // namespace geompm

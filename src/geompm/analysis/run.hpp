// The analysis driver: phases in sequence, each stepping through its duration with adaptive time
// steps (cut back on failure and retried from the last converged state, grown after easy steps),
// writing ParaView files, the history CSV and plots as it goes, so that a run that stops keeps
// every finished step.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <vector>

#include "geompm/analysis/model.hpp"

namespace geompm {

struct RunOptions {
  std::filesystem::path output_dir;
  bool progress = true;         // live progress line on the log stream
  std::ostream* log = nullptr;  // where progress and the summary go (nullptr: nowhere)
};

struct RunSummary {
  double wall_seconds = 0.0;
  int steps = 0;
  int iterations = 0;
  int cutbacks = 0;
  int max_iterations_in_a_step = 0;
  std::vector<std::vector<double>> residual_histories;  // per converged step
  std::filesystem::path history_file;
};

/// Runs every phase. Throws RunError when a step cannot converge at the minimum time step or a
/// point leaves the mesh under the "stop" policy; everything finished before is on disk.
RunSummary run_analysis(Model& model, const RunOptions& options);

}  // namespace geompm

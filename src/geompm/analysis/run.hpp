// The analysis driver: phases in sequence, each stepping through its duration with adaptive time
// steps (cut back on failure and retried from the last converged state, grown or shrunk by the
// Newton iterations they took), writing ParaView files, the history CSV and plots as it goes, so
// that a run that stops keeps every finished step, and checkpoints from which a killed run resumes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <vector>

#include "geompm/analysis/model.hpp"
#include "geompm/analysis/run_summary.hpp"
#include "geompm/core/communicator.hpp"

namespace geompm {

struct RunOptions {
  std::filesystem::path output_dir;
  bool progress = true;         // live progress line on the log stream
  std::ostream* log = nullptr;  // where progress and the summary go (nullptr: nowhere)
  /// Continue the run in output_dir from its checkpoint (geompm run --resume).
  bool resume = false;
  /// Converged steps between checkpoints, instead of output.checkpoint.every_steps (0: not by
  /// steps; geompm run --checkpoint-every).
  std::optional<int> checkpoint_every;
  /// FNV-1a 64 of the model file's text: recorded in checkpoints and summary.json; a checkpoint
  /// of another model is refused.
  std::uint64_t model_hash = 0;
  /// The processes of a distributed run (mpirun -np N; docs/architecture.md, "Distributed
  /// runs"); null for a run on one process. Only process 0 writes files.
  const Communicator* communicator = nullptr;
};

/// Runs every phase (or, with options.resume, what is left of them after the checkpoint). Throws
/// RunError when a step cannot converge at the minimum time step or a point leaves the mesh
/// under the "stop" policy; everything finished before is on disk, and summary.json says why
/// the run stopped. Throws InputError if a run to resume has no usable checkpoint.
RunSummary run_analysis(Model& model, const RunOptions& options);

}  // namespace geompm

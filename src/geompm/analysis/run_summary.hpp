// What a run did, counted as it goes and written at its end (and when it stops) to summary.json,
// so that scripts and tests read one small file instead of parsing the log. The counters are part
// of the saved state of a run: a resumed run goes on counting from its checkpoint.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace geompm {

class ByteWriter;
class ByteReader;

struct PhaseSummary {
  std::string name;
  /// "not started", "running", "finished" or "stopped" (the run stopped in this phase).
  std::string status = "not started";
  int steps = 0;       // converged steps
  int cutbacks = 0;    // steps that did not converge and were retried with a smaller one
  int iterations = 0;  // Newton iterations of the converged steps
  int max_iterations_in_a_step = 0;
  double wall_seconds = 0.0;
  /// The linear solver's work in the converged steps (NewtonResult): iterations (Krylov, or 1 a
  /// solve for a direct solver) and wall seconds in setup and solves. Not in checkpoints: a
  /// resumed run counts them from its resumption.
  std::int64_t linear_iterations = 0;
  double linear_seconds = 0.0;
};

/// A material point that left the mesh and was removed (numerics.lost_points: remove): its id,
/// the time, and where it would have gone.
struct LostPoint {
  std::int32_t id = 0;
  double time = 0.0;
  std::array<double, 3> position = {0.0, 0.0, 0.0};
};

/// The most lost points summary.json lists one by one (the count and mass cover them all).
inline constexpr std::size_t max_listed_lost_points = 1000;

struct RunSummary {
  double wall_seconds = 0.0;
  int steps = 0;
  int iterations = 0;
  int cutbacks = 0;
  int max_iterations_in_a_step = 0;
  std::int64_t linear_iterations = 0;  // as PhaseSummary's, for the whole run
  double linear_seconds = 0.0;
  std::string linear_solver;  // numerics.linear_solver (or --linear-solver)
  std::vector<std::vector<double>> residual_histories;  // per converged step
  std::filesystem::path history_file;

  std::vector<PhaseSummary> phases;  // one per phase of the model
  /// "running", then "finished" or "stopped"; `reason` says why a run stopped.
  std::string status = "running";
  std::string reason;
  double time = 0.0;                  // analysis time reached
  std::vector<int> resumed_at_steps;  // the step of each checkpoint the run resumed from
  std::string model_file;
  std::uint64_t model_hash = 0;  // FNV-1a 64 of the model file's text
  double lost_mass = 0.0;
  std::int64_t lost_points = 0;
  std::vector<LostPoint> lost;  // the first max_listed_lost_points of them
  /// history.csv's columns and its last row, as the file has them.
  std::vector<std::string> history_columns;
  std::vector<double> history_last;

  /// The counters (not the run's identity, nor its last history row), for a checkpoint.
  void save(ByteWriter& out) const;
  void load(ByteReader& in);
};

/// Writes `summary` as JSON to `file`, atomically (a temporary file renamed over it).
void write_summary_json(const std::filesystem::path& file, const RunSummary& summary);

}  // namespace geompm

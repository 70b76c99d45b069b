// A run of the analysis as one object: the model, the step solver, where the run is (phase, time,
// step), the phase's time-step controller, the output files and the summary. run() steps through
// the phases; save() and load() write and read everything a run needs to go on, so that a run
// killed at any moment resumes from its last checkpoint and ends exactly as if it had never
// stopped (simulation_state.cpp, docs/checkpoint-format.md).
#pragma once

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>

#include "geompm/analysis/phase_context.hpp"
#include "geompm/analysis/point_output.hpp"
#include "geompm/analysis/progress_line.hpp"
#include "geompm/analysis/run.hpp"
#include "geompm/analysis/run_output.hpp"
#include "geompm/analysis/step.hpp"
#include "geompm/solver/step_controller.hpp"

namespace geompm {

/// The checkpoint of an output directory.
std::filesystem::path checkpoint_file(const std::filesystem::path& output_dir);

/// A phase's time stepping as the step controller takes it.
StepControlSettings step_control_settings(const spec::TimeStepping& time_step);

class Simulation {
 public:
  /// Writes nothing yet: start() or resume() does.
  Simulation(Model& model, const RunOptions& options);
  ~Simulation();

  /// A new run: clears what an earlier run left in the output directory (checkpoint, summary)
  /// and writes the initial state.
  void start();
  /// Goes on from the output directory's checkpoint. Throws InputError (naming the file and
  /// what is wrong) if there is none or it cannot be used; nothing is changed then.
  void resume();
  /// Runs the remaining steps of every phase. Throws RunError when a step cannot converge at
  /// the smallest time step or a point leaves the mesh under the "stop" policy.
  void run();
  /// Ends the run: plots, summary.json. `reason` is empty for a run that finished.
  void finish(const std::string& stop_reason = "");

  /// Everything the run needs to go on, to `file` (atomically) / from it. save() is collective
  /// in a distributed run (process 0 writes the file, every process's points pass through it a
  /// slice at a time); load() reads this process's own points.
  void save(const std::filesystem::path& file) const;
  void load(const std::filesystem::path& file);

  const RunSummary& summary() const { return summary_; }

 private:
  /// Process 0's part of start(), resume() and finish(): the output directory and files.
  /// The output directory made ready and the initial history row written, the points' part from
  /// `point_sums` (HistoryRecorder::point_sums).
  void start_output(const std::vector<double>& point_sums);
  void resume_output(const std::filesystem::path& checkpoint);
  void finish_output(const std::string& stop_reason);
  void begin_phase();
  void run_phase();
  void cut_back(const StepResult& step, double t, double dt);
  void check_lost_points(const StepResult& step, double t);
  void report_removed_points(const StepResult& step, double t);
  void check_motions_followed();
  void accept(const StepResult& step, double dt);
  void checkpoint_if_due(bool phase_done);
  /// Writes the checkpoint (collective).
  void write_checkpoint();
  [[noreturn]] void stop_on_interrupt();
  void update_clocks();
  [[noreturn]] void stop(const std::string& message);
  /// Distributed: the cells `cell_part` gives this process are its own; it keeps their points
  /// (and the FEM region's Gauss points) and works on them.
  void distribute_points(std::vector<int> cell_part);
  /// The points' ParaView files of the step the run is at, each process its own (collective).
  void write_points();
  /// A stopped run: the points' and structures' ParaView files of the last converged step, if
  /// that step did not write them (collective).
  void write_last_state();
  /// Whether this process writes files (process 0).
  bool writes_files() const { return processes_.rank() == 0; }

  Model& model_;
  RunOptions options_;
  /// The cut of a resumed run, made while its checkpoint is read (load).
  std::vector<int> resumed_cell_part_;
  const Communicator& processes_;
  std::unique_ptr<LinearSolver> solver_;
  StepSolver stepper_;
  /// The histories' sums over the points, which every process adds up for its own (the rows are
  /// output_'s, on process 0).
  HistoryRecorder histories_;
  ProgressLine progress_;
  std::unique_ptr<OutputWriter> output_;       // process 0's
  std::unique_ptr<PointOutput> point_output_;  // every process's, once the points are shared out

  // Where the run is: the phase (its context and time-step controller while it runs), the
  // analysis time and the converged steps so far.
  std::size_t phase_index_ = 0;
  std::unique_ptr<PhaseContext> phase_;
  std::unique_ptr<StepController> control_;
  double time_ = 0.0;
  int step_number_ = 0;
  double done_duration_ = 0.0;  // of all phases, for the ETA
  RunSummary summary_;

  // Wall clocks of this process: since it started stepping, since the phase (or resume) began,
  // since the last checkpoint; the times counted before (saved in a checkpoint) are added.
  using Clock = std::chrono::steady_clock;
  Clock::time_point started_, phase_started_, last_checkpoint_;
  double wall_before_ = 0.0, phase_wall_before_ = 0.0, done_duration_before_ = 0.0;
  mutable int checkpoints_ = 0;  // written by this process (counted by save())
  int kill_in_checkpoint_ = 0;   // test only (GEOMPM_TEST_KILL_IN_CHECKPOINT)
};

}  // namespace geompm

#include "geompm/analysis/simulation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include "geompm/analysis/distribution.hpp"
#include "geompm/analysis/motion_check.hpp"
#include "geompm/analysis/output_folder.hpp"
#include "geompm/core/agreement.hpp"
#include "geompm/core/error.hpp"
#include "geompm/core/interrupt.hpp"
#include "geompm/io/checkpoint_file.hpp"
#include "geompm/io/output_directory.hpp"
#include "geompm/points/point_exchange.hpp"
#include "geompm/solver/petsc_distributed_solver.hpp"

namespace geompm {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Test only: GEOMPM_TEST_KILL_IN_CHECKPOINT=N kills the process half-way through writing its
// N-th checkpoint (tests/examples/test_checkpoints.cpp), as a crash in the middle would.
int kill_in_checkpoint() {
  const char* value = std::getenv("GEOMPM_TEST_KILL_IN_CHECKPOINT");
  return value ? std::atoi(value) : 0;
}

// The serial solver the model names, or in a distributed run its distributed stand-in (after
// the model is checked for what a distributed run does not handle yet).
std::unique_ptr<LinearSolver> make_linear_solver(const Model& model,
                                                 const Communicator& processes) {
  const LinearSolverOptions options{model.spec.numerics.petsc_options,
                                    model.spec.numerics.direct_limit};
  if (!processes.distributed())
    return create_linear_solver(model.spec.numerics.linear_solver, options);
  check_distributable(model, processes.size());
  return create_petsc_distributed_solver(model.spec.numerics.linear_solver, options);
}

}  // namespace

std::filesystem::path checkpoint_file(const std::filesystem::path& output_dir) {
  return output_dir / "checkpoint.bin";
}

StepControlSettings step_control_settings(const spec::TimeStepping& ts) {
  return {ts.initial, ts.min, ts.max, ts.growth, ts.cutback, ts.target_iterations};
}

Simulation::Simulation(Model& model, const RunOptions& options)
    : model_(model),
      options_(options),
      processes_(options.communicator ? *options.communicator : serial_communicator()),
      solver_(make_linear_solver(model, processes_)),
      stepper_(model, *solver_, processes_),
      histories_(model),
      progress_(options.log, options.progress),
      started_(Clock::now()),
      phase_started_(started_),
      last_checkpoint_(started_),
      kill_in_checkpoint_(kill_in_checkpoint()) {
  if (processes_.distributed() && model.cell_part.size() != std::size_t(model.mesh.num_cells()))
    throw std::logic_error("a distributed run needs the model built for its processes");
  summary_.model_file = model.spec.file;
  summary_.linear_solver = model.spec.numerics.linear_solver;
  summary_.model_hash = options.model_hash;
  for (const auto& phase : model.spec.phases) summary_.phases.push_back({.name = phase.name});
}

Simulation::~Simulation() = default;

void Simulation::distribute_points(std::vector<int> cell_part) {
  if (!processes_.distributed()) return;
  model_.cell_part = cell_part;  // a resumed run's cut is made anew
  keep_own_points(model_.points, cell_part, processes_.rank());
  if (model_.fem) model_.fem->keep_own(cell_part, processes_.rank());
  stepper_.distribute(processes_, std::move(cell_part));
}

void Simulation::start() {
  // Each process holds its own cells' points from the start (build_model). Process 0 writes the
  // initial history row; the others learn whether it could (an output directory that cannot be
  // used).
  const std::vector<double> sums = histories_.point_sums(model_, processes_);
  together(processes_, [&] {
    if (writes_files()) start_output(sums);
  });
  distribute_points(model_.cell_part);
  point_output_ = std::make_unique<PointOutput>(model_, options_.output_dir, processes_);
  if (model_.spec.output.vtk_every > 0) write_points();
}

void Simulation::write_points() {
  const PointOutput::Files files = point_output_->write(step_number_);
  together(processes_, [&] {
    if (output_) output_->list_points(time_, files.points, files.gauss);
  });
}

void Simulation::start_output(const std::vector<double>& point_sums) {
  // What an earlier run in the same directory left must not be mistaken for this run's: its
  // checkpoint (a later --resume would go back to it), its summary, ParaView files, plots and
  // history, a half-written checkpoint, the temporaries of files being written when it was killed.
  prepare_output_directory(options_.output_dir);
  remove_stale_temporaries(options_.output_dir);
  remove_stale_temporaries(options_.output_dir / "vtk");
  const auto removed = remove_previous_run(options_.output_dir);
  if (options_.log && !removed.empty())
    *options_.log << fmt::format("removed {} files of an earlier run from {}\n", removed.size(),
                                 options_.output_dir.string());
  const std::filesystem::path checkpoint = checkpoint_file(options_.output_dir);
  std::filesystem::remove(checkpoint);
  std::filesystem::remove(checkpoint_temporary(checkpoint));
  std::filesystem::remove(options_.output_dir / "summary.json");
  output_ = std::make_unique<OutputWriter>(model_, options_.output_dir);
  output_->initial(point_sums);
  summary_.history_file = output_->history_file();
}

void Simulation::resume() {
  const std::filesystem::path checkpoint = checkpoint_file(options_.output_dir);
  together(processes_, [&] {
    if (!std::filesystem::is_regular_file(checkpoint))
      throw InputError(fmt::format(
          "{}: no checkpoint to resume from (a run writes one every "
          "output.checkpoint.every_steps steps or every_minutes minutes, and at the end of each "
          "phase); run without --resume to start again",
          checkpoint.string()));
    load(checkpoint);
  });
  // Each process has read its own cells' points, cut anew (load).
  distribute_points(std::move(resumed_cell_part_));
  point_output_ = std::make_unique<PointOutput>(model_, options_.output_dir, processes_);
  together(processes_, [&] {
    if (writes_files()) resume_output(checkpoint);
  });
}

void Simulation::resume_output(const std::filesystem::path& checkpoint) {
  // A half-written checkpoint of the run that stopped is of no use (the one just read is), nor
  // are the temporaries of the files it was writing when it was killed.
  std::filesystem::remove(checkpoint_temporary(checkpoint));
  remove_stale_temporaries(options_.output_dir);
  remove_stale_temporaries(options_.output_dir / "vtk");
  std::filesystem::remove(options_.output_dir / "summary.json");
  summary_.resumed_at_steps.push_back(step_number_);
  summary_.history_file = output_->history_file();
  if (options_.log)
    *options_.log << fmt::format("resuming from {}: phase '{}', step {}, time {:g}\n",
                                 checkpoint.string(), summary_.phases[phase_index_].name,
                                 step_number_, time_);
}

void Simulation::run() {
  for (; phase_index_ < model_.spec.phases.size(); ++phase_index_) {
    if (!phase_) begin_phase();  // (a resumed run is in the middle of one)
    run_phase();
    check_motions_followed();
    summary_.phases[phase_index_].status = "finished";
    phase_.reset();
    control_.reset();
  }
}

void Simulation::begin_phase() {
  const spec::Phase& spec = model_.spec.phases[phase_index_];
  phase_ = std::make_unique<PhaseContext>(model_, spec);
  control_ = std::make_unique<StepController>(step_control_settings(spec.time_step), spec.duration);
  stepper_.start_phase();
  for (auto& d : model_.points.phase_displacement) d.setZero();
  for (auto& structure : model_.structures) structure->start_phase();
  summary_.phases[phase_index_].status = "running";
  phase_started_ = Clock::now();
  phase_wall_before_ = 0.0;
}

// The step loop of a phase: try the controller's step; retry a failed one smaller; stop the run
// when that cannot go on; write and count a converged one.
void Simulation::run_phase() {
  while (!control_->finished()) {
    // A signal reaches the processes at different moments: they stop together, when any has it.
    if (processes_.distributed() ? !processes_.all(!interrupt_requested()) : interrupt_requested())
      stop_on_interrupt();
    inject_test_fault(processes_, "between_steps");
    const double t = control_->time(), dt = control_->trial_step();
    const auto advance = [&](bool last_resort) {
      StepResult step = stepper_.advance(*phase_, t, dt, last_resort);
      together(processes_, [&] {
        if (output_) output_->newton_log(step_number_ + 1, time_ + dt, dt, step);
      });
      return step;
    };
    StepResult step = advance(false);
    // At the smallest allowed step, before the run stops: once more with backtracking.
    if (!step.converged && !control_->can_cut_back(dt) &&
        phase_->spec->newton.last_resort_backtracking())
      step = advance(true);
    if (!step.converged) {
      cut_back(step, t, dt);
      continue;
    }
    check_lost_points(step, t + dt);
    accept(step, dt);
  }
}

void Simulation::cut_back(const StepResult& step, double t, double dt) {
  const spec::Phase& spec = *phase_->spec;
  ++summary_.cutbacks;
  ++summary_.phases[phase_index_].cutbacks;
  update_clocks();
  if (!control_->failed(dt))
    stop(
        fmt::format("phase '{}': the step at time {:g} did not converge with the smallest "
                    "allowed time step ({:g}): {}. Results up to time {:g} are in {}",
                    spec.name, t, dt, step.newton.failure, time_, options_.output_dir.string()));
  progress_.update(
      fmt::format("phase {} | step {} | t {:.4g} | cut back to dt {:.3g}: {}", spec.name,
                  step_number_ + 1, t, control_->next_step(), step.newton.failure),
      true);
}

void Simulation::check_lost_points(const StepResult& step, double t) {
  const spec::Phase& spec = *phase_->spec;
  // A model with an FEM region may have no material points at all (every cell FEM).
  if (processes_.sum(model_.points.size()) == 0 && !model_.fem)
    stop(
        fmt::format("phase '{}', time {:g}: every material point has left the mesh; results "
                    "up to time {:g} are in {}",
                    spec.name, t, time_, options_.output_dir.string()));
  if (step.lost.empty()) return;
  if (model_.spec.numerics.lost_points == spec::LostPointPolicy::Remove) {
    report_removed_points(step, t);
    return;
  }
  std::string where;
  for (std::size_t k = 0; k < std::min<std::size_t>(step.lost.size(), 5); ++k)
    where += fmt::format("\n  point {} would move to ({:.6g}, {:.6g}, {:.6g})", step.lost[k].first,
                         step.lost[k].second.x(), step.lost[k].second.y(), step.lost[k].second.z());
  stop(
      fmt::format("phase '{}', time {:g}: {} material point(s) left the mesh{} (policy "
                  "numerics.lost_points = stop):{}{}\nEnlarge the mesh{} or set "
                  "lost_points: remove. Results up to time {:g} are in {}",
                  spec.name, t, step.lost.size(), model_.fem ? " or entered an FEM cell" : "",
                  where, step.lost.size() > 5 ? "\n  ..." : "",
                  model_.fem ? " (or the MPM region)" : "", time_, options_.output_dir.string()));
}

// Which points were removed, and where they went: on the log (the first few of a step) and in
// summary.json (the first max_listed_lost_points of the run).
void Simulation::report_removed_points(const StepResult& step, double t) {
  std::string where;
  for (std::size_t k = 0; k < step.lost.size(); ++k) {
    const auto& [id, x] = step.lost[k];
    if (summary_.lost.size() < max_listed_lost_points)
      summary_.lost.push_back({static_cast<std::int32_t>(id), t, {x.x(), x.y(), x.z()}});
    if (k < 5)
      where += fmt::format("\n  point {} would move to ({:.6g}, {:.6g}, {:.6g})", id, x.x(), x.y(),
                           x.z());
  }
  if (!options_.log) return;
  progress_.finish();
  *options_.log << fmt::format(
      "phase '{}', time {:g}: {} material point(s) left the mesh and were removed "
      "(numerics.lost_points = remove):{}{}\n",
      phase_->spec->name, t, step.lost.size(), where, step.lost.size() > 5 ? "\n  ..." : "");
}

void Simulation::accept(const StepResult& step, double dt) {
  const spec::Phase& spec = *phase_->spec;
  const int iterations = step.newton.iterations;
  control_->converged(dt, iterations);
  time_ += dt;
  done_duration_ += dt;
  ++step_number_;
  PhaseSummary& phase = summary_.phases[phase_index_];
  ++summary_.steps;
  ++phase.steps;
  summary_.iterations += iterations;
  phase.iterations += iterations;
  summary_.max_iterations_in_a_step = std::max(summary_.max_iterations_in_a_step, iterations);
  phase.max_iterations_in_a_step = std::max(phase.max_iterations_in_a_step, iterations);
  summary_.residual_histories.push_back(step.newton.residuals);
  summary_.linear_iterations += step.newton.linear_iterations;
  phase.linear_iterations += step.newton.linear_iterations;
  summary_.linear_seconds += step.newton.linear_seconds;
  phase.linear_seconds += step.newton.linear_seconds;

  const bool phase_done = control_->finished();
  const int vtk_every = model_.spec.output.vtk_every;
  const bool vtk = vtk_every > 0 && (step_number_ % vtk_every == 0 || phase_done);
  if (vtk_every > 0) point_output_->after_step();
  if (vtk) write_points();
  // The histories' sums over the points of every process (reduced, not gathered).
  const std::vector<double> sums = histories_.point_sums(model_, processes_);
  together(processes_, [&] {
    if (output_)
      output_->step(stepper_.grid(), step, *phase_, control_->time(), time_, step_number_, dt, vtk,
                    sums);
  });
  update_clocks();

  double total_duration = 0.0;
  for (const auto& p : model_.spec.phases) total_duration += p.duration;
  const double done_here = done_duration_ - done_duration_before_;
  const double eta =
      done_here > 0 ? seconds_since(started_) * (total_duration - done_duration_) / done_here : 0;
  // With an FEM region, the MPM cells' shape after the relaxation (docs/theory.md §19.3).
  const std::string mesh = step.mesh_quality ? fmt::format(" | MPM mesh {:.1f} deg, aspect {:.1f}",
                                                           step.mesh_quality->smallest_angle,
                                                           step.mesh_quality->largest_aspect_ratio)
                                             : std::string();
  progress_.update(
      fmt::format("phase {} | step {} | t {:.4g}/{:.4g} | dt {:.3g} | it {} | lin {} in {:.2f} s | "
                  "r {:.2e}{} | ETA {}",
                  spec.name, step_number_, control_->time(), spec.duration, dt, iterations,
                  step.newton.linear_iterations, step.newton.linear_seconds,
                  step.newton.residuals.back(), mesh, format_duration(eta)));
  checkpoint_if_due(phase_done);
}

// After the step's output, so that the files a checkpoint records hold that step.
void Simulation::checkpoint_if_due(bool phase_done) {
  const spec::Checkpoint& schedule = model_.spec.output.checkpoint;
  const int every_steps = options_.checkpoint_every.value_or(schedule.every_steps);
  const double every_minutes = schedule.every_minutes;
  if (every_steps <= 0 && every_minutes <= 0) return;  // checkpoints are off
  const bool timed = every_minutes > 0 && seconds_since(last_checkpoint_) >= 60 * every_minutes;
  // Each process has its own clock: rank 0's decides, or the processes would part at the gather.
  const bool timed_on_rank0 = processes_.distributed()
                                  ? processes_.sum(processes_.rank() == 0 && timed ? 1.0 : 0.0) > 0
                                  : timed;
  const bool due =
      phase_done || (every_steps > 0 && step_number_ % every_steps == 0) || timed_on_rank0;
  if (!due) return;
  write_checkpoint();
  last_checkpoint_ = Clock::now();
}

// In the serial format, whatever the number of processes (save()).
void Simulation::write_checkpoint() { save(checkpoint_file(options_.output_dir)); }

// After the phase's last step (written, and checkpointed), so that its results are kept.
void Simulation::check_motions_followed() {
  if (phase_->motions.empty()) return;
  // Each process sums its own driven points; the sums over the processes are the same bits on
  // every process, and so is the verdict drawn from them.
  std::vector<double> sums = motion_sums(model_, *phase_);
  processes_.sum(sums);
  const std::string unfollowed = unfollowed_motions(model_, *phase_, sums);
  if (unfollowed.empty()) return;
  stop(fmt::format(
      "phase '{}': the points did not follow the displacement prescribed to them:{}\nThe body "
      "resists more than the penalty springs that drive its points can impose (docs/theory.md "
      "§5): prescribe a motion the body can follow, or drive it through a structure (a rigid "
      "footing in contact) or a grid_motion. Results up to time {:g} are in {}",
      phase_->spec->name, unfollowed, time_, options_.output_dir.string()));
}

// Between steps: the run ends as one that stopped, with a checkpoint of the last converged step
// (when checkpoints are on) from which --resume goes on.
void Simulation::stop_on_interrupt() {
  update_clocks();
  const spec::Checkpoint& schedule = model_.spec.output.checkpoint;
  const bool checkpoints =
      options_.checkpoint_every.value_or(schedule.every_steps) > 0 || schedule.every_minutes > 0;
  if (checkpoints) write_checkpoint();
  stop(fmt::format(
      "interrupted ({}) in phase '{}' after step {}; results up to time {:g} are in "
      "{}{}",
      interrupt_signal_name(), phase_->spec->name, step_number_, time_,
      options_.output_dir.string(), checkpoints ? "; geompm run --resume goes on from there" : ""));
}

void Simulation::update_clocks() {
  summary_.wall_seconds = wall_before_ + seconds_since(started_);
  summary_.phases[phase_index_].wall_seconds = phase_wall_before_ + seconds_since(phase_started_);
}

void Simulation::stop(const std::string& message) {
  summary_.phases[phase_index_].status = "stopped";
  // Every process stops here together: each decision that leads here is shared by all.
  throw Shared<RunError>(message);
}

void Simulation::finish(const std::string& stop_reason) {
  progress_.finish();
  summary_.status = stop_reason.empty() ? "finished" : "stopped";
  // A stop thrown from below the step loop (an expression's value, a failed write) leaves its
  // phase "running".
  if (!stop_reason.empty() && phase_index_ < summary_.phases.size() &&
      summary_.phases[phase_index_].status == "running")
    summary_.phases[phase_index_].status = "stopped";
  summary_.time = time_;
  summary_.reason = stop_reason.empty() ? "finished" : stop_reason;
  summary_.wall_seconds = wall_before_ + seconds_since(started_);
  summary_.lost_mass = model_.lost_mass;
  summary_.lost_points = model_.lost_points;
  // Where the run stopped, unless its last step was written.
  if (!stop_reason.empty()) try {
      write_last_state();
    } catch (const std::exception&) {
    }
  together(processes_, [&] {
    if (writes_files()) finish_output(stop_reason);
  });
}

// A run that stops between two ParaView steps still shows where it stopped.
void Simulation::write_last_state() {
  if (model_.spec.output.vtk_every <= 0) return;
  const PointOutput::Files files = point_output_->files(step_number_);
  // Process 0's series says whether the step's files were written; every process learns it.
  const bool listed = output_ && output_->lists_points(files.points);
  if (processes_.sum(listed ? 1.0 : 0.0) > 0) return;
  write_points();
  together(processes_, [&] {
    if (output_) output_->write_structures(time_, step_number_);
  });
}

void Simulation::finish_output(const std::string& stop_reason) {
  if (output_) {
    summary_.history_columns = output_->columns();
    summary_.history_last = output_->last_values();
    // Whatever stopped the run, the plots of what was finished are still drawn.
    if (stop_reason.empty()) {
      output_->plots();
    } else {
      // What stopped the run (a full disk) may keep these from being written: the stop's
      // message matters more.
      try {
        output_->plots();
      } catch (const std::exception&) {
      }
    }
  }
  write_summary_json(options_.output_dir / "summary.json", summary_);
}

}  // namespace geompm

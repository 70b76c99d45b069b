#include "geompm/analysis/run.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <ostream>

#include "geompm/analysis/histories.hpp"
#include "geompm/analysis/output_fields.hpp"
#include "geompm/analysis/step.hpp"
#include "geompm/io/history_writer.hpp"
#include "geompm/io/plot.hpp"
#include "geompm/io/vtk_writer.hpp"

namespace geompm {

namespace {

using Clock = std::chrono::steady_clock;

std::string format_duration(double seconds) {
  const long s = static_cast<long>(seconds + 0.5);
  return fmt::format("{:02d}:{:02d}:{:02d}", s / 3600, (s / 60) % 60, s % 60);
}

// One line that rewrites itself on a terminal, or a line every few seconds into a log file.
class ProgressLine {
 public:
  ProgressLine(std::ostream* out, bool enabled)
      : out_(enabled ? out : nullptr), tty_(isatty(fileno(stderr))) {}

  void update(const std::string& text, bool force = false) {
    if (!out_) return;
    const auto now = Clock::now();
    if (tty_) {
      *out_ << "\r" << text << "\033[K" << std::flush;
    } else if (force || now - last_ > std::chrono::seconds(5)) {
      *out_ << text << "\n" << std::flush;
      last_ = now;
    }
  }
  void finish() {
    if (out_ && tty_) *out_ << "\n";
  }

 private:
  std::ostream* out_;
  bool tty_;
  Clock::time_point last_{};
};

class OutputWriter {
 public:
  OutputWriter(Model& model, const std::filesystem::path& dir)
      : model_(model),
        dir_(dir),
        points_series_(dir / "points.pvd"),
        grid_series_(dir / "grid.pvd"),
        recorder_(model),
        history_(dir / "history.csv", recorder_.columns()),
        newton_(dir / "newton.csv",
                {"step", "time", "dt", "iteration", "relative_residual", "relative_correction",
                 "converged", "largest_residual_node", "largest_residual_unknown", "tangent_error",
                 "plastic_points", "plastic_changes", "largest_correction_node",
                 "largest_correction_unknown", "step_length"}) {}

  /// Every Newton attempt, converged or cut back: one row per iteration, with where the
  /// residual is largest (mesh node; 0, 1, 2 = force in x, y, z, 3 = pressure equation),
  /// with `newton.tangent_check`, the tangent's error along the correction that follows (0 when
  /// the check is off or no correction followed), and the points returned plastically with
  /// how many switched between elastic and plastic since the iterate before (-1 at an attempt's
  /// first iterate), and the unknown the correction that led to the iterate moved most (node -1
  /// at an attempt's first iterate), and the fraction of that correction kept (1 for the full
  /// Newton correction, less where backtracking or the energy line search shortened it; 0 at an
  /// attempt's first iterate).
  void newton_log(int step_number, double time, double dt, const StepResult& step) {
    const NewtonResult& newton = step.newton;
    for (std::size_t k = 0; k < newton.residuals.size(); ++k) {
      const UnknownAt at =
          k < step.largest_residual.size() ? step.largest_residual[k] : UnknownAt{};
      const UnknownAt moved = k > 0 && k - 1 < step.largest_correction.size()
                                  ? step.largest_correction[k - 1]
                                  : UnknownAt{};
      newton_.append(
          {double(step_number), time, dt, double(k), newton.residuals[k],
           k > 0 && k - 1 < newton.corrections.size() ? newton.corrections[k - 1] : 0.0,
           newton.converged ? 1.0 : 0.0, double(at.node), double(at.unknown),
           k < newton.tangent_errors.size() ? newton.tangent_errors[k] : 0.0,
           k < newton.active.size() ? double(newton.active[k].size) : -1.0,
           k < newton.active.size() ? double(newton.active[k].changed) : -1.0, double(moved.node),
           double(moved.unknown),
           k > 0 && k - 1 < newton.step_lengths.size() ? newton.step_lengths[k - 1] : 0.0});
    }
  }

  void initial() {
    write_points(0.0, 0);
    history_.append(recorder_.initial_values(model_));
  }

  void step(GridSystem& grid, const StepResult& step, const PhaseContext& phase, double phase_time,
            double time, int step_number, double dt, bool vtk) {
    history_.append(recorder_.values(model_, grid, step, phase, phase_time, time, step_number, dt));
    if (!vtk) return;
    write_points(time, step_number);
    if (model_.spec.output.vtk_grid) {
      FieldSet nodes, cells;
      grid_fields(model_, grid, step, nodes, cells);
      const std::string name = fmt::format("vtk/grid_{:06d}.vtu", step_number);
      write_vtu_mesh(dir_ / name, model_.mesh, model_.mesh.nodes, nodes, cells);
      grid_series_.add(time, name);
    }
  }

  std::vector<std::filesystem::path> plots() {
    std::vector<std::filesystem::path> written;
    for (const auto& p : model_.spec.output.plots) {
      PlotRequest request;
      request.csv = history_.path();
      request.x = p.x;
      request.y = p.y;
      request.x_scale = p.x_scale;
      request.y_scale = p.y_scale;
      request.title = p.title.empty() ? model_.spec.title : p.title;
      plot_history(request, dir_ / p.file);
      written.push_back(dir_ / p.file);
    }
    return written;
  }

  const std::filesystem::path& history_file() const { return history_.path(); }

 private:
  void write_points(double time, int step_number) {
    const std::string name = fmt::format("vtk/points_{:06d}.vtu", step_number);
    write_vtu_points(dir_ / name, model_.points.position, point_fields(model_));
    points_series_.add(time, name);
  }

  Model& model_;
  std::filesystem::path dir_;
  PvdSeries points_series_, grid_series_;
  HistoryRecorder recorder_;
  HistoryWriter history_;
  HistoryWriter newton_;
};

}  // namespace

RunSummary run_analysis(Model& model, const RunOptions& options) {
  RunSummary summary;
  const auto start = Clock::now();
  std::filesystem::create_directories(options.output_dir / "vtk");
  OutputWriter output(model, options.output_dir);
  output.initial();
  summary.history_file = output.history_file();

  auto solver = create_linear_solver(model.spec.numerics.linear_solver);
  StepSolver stepper(model, *solver);
  ProgressLine progress(options.log, options.progress);

  double total_duration = 0.0, done_duration = 0.0;
  for (const auto& phase : model.spec.phases) total_duration += phase.duration;
  double time = 0.0;
  int step_number = 0;
  const int vtk_every = model.spec.output.vtk_every;

  // Whatever stops the run, the plots of what was finished are still drawn.
  auto fail = [&](const std::string& message) {
    progress.finish();
    try {
      output.plots();
    } catch (const std::exception&) {
    }
    throw RunError(message);
  };

  for (const auto& phase_spec : model.spec.phases) {
    PhaseContext phase(model, phase_spec);
    stepper.start_phase();
    for (auto& d : model.points.phase_displacement) d.setZero();
    const auto& ts = phase_spec.time_step;
    double t = 0.0, dt = ts.initial;
    while (t < phase_spec.duration * (1.0 - 1e-12)) {
      double remaining = phase_spec.duration - t;
      double dt_try = std::min(dt, remaining);
      if (remaining - dt_try < 0.01 * dt_try) dt_try = remaining;  // no sliver of a last step
      StepResult step = stepper.advance(phase, t, dt_try);
      output.newton_log(step_number + 1, time + dt_try, dt_try, step);
      if (!step.converged) {
        ++summary.cutbacks;
        dt = dt_try * ts.cutback;
        if (dt < ts.min * (1.0 - 1e-12))
          fail(fmt::format(
              "phase '{}': the step at time {:g} did not converge with the smallest "
              "allowed time step ({:g}): {}. Results up to time {:g} are in {}",
              phase_spec.name, t, dt_try, step.newton.failure, time, options.output_dir.string()));
        progress.update(fmt::format("phase {} | step {} | t {:.4g} | cut back to dt {:.3g}: {}",
                                    phase_spec.name, step_number + 1, t, dt, step.newton.failure),
                        true);
        continue;
      }
      if (model.points.size() == 0)
        fail(
            fmt::format("phase '{}', time {:g}: every material point has left the mesh; results "
                        "up to time {:g} are in {}",
                        phase_spec.name, t + dt_try, time, options.output_dir.string()));
      if (!step.lost.empty() && model.spec.numerics.lost_points == spec::LostPointPolicy::Stop) {
        std::string where;
        for (std::size_t k = 0; k < std::min<std::size_t>(step.lost.size(), 5); ++k)
          where += fmt::format("\n  point {} would move to ({:.6g}, {:.6g}, {:.6g})",
                               step.lost[k].first, step.lost[k].second.x(), step.lost[k].second.y(),
                               step.lost[k].second.z());
        fail(
            fmt::format("phase '{}', time {:g}: {} material point(s) left the mesh (policy "
                        "numerics.lost_points = stop):{}{}\nEnlarge the mesh or set "
                        "lost_points: remove. Results up to time {:g} are in {}",
                        phase_spec.name, t + dt_try, step.lost.size(), where,
                        step.lost.size() > 5 ? "\n  ..." : "", time, options.output_dir.string()));
      }
      t += dt_try;
      time += dt_try;
      done_duration += dt_try;
      ++step_number;
      ++summary.steps;
      summary.iterations += step.newton.iterations;
      summary.max_iterations_in_a_step =
          std::max(summary.max_iterations_in_a_step, step.newton.iterations);
      summary.residual_histories.push_back(step.newton.residuals);
      const bool phase_done = t >= phase_spec.duration * (1.0 - 1e-12);
      const bool vtk = vtk_every > 0 && (step_number % vtk_every == 0 || phase_done);
      output.step(stepper.grid(), step, phase, t, time, step_number, dt_try, vtk);

      const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
      const double eta =
          done_duration > 0 ? elapsed * (total_duration - done_duration) / done_duration : 0;
      progress.update(
          fmt::format("phase {} | step {} | t {:.4g}/{:.4g} | dt {:.3g} | it {} | "
                      "r {:.2e} | ETA {}",
                      phase_spec.name, step_number, t, phase_spec.duration, dt_try,
                      step.newton.iterations, step.newton.residuals.back(), format_duration(eta)));

      if (step.newton.iterations <= ts.easy_iterations)
        dt = std::min(dt_try * ts.growth, ts.max);
      else
        dt = std::min(dt_try, ts.max);
    }
  }
  progress.finish();
  output.plots();
  summary.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (options.log) {
    *options.log << fmt::format(
        "finished: {} steps, {} Newton iterations (at most {} in a step), {} cut-backs, "
        "wall time {:.2f} s{}\n",
        summary.steps, summary.iterations, summary.max_iterations_in_a_step, summary.cutbacks,
        summary.wall_seconds,
        model.lost_points ? fmt::format(", {} points left the mesh (mass {:.6g} removed)",
                                        model.lost_points, model.lost_mass)
                          : "");
    *options.log << "results in " << options.output_dir.string() << "\n";
  }
  return summary;
}

}  // namespace geompm

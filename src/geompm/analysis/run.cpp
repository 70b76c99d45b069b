#include "geompm/analysis/run.hpp"

#include <fmt/format.h>

#include <ostream>

#include "geompm/analysis/simulation.hpp"
#include "geompm/core/agreement.hpp"
#include "geompm/core/error.hpp"

namespace geompm {

namespace {

// The run from its start (or resume) to its end; a run that stops writes its summary and plots
// before the error that stopped it goes on.
void run_to_the_end(Simulation& simulation, const RunOptions& options,
                    const Communicator& processes) {
  if (options.resume)
    simulation.resume();
  else
    simulation.start();
  try {
    simulation.run();
  } catch (const RunError& e) {
    // The summary is written together by every process: not for an error of one alone.
    if (!met_by_all(e, processes)) throw;
    // summary.json says why, and the plots show what was done; what stopped the run (a full
    // disk) may keep those from being written too, which the message then says as well.
    try {
      simulation.finish(e.what());
    } catch (const std::exception& also) {
      throw Shared<RunError>(fmt::format("{}\n(and the run's summary could not be written: {})",
                                         e.what(), also.what()));
    }
    throw;
  }
  simulation.finish();
}

}  // namespace

RunSummary run_analysis(Model& model, const RunOptions& options) {
  const Communicator& processes =
      options.communicator ? *options.communicator : serial_communicator();
  Simulation simulation(model, options);
  try {
    run_to_the_end(simulation, options, processes);
  } catch (const std::exception& e) {
    // An error met by this process alone (core/agreement.hpp): the others would wait for it at
    // their next collective call. Every process is stopped now, before this one's distributed
    // solver, whose clean-up is collective too, is taken down.
    if (!met_by_all(e, processes)) end_alone(e, processes);
    throw;
  }

  const RunSummary& summary = simulation.summary();
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

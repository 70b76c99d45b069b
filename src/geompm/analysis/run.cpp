#include "geompm/analysis/run.hpp"

#include <fmt/format.h>

#include <ostream>

#include "geompm/analysis/simulation.hpp"
#include "geompm/core/error.hpp"

namespace geompm {

RunSummary run_analysis(Model& model, const RunOptions& options) {
  Simulation simulation(model, options);
  if (options.resume)
    simulation.resume();
  else
    simulation.start();
  try {
    simulation.run();
  } catch (const RunError& e) {
    // summary.json says why, and the plots show what was done; what stopped the run (a full
    // disk) may keep those from being written too, which the message then says as well.
    try {
      simulation.finish(e.what());
    } catch (const std::exception& also) {
      throw RunError(fmt::format("{}\n(and the run's summary could not be written: {})", e.what(),
                                 also.what()));
    }
    throw;
  }
  simulation.finish();

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

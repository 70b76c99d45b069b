// The quantities a model asks to follow through the run (output.history), one CSV column each,
// evaluated after every converged step: reactions on fixed boundaries and driven point sets,
// mean motion of point sets, energies, Newton iterations and the time step.
#pragma once

#include <string>
#include <vector>

#include "geompm/analysis/model.hpp"
#include "geompm/analysis/phase_context.hpp"
#include "geompm/analysis/step.hpp"

namespace geompm {

class HistoryRecorder {
 public:
  explicit HistoryRecorder(const Model& model);
  /// "time", "step", then one column per requested history.
  std::vector<std::string> columns() const;
  /// What the histories read of the points, summed over the model's points: per history, the
  /// weighted sum of a point set's field and the sum of its weights (a mean's numerator and
  /// denominator), or an energy and 0. In a distributed run, pass its processes (collective):
  /// each sums its own points and the sums are reduced, the points never gathered.
  std::vector<double> point_sums(const Model& model,
                                 const Communicator& processes = serial_communicator()) const;
  /// Values after a converged step (`grid` still holds that step's grid), with the points' part
  /// from `sums` (point_sums).
  std::vector<double> values(const Model& model, const GridSystem& grid, const StepResult& step,
                             const PhaseContext& phase, double phase_time, double time,
                             int step_number, double dt, const std::vector<double>& sums) const;
  /// Values of the initial state (time 0, step 0): reactions and iterations are 0.
  std::vector<double> initial_values(const Model& model, const std::vector<double>& sums) const;

 private:
  std::vector<spec::History> histories_;
  std::vector<int> set_bits_;
};

double kinetic_energy(const Model& model);
double strain_energy(const Model& model);

}  // namespace geompm

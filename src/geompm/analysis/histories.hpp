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
  /// Values after a converged step (`grid` still holds that step's grid).
  std::vector<double> values(const Model& model, const GridSystem& grid, const StepResult& step,
                             const PhaseContext& phase, double phase_time, double time,
                             int step_number, double dt) const;
  /// Values of the initial state (time 0, step 0): reactions and iterations are 0.
  std::vector<double> initial_values(const Model& model) const;

 private:
  double point_set_mean(const Model& model, int set, int component,
                        const std::vector<Vec3>& field) const;

  std::vector<spec::History> histories_;
  std::vector<int> set_bits_;
};

double kinetic_energy(const Model& model);
double strain_energy(const Model& model);

}  // namespace geompm

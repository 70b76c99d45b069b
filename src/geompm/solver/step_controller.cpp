#include "geompm/solver/step_controller.hpp"

#include <algorithm>
#include <cmath>

namespace geompm {

StepController::StepController(const StepControlSettings& settings, double duration)
    : settings_(settings), duration_(duration), state_{0.0, settings.initial} {}

// The relative tolerances below decide when the phase's end is reached and when a step is too
// small, whatever round-off the sum of the steps carries.
bool StepController::finished() const { return state_.time >= duration_ * (1.0 - 1e-12); }

double StepController::trial_step() const {
  const double remaining = duration_ - state_.time;
  const double dt = std::min(state_.dt, remaining);
  return remaining - dt < 0.01 * dt ? remaining : dt;  // no sliver of a last step
}

void StepController::converged(double dt, int iterations) {
  state_.time += dt;
  const double ratio = static_cast<double>(settings_.target_iterations) / std::max(iterations, 1);
  // Eq. 4.6: grow after quick steps, never shorten a converged one (only a failed step is cut).
  const double factor = std::clamp(std::sqrt(ratio), 1.0, settings_.growth);
  state_.dt = std::min(dt * factor, settings_.max);
}

bool StepController::failed(double dt) {
  state_.dt = dt * settings_.cutback;
  return can_cut_back(dt);
}

bool StepController::can_cut_back(double dt) const {
  return dt * settings_.cutback >= settings_.min * (1.0 - 1e-12);
}

}  // namespace geompm

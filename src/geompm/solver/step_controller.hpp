// The adaptive time step of a phase (docs/user-guide.md, phases.time_step): start at `initial`;
// after a step that does not converge, retry it with the step cut back by `cutback`, and give up
// once that falls below `min`; after a converged step that took n Newton iterations, grow the
// next by sqrt(target / n) where n < `target_iterations` (by at most `growth`, docs/theory.md
// §4.6) and keep it otherwise; never exceed `max`; and never leave a sliver of a step at the end
// of the phase (a last step under 1 % of the one before is taken with it).
//
// The growth is FEBio's automatic time stepper (its "optimal number of iterations"). Newton's
// iteration count in plastic steps hardly falls with the step, so a rule that grows only after
// 'easy' steps of a fixed small count never grows back once a plastic run was cut back; and a
// converged step is not shortened, for the same reason: where points switching between plastic
// states set the count, a shorter step takes as many iterations and the run only slows down.
//
// Its state (the phase time reached and the step to try next) is two numbers, saved in a
// checkpoint and restored exactly, so a resumed run takes the same steps as one that never
// stopped.
#pragma once

namespace geompm {

struct StepControlSettings {
  double initial = 0.0;
  double min = 0.0;
  double max = 0.0;
  double growth = 1.5;
  double cutback = 0.5;
  int target_iterations = 8;
};

class StepController {
 public:
  struct State {
    double time = 0.0;  // phase time reached by the converged steps
    double dt = 0.0;    // the step to try next (before the phase's end shortens it)
  };

  /// Starts a phase of the given duration at phase time 0 with the initial step.
  StepController(const StepControlSettings& settings, double duration);

  /// True once the converged steps have reached the phase's end.
  bool finished() const;
  /// The step to try from time(): the next step, shortened to end the phase exactly.
  double trial_step() const;
  /// A step of `dt` converged in `iterations` Newton iterations: time advances, and the next
  /// step is dt sqrt(target / iterations), kept within [1, growth] times dt and below max.
  void converged(double dt, int iterations);
  /// A step of `dt` did not converge: the next try is cut back. False if that would be below
  /// the smallest allowed step (the run cannot go on).
  bool failed(double dt);
  /// Whether a step of `dt` that does not converge can be retried cut back.
  bool can_cut_back(double dt) const;

  double time() const { return state_.time; }
  /// The step to try next (before trial_step() shortens it to the phase's end).
  double next_step() const { return state_.dt; }
  const StepControlSettings& settings() const { return settings_; }
  double duration() const { return duration_; }

  const State& state() const { return state_; }
  void restore(const State& state) { state_ = state; }

 private:
  StepControlSettings settings_;
  double duration_;
  State state_;
};

}  // namespace geompm

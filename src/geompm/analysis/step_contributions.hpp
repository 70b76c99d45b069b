// The contributions of a step (docs/architecture.md, "Contributions"): one maker per term, each
// reading what it needs of the model and the phase. Adding a term is one file with its
// Contribution and one line in the list of step_contributions.cpp.
#pragma once

#include <vector>

#include "geompm/analysis/phase_context.hpp"
#include "geompm/physics/newmark.hpp"
#include "geompm/physics/pressure_field.hpp"
#include "geompm/physics/step_system.hpp"

namespace geompm {

/// What the makers read, and what they hand back to the step.
struct StepContext {
  Model& model;
  PhaseContext& phase;
  const GridSystem& grid;
  const PressureField& pressure;
  double t0 = 0.0, t1 = 0.0;
  bool dynamic = false;
  Newmark newmark;
  /// Out: per prescribed point motion of the phase, the displacement since the phase start it
  /// prescribes at t1 (NaN for free components).
  std::vector<Vec3> prescribed;
};

/// Adds every contribution of the step to `system`, in the order they are evaluated.
void add_step_contributions(StepSystem& system, StepContext& context);

}  // namespace geompm

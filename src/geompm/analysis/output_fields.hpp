// What goes into the ParaView files: point fields and grid fields, gathered from the model and
// the last converged step.
#pragma once

#include "geompm/analysis/model.hpp"
#include "geompm/analysis/step.hpp"
#include "geompm/io/field_set.hpp"

namespace geompm {

/// displacement, velocity, acceleration, stress (Cauchy, tension positive), strain (Hencky,
/// 1/2 ln(F F^T)), mean_stress (tr sigma / 3), deviatoric_stress (q = sqrt(3/2 s:s)), volume,
/// mass, id, body, material.
FieldSet point_fields(const Model& model);

/// Node fields (velocity, displacement increment of the step, mass; zero at inactive nodes) and
/// cell fields (active flag, fill fraction).
void grid_fields(const Model& model, const GridSystem& grid, const StepResult& step,
                 FieldSet& node_fields, FieldSet& cell_fields);

}  // namespace geompm

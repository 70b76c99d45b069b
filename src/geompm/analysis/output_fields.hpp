// What goes into the ParaView files: point fields and grid fields, gathered from the model and
// the last converged step.
#pragma once

#include <vector>

#include "geompm/analysis/model.hpp"
#include "geompm/analysis/step.hpp"
#include "geompm/io/field_set.hpp"

namespace geompm {

/// Each point's accumulated equivalent plastic strain: its material's internal variable of that
/// name (Tresca, Mohr-Coulomb), 0 for a material without one (elastic models).
/// `points`: the model's material points, or the FEM region's Gauss points.
std::vector<double> equivalent_plastic_strain(const Model& model, const MaterialPoints& points);
inline std::vector<double> equivalent_plastic_strain(const Model& model) {
  return equivalent_plastic_strain(model, model.points);
}

/// displacement, velocity, acceleration, stress (Cauchy, tension positive), strain (Hencky,
/// 1/2 ln(F F^T)), mean_stress (tr sigma / 3), deviatoric_stress (q = sqrt(3/2 s:s)),
/// equivalent_plastic_strain, plastic (1 where the point flowed plastically in the step written,
/// as the caller found it; 0 elastic), volume, mass, id, body, material.
/// `points`: the model's material points, or the FEM region's Gauss points (docs/theory.md §19).
FieldSet point_fields(const Model& model, const MaterialPoints& points,
                      const std::vector<Index>& plastic);
inline FieldSet point_fields(const Model& model, const std::vector<Index>& plastic) {
  return point_fields(model, model.points, plastic);
}

/// Node fields (velocity, displacement increment of the step, mass; zero at inactive nodes) and
/// cell fields (active flag, fill fraction).
void grid_fields(const Model& model, const GridSystem& grid, const StepResult& step,
                 FieldSet& node_fields, FieldSet& cell_fields);

}  // namespace geompm

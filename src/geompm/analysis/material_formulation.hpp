// Which formulation a material's points take (docs/user-guide.md, "materials"; docs/theory.md
// §11, §12, §14), decided here and nowhere else: what the model file gives, or else the one that
// suits the material, so that a model written without `formulation:` does not lock.
#pragma once

#include <string>

#include "geompm/mesh/mesh.hpp"
#include "geompm/spec/model_spec.hpp"

namespace geompm {

struct MaterialFormulation {
  spec::Formulation formulation = spec::Formulation::Displacement;
  /// Mixed: the material evaluated at the field's pressure (theory §14) rather than its own.
  bool field_pressure = false;
  /// Where the choice came from: "given", "numerics.formulation" or "default for <model>".
  std::string origin;
};

/// The formulation of `material`, one of `model.materials`, on the model's `mesh`.
MaterialFormulation material_formulation(const spec::Model& model, const Mesh& mesh,
                                         const spec::Material& material);

/// "mixed p-u at the field's pressure (default for mohr_coulomb)", for geompm check.
std::string describe(const MaterialFormulation& formulation);

/// Throws InputError where the settings the formulations take contradict each other: a material
/// at the field's pressure (theory §14, which carries its own volume mismatch over the steps)
/// with numerics.mixed_pressure_equation: incremental (eq. 11.8, for the material's own pressure).
void check_material_formulations(const spec::Model& model, const Mesh& mesh);

}  // namespace geompm

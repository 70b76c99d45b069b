// Initial stresses given directly (docs/user-guide.md, "initial_stress"; docs/theory.md §10.4):
// a body's points start from the Cauchy stress its model file gives, uniform or as expressions
// of position (e.g. an isotropic 66 kPa in weightless soil), stored as the elastic strain that
// gives it, as the K0 procedure stores its geostatic stress (theory eq. 10.3).
#pragma once

#include "geompm/analysis/model.hpp"

namespace geompm {

/// Sets the initial stress of the points of every body that gives one. Called by build_model once
/// the points are seeded, before the K0 procedure. Throws InputError, at the body's
/// initial_stress, when the body is also set by the K0 procedure, when its material cannot start
/// from a stress, or when a point's stress lies outside its material's yield surface (as the K0
/// procedure does: the analysis would start from a state that is not admissible).
void apply_initial_stresses(Model& model);

}  // namespace geompm

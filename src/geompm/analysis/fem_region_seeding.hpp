// The FEM region of a model (docs/theory.md §19): its cells from the model file's `regions`, and
// a material point at each Gauss point of each FEM cell, of the body that holds the cell (its
// material by layer, its density and its point-dependent state, as a seeded point's).
#pragma once

#include "geompm/analysis/model.hpp"

namespace geompm {

/// Classifies the mesh's cells; with FEM cells, makes model.fem and seeds its Gauss points (the
/// MPM seeding skips FEM and buffer cells: analysis/model.cpp). Throws InputError for an FEM
/// cell no body holds, and for what an FEM region does not support yet (a dynamic phase, the
/// mixed formulation, GIMP).
void build_fem_region(const spec::Model& spec, Model& model);

}  // namespace geompm

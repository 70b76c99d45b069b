// A structure of the model file made into its runtime object: its mesh (a built-in shape or a
// Gmsh file), its boundary surface, its density (given, or from its mass or weight over its
// volume; a deformable structure's by default its material's) and, rigid, its reference point or,
// deformable, its material.
#pragma once

#include <memory>
#include <vector>

#include "geompm/materials/material.hpp"
#include "geompm/spec/model_spec.hpp"
#include "geompm/structures/structure.hpp"

namespace geompm {

/// Throws InputError at the structure's place in the model file for a mesh that cannot be made
/// or read, a weight with no gravity in any phase to turn it into a mass, a cell type a deformable
/// structure cannot have, a drive whose nodes select none. `materials` in the order of
/// spec.materials (a deformable structure's material among them; they outlive the structure).
std::unique_ptr<Structure> build_structure(const spec::Structure& structure,
                                           const spec::Model& model,
                                           const std::vector<const Material*>& materials);

}  // namespace geompm

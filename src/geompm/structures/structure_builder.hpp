// A structure of the model file made into its runtime object: its mesh (a built-in shape or a
// Gmsh file), its boundary surface, its density (given, or from its mass or weight over its
// volume) and its reference point.
#pragma once

#include <memory>
#include <vector>

#include "geompm/spec/model_spec.hpp"
#include "geompm/structures/structure.hpp"

namespace geompm {

/// Throws InputError at the structure's place in the model file for a mesh that cannot be made
/// or read, a weight with no gravity in any phase to turn it into a mass, a deformable
/// structure (not yet supported).
std::unique_ptr<Structure> build_structure(const spec::Structure& structure, Kinematics kinematics,
                                           const std::vector<spec::Phase>& phases);

}  // namespace geompm

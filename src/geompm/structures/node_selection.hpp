// Named sets of a deformable structure's nodes (docs/user-guide.md, "structures"): where a phase
// drives it (a pile's head: `nodes: top`) and what a history measures. Resolved on the mesh's
// current configuration, so `top` is the top wherever the structure has gone.
#pragma once

#include <vector>

#include "geompm/spec/model_spec.hpp"
#include "geompm/structures/structure_mesh.hpp"

namespace geompm {

/// The nodes selected, sorted. Throws InputError at the selection's place in the model file for
/// a group the mesh does not have, or a selection that holds no node.
std::vector<Index> select_nodes(const StructureMesh& mesh, const spec::StructureNodes& nodes);

}  // namespace geompm

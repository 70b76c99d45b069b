// Fixities of grid nodes: on a named boundary of the mesh or on a plane normal to an axis;
// "normal" fixes the component normal to that boundary (which must then be a plane normal to an
// axis: the grid is reset every step, so its boundaries stay where the mesh put them).
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "geompm/mesh/mesh.hpp"
#include "geompm/spec/model_spec.hpp"

namespace geompm {

struct ResolvedFixity {
  std::string name;          // boundary name, or "plane x=..."
  std::vector<Index> nodes;  // mesh nodes
  std::array<bool, 3> components = {false, false, false};
};

/// The corners of the box around the mesh's nodes.
std::pair<Vec3, Vec3> node_bounds(const Mesh& mesh);
/// The distance below which a node counts as on a plane or in a box: 1e-9 of the mesh's
/// bounding-box diagonal.
double node_tolerance(const Mesh& mesh);

/// Throws InputError (with the fixity's source) for a boundary that is not axis-aligned under
/// "normal", or a plane that holds no mesh node.
std::vector<ResolvedFixity> resolve_fixities(const Mesh& mesh,
                                             const std::vector<spec::Fixity>& fixities);

}  // namespace geompm

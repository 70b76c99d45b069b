// The springs at the nodes the points barely support (docs/theory.md eq. 6.2), as blocks of one
// node each (physics/node_block.hpp).
#pragma once

#include <vector>

#include "geompm/physics/grid_system.hpp"
#include "geompm/physics/node_block.hpp"

namespace geompm {

/// A spring at every active node whose support fill is below settings.sparse_node_fill; none when
/// settings.sparse_node_modulus is 0.
std::vector<NodeBlock> sparse_node_springs(const GridSystem& grid, const MaterialPoints& points);

}  // namespace geompm

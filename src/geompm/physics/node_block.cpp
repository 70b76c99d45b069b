#include "geompm/physics/node_block.hpp"

namespace geompm {

void NodeBlocks::declare_couplings(SparsityBuilder& pattern) const {
  for (const NodeBlock& block : blocks_) pattern.couple_nodes(block.nodes);
}

bool NodeBlocks::add(const Vector& du, SystemForces& forces, SparseMatrix* tangent) {
  // Few blocks (the body's edge): one thread, in order, so the sums are deterministic.
  const int u = dofs_.find("displacement");
  for (const NodeBlock& block : blocks_) {
    const Index size = static_cast<Index>(block.nodes.size());
    for (int i = 0; i < dim_; ++i)
      for (Index a = 0; a < size; ++a)
        for (Index b = 0; b < size; ++b)
          forces.internal(dofs_.dof(u, block.nodes[a], i)) +=
              block.weight(a, b) * du(dofs_.dof(u, block.nodes[b], i));
    if (!tangent) continue;
    for (int i = 0; i < dim_; ++i)
      for (Index b = 0; b < size; ++b)
        for (Index a = 0; a < size; ++a)
          add_to_tangent(*tangent, dofs_, dofs_.dof(u, block.nodes[a], i),
                         dofs_.dof(u, block.nodes[b], i), block.weight(a, b));
  }
  return true;
}

}  // namespace geompm

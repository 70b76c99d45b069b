// A stiffness that is constant over a step and acts on each displacement component of a few
// nodes alike: f_a,i += sum_b weight(a, b) du_b,i. The springs at the nodes the points barely
// support (docs/theory.md eq. 6.2: one node) and the ghost penalty of a face (eq. 6.3: the nodes
// of its two cells) are both of this form, built once a step and applied at every Newton
// iteration by one contribution.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "geompm/core/types.hpp"
#include "geompm/physics/contribution.hpp"

namespace geompm {

struct NodeBlock {
  std::vector<Index> nodes;  // active node ids, ascending
  Eigen::MatrixXd weight;    // symmetric, positive semi-definite
};

class NodeBlocks final : public Contribution {
 public:
  NodeBlocks(const char* name, std::vector<NodeBlock> blocks, const DofMap& dofs, int dim)
      : name_(name), blocks_(std::move(blocks)), dofs_(dofs), dim_(dim) {}
  const char* name() const override { return name_; }
  /// A block couples its nodes (the ghost penalty: two cells across their face).
  void declare_couplings(SparsityBuilder& pattern) const override;
  bool add(const Vector& du, SystemForces& forces, SparseMatrix* tangent) override;
  const std::vector<NodeBlock>& blocks() const { return blocks_; }

 private:
  const char* name_;
  std::vector<NodeBlock> blocks_;
  const DofMap& dofs_;
  int dim_;
};

}  // namespace geompm

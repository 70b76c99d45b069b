// A stiffness that is constant over a step and acts on each displacement component of a few
// nodes alike: f_a,i += sum_b weight(a, b) du_b,i. The springs at the nodes the points barely
// support (docs/theory.md eq. 6.2: one node) and the ghost penalty of a face (eq. 6.3: the nodes
// of its two cells) are both of this form, built once a step and applied at every Newton
// iteration by one routine.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "geompm/core/types.hpp"

namespace geompm {

struct NodeBlock {
  std::vector<Index> nodes;  // active node ids, ascending
  Eigen::MatrixXd weight;    // symmetric, positive semi-definite
};

}  // namespace geompm

// The start of a step's nodal pressure from the last converged field, smoothed by a local linear
// least-squares fit (theory eq. 11.11, `numerics.mixed_pressure_start: fitted`).
//
// With the incremental pressure equation (eqs. 11.8-11.9) the stabilisation acts on the step's
// change p - p_start, so p_start decides which pressure pattern a step keeps. Rebuilt from the
// points (eq. 11.6) it damps node-to-node patterns but is biased where a node's support is
// one-sided, which deepens the footings' crossing dip; the last converged field unchanged keeps
// every pattern the crossings leave. The fit keeps linear fields exactly, at boundary nodes too,
// and damps the patterns: a checkerboard to 1/9 and a row-alternating stripe to -1/3 a step on a
// uniform grid.
#pragma once

#include <span>
#include <vector>

#include <Eigen/Core>

#include "geompm/core/types.hpp"
#include "geompm/mesh/mesh.hpp"

namespace geompm {

/// For each active node a with a known last value (finite last[mesh node]) and `fit[a]` set:
/// start[a] = the value at a of the linear function fitted by least squares to the last values
/// of the nodes sharing an active cell with a (a included, nodes without a last value left
/// out). A node whose patch holds no more than dim + 1 such nodes, or whose nodes do not span
/// the dimension, takes its own last value. Other nodes keep start[a].
void fit_pressure_start(const Mesh& mesh, std::span<const Index> active_cells,
                        std::span<const Index> active_nodes, std::span<const Index> node_to_active,
                        std::span<const double> last, std::span<const char> fit,
                        Eigen::VectorXd& start);

}  // namespace geompm

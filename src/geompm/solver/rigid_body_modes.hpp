// The rigid-body modes of the displacement field in a matrix's numbering, from the linear
// solver's hints (linear_solver.hpp): the near-null space an AMG preconditioner needs for
// elasticity (smoothed aggregation: Vanek, Mandel & Brezina 1996), which it cannot guess from
// the matrix alone. A backend passes them on (PETSc: MatSetNearNullSpace).
#pragma once

#include <Eigen/Core>

#include "geompm/solver/linear_solver.hpp"

namespace geompm {

/// One column per mode: the block_size translations, then the rotations (one in 2D, about z;
/// three in 3D, about x, y and z) about the centroid of the nodes, u = omega x (x - c); rows of
/// other fields are zero. (In axisymmetry only the axial translation is rigid; the other columns
/// still are the smooth vectors AMG wants.)
Eigen::MatrixXd rigid_body_modes(const LinearSolverHints& hints);

}  // namespace geompm

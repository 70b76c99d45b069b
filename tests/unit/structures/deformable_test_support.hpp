// Deformable structures without the soil (docs/theory.md §17.7): a structure's term solved by
// Newton on its own unknowns, as the step solver does with the prescribed ones set and the free
// ones solved, and the meshes of the tests.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/SparseLU>

#include "geompm/dofs/sparsity.hpp"
#include "geompm/mesh/structured_mesh.hpp"
#include "geompm/structures/deformable_structure_term.hpp"

namespace geompm::testing {

/// A structured mesh of the box [0, size] from the origin with `cells` cells per axis.
inline StructureMesh box_mesh(CellType type, Kinematics k, const Vec3& size,
                              const std::array<int, 3>& cells, const Vec3& origin = Vec3::Zero()) {
  StructuredMeshSpec spec;
  spec.cell_type = type;
  spec.origin = origin;
  for (int i = 0; i < 3; ++i) spec.axes[i] = {AxisSegment{size(i), cells[i], 1.0}};
  return StructureMesh(generate_structured_mesh(spec), k);
}

/// One step of a structure under its term: Newton from the prescribed increments until the
/// free unknowns' residual is below `tolerance` times the largest force; returns the reaction
/// f_int + M a - f_ext at every unknown, and the iterations in `iterations`.
inline Vector solve_structure_step(const DofMap& dofs, DeformableStructureTerm& term, Vector& du,
                                   double tolerance = 1e-12, int* iterations = nullptr) {
  SparsityBuilder builder(dofs);
  term.declare_couplings(builder);
  SparseMatrix K = builder.build();
  term.attach(K);
  du = dofs.prescribed();
  SystemForces f;
  for (int it = 0; it < 30; ++it) {
    f.reset(dofs.size());
    K.coeffs().setZero();
    EXPECT_TRUE(term.add(du, f, &K));
    const Vector r = f.external - f.internal - f.inertia;
    Vector rf;
    dofs.restrict_to_free(r, rf);
    const double scale =
        std::max({f.internal.cwiseAbs().maxCoeff(), f.external.cwiseAbs().maxCoeff(), 1e-300});
    if (iterations) *iterations = it;
    if (rf.size() == 0 || rf.cwiseAbs().maxCoeff() < tolerance * scale) break;
    Eigen::SparseLU<SparseMatrix> lu(K);
    const Vector dx = lu.solve(rf);
    for (Index k = 0; k < dofs.num_free(); ++k) du(dofs.dof_of_free(k)) += dx(k);
  }
  f.reset(dofs.size());
  term.add(du, f, nullptr);
  return f.internal + f.inertia - f.external;
}

}  // namespace geompm::testing

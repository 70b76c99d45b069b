// The linear solver's hints for a step's system (analysis/linear_solver_hints.cpp): in the
// matrix's numbering (the free unknowns of the DofMap), each displacement row names its node and
// component, the node's position is the mesh node's, and the fields (displacement, then pressure
// in the mixed p-u formulation) partition the rows.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "geompm/analysis/linear_solver_hints.hpp"

namespace geompm {
namespace {

// Mesh nodes 0..9 at (n, n^2, -n); the step's active nodes are four of them.
std::vector<Vec3> mesh_nodes() {
  std::vector<Vec3> nodes;
  for (int n = 0; n < 10; ++n) nodes.emplace_back(n, n * n, -n);
  return nodes;
}

void check_hints(int dim, bool mixed) {
  const std::vector<Index> active{7, 2, 5, 9};
  DofMap dofs(active);
  const int u = dofs.add_nodal_field("displacement", FieldKind::Displacement, dim);
  const int p = mixed ? dofs.add_nodal_field("pressure", FieldKind::Pressure, 1) : -1;
  // Every third unknown constrained: those are no rows of the matrix.
  for (Index d = 0; d < dofs.size(); d += 3) dofs.constrain(d);
  dofs.number_free();

  const std::vector<Vec3> nodes = mesh_nodes();
  const LinearSolverHints hints = linear_solver_hints(dofs, nodes);
  const Index rows = dofs.num_free();
  EXPECT_EQ(hints.block_size, dim);
  EXPECT_FALSE(hints.symmetric);
  ASSERT_EQ(hints.unknown_node.size(), std::size_t(rows));
  ASSERT_EQ(hints.unknown_component.size(), std::size_t(rows));
  ASSERT_EQ(hints.node_coordinates.size(), active.size());
  for (std::size_t a = 0; a < active.size(); ++a)
    EXPECT_EQ(hints.node_coordinates[a], nodes[active[a]]);
  for (Index a = 0; a < Index(active.size()); ++a) {
    for (int c = 0; c < dim; ++c) {
      const Index row = dofs.free_index(dofs.dof(u, a, c));
      if (row < 0) continue;
      EXPECT_EQ(hints.unknown_node[row], a);
      EXPECT_EQ(hints.unknown_component[row], c);
    }
    if (mixed) {
      if (const Index row = dofs.free_index(dofs.dof(p, a)); row >= 0) {
        EXPECT_EQ(hints.unknown_node[row], -1);
      }
    }
  }
  // The fields partition the rows, ascending each.
  ASSERT_EQ(hints.fields.size(), mixed ? 2u : 1u);
  EXPECT_EQ(hints.fields[0].name, "displacement");
  if (mixed) {
    EXPECT_EQ(hints.fields[1].name, "pressure");
  }
  std::vector<int> seen(rows, 0);
  for (const auto& field : hints.fields) {
    EXPECT_TRUE(std::is_sorted(field.unknowns.begin(), field.unknowns.end()));
    for (const Index row : field.unknowns) ++seen[row];
  }
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), rows);
  const auto displacement_rows = std::count_if(hints.unknown_node.begin(), hints.unknown_node.end(),
                                               [](Index n) { return n >= 0; });
  EXPECT_EQ(Index(hints.fields[0].unknowns.size()), Index(displacement_rows));
  EXPECT_LT(displacement_rows, Index(active.size()) * dim);  // some were constrained
}

TEST(LinearSolverHints, DisplacementFormulation2D) { check_hints(2, false); }
TEST(LinearSolverHints, DisplacementFormulation3D) { check_hints(3, false); }
TEST(LinearSolverHints, MixedFormulationHasAPressureField) { check_hints(2, true); }

}  // namespace
}  // namespace geompm

namespace geompm {
namespace {

// A structure's rigid-body unknowns (docs/theory.md §17.2) are a field of their own: rows of no
// node, listed under the field's name after the displacement's, its constrained ones left out.
TEST(LinearSolverHints, ListAStructuresUnknownsAsAFieldOfNoNode) {
  DofMap dofs({3, 4});
  dofs.add_nodal_field("displacement", FieldKind::Displacement, 2);
  const int pipe = dofs.add_field("structure:pipe", FieldKind::Other, 1, 3);
  dofs.constrain(dofs.dof(pipe, 0, 0), 0.1);
  dofs.number_free();
  const LinearSolverHints hints = linear_solver_hints(dofs, mesh_nodes());
  ASSERT_EQ(hints.fields.size(), 2u);
  EXPECT_EQ(hints.fields[1].name, "structure:pipe");
  ASSERT_EQ(hints.fields[1].unknowns.size(), 2u);
  for (const Index row : hints.fields[1].unknowns) {
    EXPECT_EQ(hints.unknown_node[row], -1);
    EXPECT_EQ(hints.unknown_component[row], -1);
  }
  EXPECT_EQ(hints.fields[1].unknowns[0], dofs.free_index(dofs.dof(pipe, 0, 1)));
  EXPECT_EQ(hints.block_size, 2);
}

}  // namespace
}  // namespace geompm

// The linear solver's hints for a step's system (analysis/linear_solver_hints.cpp): in the
// matrix's numbering (the free unknowns), each displacement row names its node and component, the
// node's position is the mesh node's, and the fields (displacement, then pressure in the mixed
// p-u formulation) partition the rows.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "geompm/analysis/linear_solver_hints.hpp"
#include "geompm/analysis/step.hpp"
#include "run_model.hpp"

namespace geompm {
namespace {

void check_hints(spec::Formulation formulation) {
  auto spec = testing::read_example("oedometer/oedometer.yaml");
  spec.numerics.formulation = formulation;
  for (auto& material : spec.materials) material.formulation.reset();
  auto model = build_model(spec);
  GridSystem grid(model->mesh, model->topology, model->material_pointers(), grid_settings(*model));
  grid.initialise(model->points);
  // Every seventh unknown constrained: those are no rows of the matrix.
  std::vector<char> constrained(grid.num_dofs(), 0);
  for (std::size_t d = 0; d < constrained.size(); d += 7) constrained[d] = 1;
  grid.set_constraints(constrained);

  const LinearSolverHints hints = linear_solver_hints(grid, model->mesh.nodes);
  const int dim = grid.dim();
  const Index rows = grid.num_free();
  EXPECT_EQ(hints.block_size, dim);
  EXPECT_FALSE(hints.symmetric);
  ASSERT_EQ(hints.unknown_node.size(), std::size_t(rows));
  ASSERT_EQ(hints.unknown_component.size(), std::size_t(rows));
  ASSERT_EQ(hints.node_coordinates.size(), grid.active_nodes().size());
  const Index displacements = Index(grid.active_nodes().size()) * dim;
  for (Index d = 0; d < grid.num_dofs(); ++d) {
    const Index row = grid.free_index()[d];
    if (row < 0) continue;
    if (d < displacements) {
      EXPECT_EQ(hints.unknown_node[row], d / dim);
      EXPECT_EQ(hints.unknown_component[row], d % dim);
      EXPECT_EQ(hints.node_coordinates[d / dim], model->mesh.nodes[grid.active_nodes()[d / dim]]);
    } else {
      EXPECT_EQ(hints.unknown_node[row], -1);
    }
  }
  // The fields partition the rows, in ascending order each.
  const bool mixed = formulation == spec::Formulation::Mixed;
  ASSERT_EQ(hints.fields.size(), mixed ? 2u : 1u);
  EXPECT_EQ(hints.fields[0].name, "displacement");
  std::vector<int> seen(rows, 0);
  for (const auto& field : hints.fields) {
    EXPECT_TRUE(std::is_sorted(field.unknowns.begin(), field.unknowns.end()));
    for (const Index row : field.unknowns) ++seen[row];
  }
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), rows);
  Index displacement_rows = 0;
  for (Index d = 0; d < displacements; ++d) displacement_rows += grid.free_index()[d] >= 0;
  EXPECT_EQ(Index(hints.fields[0].unknowns.size()), displacement_rows);
  if (mixed) {
    EXPECT_EQ(hints.fields[1].name, "pressure");
    EXPECT_EQ(Index(hints.fields[1].unknowns.size()), rows - displacement_rows);
    EXPECT_GT(hints.fields[1].unknowns.size(), 0u);
  }
}

TEST(LinearSolverHints, DisplacementFormulation) { check_hints(spec::Formulation::Displacement); }
TEST(LinearSolverHints, MixedFormulationHasAPressureField) {
  check_hints(spec::Formulation::Mixed);
}

}  // namespace
}  // namespace geompm

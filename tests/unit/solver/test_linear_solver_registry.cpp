// Every registered linear solver (solver/linear_solver_registry.cpp) behind the LinearSolver
// interface: analyse once, setup, then any number of solves against the last setup; a singular
// matrix or an unknown name is refused. A new solver is registered by one line and is tested here
// without a line of its own (docs/architecture.md, "Adding a linear solver").
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "geompm/solver/linear_solver.hpp"

namespace geompm {
namespace {

// An unsymmetric, diagonally dominant n x n matrix (a convection-diffusion stencil), whose
// pattern does not depend on `shift`.
SparseMatrix stencil(int n, double shift) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) {
    entries.emplace_back(i, i, 4.0 + shift);
    if (i > 0) entries.emplace_back(i, i - 1, -1.5);
    if (i + 1 < n) entries.emplace_back(i, i + 1, -0.5);
    if (i + 5 < n) entries.emplace_back(i + 5, i, -1.0);
  }
  SparseMatrix a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  return a;
}

LinearSolverHints hints_for(int n) {
  LinearSolverHints hints;
  hints.block_size = 2;
  for (int node = 0; node < n / 2; ++node) hints.node_coordinates.emplace_back(node, 0.0, 0.0);
  LinearSolverField displacement{"displacement", {}};
  for (int i = 0; i < n; ++i) {
    hints.unknown_node.push_back(i / 2);
    hints.unknown_component.push_back(i % 2);
    displacement.unknowns.push_back(i);
  }
  hints.fields.push_back(displacement);
  return hints;
}

TEST(LinearSolverRegistry, NamesTheDefaultFirst) {
  const std::vector<std::string> names = linear_solver_names();
  ASSERT_GE(names.size(), 2u);
  EXPECT_EQ(names.front(), "umfpack");
  EXPECT_NE(std::find(names.begin(), names.end(), "sparse_lu"), names.end());
}

TEST(LinearSolverRegistry, EverySolverSolvesAgainstItsLastSetup) {
  const int n = 40;
  const SparseMatrix a = stencil(n, 0.0), b = stencil(n, 1.0);
  const Vector rhs = Vector::LinSpaced(n, 1.0, 2.0);
  for (const std::string& name : linear_solver_names()) {
    SCOPED_TRACE(name);
    auto solver = create_linear_solver(name);
    EXPECT_EQ(solver->name(), name);
    solver->analyse(a, hints_for(n));
    solver->setup(a);
    Vector x = Vector::Constant(n, 7.0);  // not a guess: its value on entry is not used
    const int iterations = solver->solve(rhs, x, 1e-12);
    EXPECT_GE(iterations, 1);
    EXPECT_LT((a * x - rhs).norm(), 1e-10 * rhs.norm());
    // Another right-hand side against the same setup, then a new operator of the same pattern.
    Vector y;
    solver->solve(2.0 * rhs, y, 1e-12);
    EXPECT_LT((a * y - 2.0 * rhs).norm(), 2e-10 * rhs.norm());
    solver->setup(b);
    solver->solve(rhs, y, 1e-12);
    EXPECT_LT((b * y - rhs).norm(), 1e-10 * rhs.norm());
    // A new step: analysed again, for another pattern.
    const SparseMatrix c = stencil(n + 6, 0.5);
    solver->analyse(c, hints_for(n + 6));
    solver->setup(c);
    const Vector rhs_c = Vector::Ones(n + 6);
    solver->solve(rhs_c, y, 1e-12);
    EXPECT_LT((c * y - rhs_c).norm(), 1e-10 * rhs_c.norm());
  }
}

TEST(LinearSolverRegistry, ASingularMatrixIsAFailureNotAnAnswer) {
  SparseMatrix singular = stencil(10, 0.0);
  for (int k = 0; k < singular.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(singular, k); it; ++it)
      if (it.col() == 3) it.valueRef() = 0.0;  // a zero column
  for (const std::string& name : linear_solver_names()) {
    SCOPED_TRACE(name);
    auto solver = create_linear_solver(name);
    solver->analyse(singular, {});
    Vector x;
    EXPECT_THROW(
        {
          solver->setup(singular);
          solver->solve(Vector::Ones(10), x, 1e-12);
        },
        LinearSolverFailure);
  }
}

TEST(LinearSolverRegistry, AnUnknownNameListsTheKnownOnes) {
  try {
    create_linear_solver("superlu_dist");
    FAIL() << "an unknown name was accepted";
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("'superlu_dist'"), std::string::npos) << message;
    for (const std::string& name : linear_solver_names())
      EXPECT_NE(message.find(name), std::string::npos) << message;
  }
}

TEST(LinearSolverRegistry, KnowsWhichSolversReadPetscOptionsAndTheirSyntax) {
  EXPECT_FALSE(uses_petsc("umfpack"));
  EXPECT_TRUE(uses_petsc("auto"));
  EXPECT_TRUE(uses_petsc("petsc_gamg"));
  EXPECT_THROW(uses_petsc("superlu_dist"), std::invalid_argument);
  EXPECT_EQ(petsc_options_error("-ksp_type fgmres -pc_gamg_threshold -0.1 -ksp_view"), "");
  EXPECT_EQ(petsc_options_error(""), "");
  EXPECT_NE(petsc_options_error("ksp_type gmres"), "");      // no dash
  EXPECT_NE(petsc_options_error("-ksp_type gmres cg"), "");  // two values
}

}  // namespace
}  // namespace geompm

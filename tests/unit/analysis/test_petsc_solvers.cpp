// The PETSc solvers (solver/petsc_solver.cpp) on systems of geompm's own assembly: the first
// Newton system of an elastic block under self-weight (plane strain; the displacement and the
// nearly incompressible mixed p-u formulation), recorded from a step as StepSolver solves it with
// UMFPACK, then solved again by each PETSc solver and compared with UMFPACK's solution. Also:
// GAMG's iterations stay bounded as the mesh is refined, and a solve that cannot succeed throws
// LinearSolverFailure (which Newton reports and the step controller answers by cutting the step).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <string>

#include "geompm/analysis/model.hpp"
#include "geompm/analysis/phase_context.hpp"
#include "geompm/analysis/step.hpp"

namespace geompm {
namespace {

// UMFPACK, keeping a copy of the first system it is given.
class RecordingSolver : public LinearSolver {
 public:
  SparseMatrix matrix;
  Vector rhs, solution;
  LinearSolverHints hints;

  void analyse(const SparseMatrix& pattern, const LinearSolverHints& h) override {
    if (hints.fields.empty()) hints = h;
    direct_->analyse(pattern, h);
  }
  void setup(const SparseMatrix& m) override {
    if (matrix.size() == 0) matrix = m;
    direct_->setup(m);
  }
  int solve(const Vector& b, Vector& x, double tolerance) override {
    const int n = direct_->solve(b, x, tolerance);
    if (rhs.size() == 0) {
      rhs = b;
      solution = x;
    }
    return n;
  }
  const char* name() const override { return "recording"; }

 private:
  std::unique_ptr<LinearSolver> direct_ = create_linear_solver("umfpack");
};

// The elastic block of bench/step_case.cpp: cells x cells Quad4 cells of a 10 m square, the top
// row empty, rollers on the sides, a fixed base, 4 points a cell.
spec::Model block(int cells, bool mixed, double nu) {
  spec::Model model;
  model.kinematics = Kinematics::PlaneStrain;
  StructuredMeshSpec mesh;
  mesh.cell_type = CellType::Quad4;
  mesh.axes[0] = {AxisSegment{10.0, cells, 1.0}};
  mesh.axes[1] = {AxisSegment{10.0, cells, 1.0}};
  model.mesh.generate = mesh;
  model.materials.push_back({"soil",
                             "linear_elastic",
                             {{"E", 1e5}, {"nu", nu}, {"density", 2.0}},
                             mixed ? spec::Formulation::Mixed : spec::Formulation::Displacement,
                             {}});
  spec::Body body;
  body.name = "block";
  body.material = "soil";
  body.region.kind = spec::Region::Kind::Box;
  body.region.min = Vec3(0, 0, 0);
  body.region.max = Vec3(10.0, 10.0 - 10.0 / cells, 0);
  body.points_per_cell = 4;
  model.bodies.push_back(body);
  spec::Phase phase;
  phase.name = "gravity";
  phase.duration = 1.0;
  phase.time_step = {1.0, 1.0, 1.0};
  phase.gravity = spec::Gravity{Vec3(0, -9.81, 0), false};
  spec::Fixity left, right, base;
  left.boundary = "left";
  left.normal_only = true;
  right.boundary = "right";
  right.normal_only = true;
  base.boundary = "bottom";
  base.components = {true, true, true};
  phase.fixities = {left, right, base};
  model.phases.push_back(phase);
  return model;
}

// The block's first Newton system, as UMFPACK solved it.
RecordingSolver first_system(int cells, bool mixed = false, double nu = 0.3) {
  auto model = build_model(block(cells, mixed, nu));
  PhaseContext phase(*model, model->spec.phases.front());
  RecordingSolver recorder;
  StepSolver step(*model, recorder);
  EXPECT_TRUE(step.advance(phase, 0.0, 1.0).converged);
  return recorder;
}

// Solves the recorded system with `name` to `tolerance`; the iterations it took.
int solve_with(const std::string& name, const RecordingSolver& system, double tolerance,
               Vector& x) {
  auto solver = create_linear_solver(name);
  solver->analyse(system.matrix, system.hints);
  solver->setup(system.matrix);
  return solver->solve(system.rhs, x, tolerance);
}

double relative_error(const Vector& x, const Vector& reference) {
  return (x - reference).norm() / reference.norm();
}

TEST(PetscSolvers, ElasticBlockMatchesUmfpack) {
  const RecordingSolver system = first_system(24);
  ASSERT_GT(system.rhs.size(), 1000);
  for (const std::string name : {"petsc_gamg", "petsc_hypre", "petsc_mumps"}) {
    SCOPED_TRACE(name);
    Vector x;
    const int iterations = solve_with(name, system, 1e-10, x);
    EXPECT_LT(relative_error(x, system.solution), 1e-7);
    EXPECT_LT((system.matrix * x - system.rhs).norm(), 1.1e-10 * system.rhs.norm());
    if (name != "petsc_mumps") {
      EXPECT_LT(iterations, 100);
    }
  }
}

TEST(PetscSolvers, NearlyIncompressibleMixedBlockMatchesUmfpackThroughTheSchurSplit) {
  const RecordingSolver system = first_system(16, true, 0.4999);
  ASSERT_EQ(system.hints.fields.size(), 2u);
  for (const std::string name : {"petsc_gamg", "petsc_mumps"}) {
    SCOPED_TRACE(name);
    Vector x;
    const int iterations = solve_with(name, system, 1e-10, x);
    EXPECT_LT(relative_error(x, system.solution), 1e-6);
    EXPECT_LT(iterations, 200);
  }
}

// Multigrid: the iterations to a fixed tolerance grow slowly with the number of unknowns (here
// 4x and 100x the coarsest), where a Jacobi-preconditioned Krylov method's grow with the mesh
// size's inverse (10x here). BoomerAMG's stay within 1.5x; GAMG's, with the translations alone as
// its near-null space, grew 11 -> 25 (docs/performance.md, note 17): bounded at 2.5x.
TEST(PetscSolvers, AmgIterationsStayBoundedAsTheMeshIsRefined) {
  std::vector<int> gamg, hypre;
  for (const int cells : {16, 32, 160}) {
    const RecordingSolver system = first_system(cells);
    Vector x;
    gamg.push_back(solve_with("petsc_gamg", system, 1e-8, x));
    EXPECT_LT(relative_error(x, system.solution), 1e-5);
    hypre.push_back(solve_with("petsc_hypre", system, 1e-8, x));
    EXPECT_LT(relative_error(x, system.solution), 1e-5);
  }
  std::cout << "iterations to 1e-8 on 16, 32, 160 cells: GAMG " << gamg[0] << " " << gamg[1] << " "
            << gamg[2] << ", BoomerAMG " << hypre[0] << " " << hypre[1] << " " << hypre[2] << "\n";
  EXPECT_LE(hypre[2], 1.5 * hypre[0] + 2);
  EXPECT_LE(gamg[2], 2.5 * gamg[0]);
  EXPECT_LE(gamg[1], 1.5 * gamg[0] + 2);
}

TEST(PetscSolvers, ASolveThatCannotSucceedThrowsLinearSolverFailure) {
  const RecordingSolver system = first_system(8);
  for (const std::string name : {"petsc_gamg", "petsc_hypre", "petsc_mumps"}) {
    SCOPED_TRACE(name);
    auto solver = create_linear_solver(name);
    solver->analyse(system.matrix, system.hints);
    SparseMatrix bad = system.matrix;
    bad.coeffs()[3] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(solver->setup(bad), LinearSolverFailure);
    // Singular: a row and column of zeros.
    SparseMatrix singular = system.matrix;
    for (Index k = 0; k < singular.nonZeros(); ++k)
      if (singular.innerIndexPtr()[k] == 5) singular.coeffs()[k] = 0.0;
    for (int k = singular.outerIndexPtr()[5]; k < singular.outerIndexPtr()[6]; ++k)
      singular.valuePtr()[k] = 0.0;
    Vector x, rhs = system.rhs;
    rhs[5] = 1.0;  // inconsistent: no solution
    EXPECT_THROW(
        {
          solver->setup(singular);
          solver->solve(rhs, x, 1e-10);
        },
        LinearSolverFailure);
  }
}

}  // namespace
}  // namespace geompm

// The model every benchmark times, and one step of it built up stage by stage, so that each
// benchmark times one phase of the step with everything before it already in place.
//
// The model is the self-weight of an elastic block in plane strain (the column example made
// wide): a square of `cells` x `cells` Quad4 cells, the body filling all but the top row (the
// empty buffer layer a real model has above its free surface), 4 points per cell, rollers on the
// sides and a fixed base. It exercises every part of a step that a soil model does (sorting,
// buffer cells, empty-cell stiffness, constraints, finite-strain stress update, relocation)
// while its cost depends only on the size.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "geompm/analysis/model.hpp"
#include "geompm/analysis/phase_context.hpp"
#include "geompm/analysis/step.hpp"
#include "geompm/physics/grid_system.hpp"
#include "geompm/solver/linear_solver.hpp"
#include "grid_harness.hpp"

namespace geompm::bench {

/// How the block's soil is formulated: the displacement formulation, or the mixed p-u one
/// (docs/theory.md §11) with each point's own volume change or its cell's average (F-bar, §12).
/// MixedFieldPressure: the cell average with the material at the field's pressure (theory §14).
/// MixedIncrementalFitted: the cell average with the incremental pressure equation (eq. 11.8)
/// started from the last nodal pressure fitted (eq. 11.11). DisplacementCrossedTriangles: the
/// displacement formulation on the same grid with every square split into four triangles by
/// its crossed diagonals (docs/theory.md §15), 3 points per triangle.
enum class Formulation {
  Displacement,
  MixedPerPoint,
  MixedCellAverage,
  MixedFieldPressure,
  MixedIncrementalFitted,
  DisplacementCrossedTriangles
};
const char* formulation_name(Formulation f);

/// The benchmark model with `cells` x `cells` cells (4 (cells - 1) cells material points); in
/// the mixed formulations the soil is nearly incompressible (nu = 0.49), as undrained clay is.
/// With `three_d` the same block in 3D: `cells`^3 Hex8 cells, 8 points per cell below the top
/// layer (8 (cells - 1) cells^2 points), rollers on the four sides (displacement formulation).
spec::Model block_under_gravity(int cells, Formulation formulation = Formulation::Displacement,
                                bool three_d = false);

/// Heap held by each stage of a step, measured the first time the stage is built (0: not yet).
struct StageMemory {
  double model = 0;   // mesh, topology, locator, materials, material points
  double grid = 0;    // GridSystem after initialise + constraints + one evaluation, f_ext, f_int
  double solver = 0;  // UMFPACK symbolic + numeric factorisation
};

class StepCase {
 public:
  StepCase(int cells, Formulation formulation, bool three_d = false);

  int cells() const { return cells_; }
  Formulation formulation() const { return formulation_; }
  Model& model() { return *model_; }
  Index points() const { return model_->points.size(); }

  // --- the stages of one step, in order; each builds the ones before it if needed ------------
  /// Phase 1: grid.initialise (sort, active set, colouring, shape functions, nodal mass) and the
  /// external force.
  void map();
  /// Constrained dofs from the phase's fixities, as StepSolver::advance does, then the free
  /// numbering, the tangent's pattern and the scatter maps (StepSystem::build_pattern).
  void constrain();
  /// One Newton iteration's non-solve work: stress update, internal force, tangent assembly.
  /// Its displacement increment is a smooth settlement (du_y = -1e-4 y), so the stress update
  /// runs its general path rather than the one of an undeformed point.
  void evaluate();
  /// UMFPACK's symbolic analysis of the tangent (once per step in Newton); the first call also
  /// gives the linear solver the step's pattern (LinearSolver::analyse).
  void analyse();
  /// Numeric factorisation and one solve (once per Newton iteration): LinearSolver::setup and
  /// solve. The first call after analyse() also does the solver's symbolic analysis.
  void factorize_and_solve();
  /// Phase 3: points moved with du, state committed, points relocated in the mesh (mirrors
  /// StepSolver::convect_and_relocate, which is private).
  void convect_and_relocate();
  /// Undoes what convect_and_relocate() changed that would make the next call differ (position,
  /// cell, local coordinates), so that every timed call does the same work.
  void undo_convect();

  /// A whole step, StepSolver::advance, from the current points. Returns the number of linear
  /// solves (Newton iterations).
  int full_step();
  /// What the last full_step() returned (Newton's iterations, linear iterations and seconds).
  const StepResult& last_step() const { return last_step_; }
  /// Saves the material points (once), so that restore_points() can start every timed step from
  /// the same state; the copy costs as much memory as the points themselves.
  void save_points();
  void restore_points();

  /// Builds every stage not built yet (so that memory() is complete).
  void build_all_stages();
  /// Bytes held by the copy save_points() made (0 if none).
  double saved_points_bytes() const;

  /// Drops the stage-by-stage state (grid, tangent, factorisation) and returns the freed heap to
  /// the system, so that a full step's peak memory is measured on its own.
  void release_stages();

  const StageMemory& memory() const { return memory_; }
  /// Resident bytes before the model was built (the process's baseline for this case).
  std::size_t baseline_resident() const { return baseline_resident_; }

  testing::GridHarness& grid() { return *grid_; }
  const SparseMatrix& tangent() const {
    return grid_->system().tangent();
  }  // the assembled tangent

 private:
  int cells_;
  Formulation formulation_;
  std::size_t baseline_resident_ = 0;
  std::unique_ptr<Model> model_;
  std::unique_ptr<PhaseContext> phase_;
  StageMemory memory_;
  StepResult last_step_;

  // Stage by stage.
  std::unique_ptr<testing::GridHarness> grid_;
  std::unique_ptr<LinearSolver> solver_;
  bool mapped_ = false, constrained_ = false, evaluated_ = false, analysed_ = false,
       factorised_ = false;
  std::size_t heap_before_grid_ = 0;
  Vector f_ext_, f_int_, du_, residual_;
  std::vector<char> constrained_dofs_;
  std::vector<Vec3> saved_position_;
  std::vector<Index> saved_cell_;
  std::vector<Vec3> saved_local_;

  // Whole steps.
  std::unique_ptr<LinearSolver> step_linear_solver_;
  std::unique_ptr<StepSolver> step_;
  std::optional<MaterialPoints> initial_points_;
};

/// The case of the given size and formulation, built on first use; building another drops this
/// one first, so only one model is in memory at a time (benchmarks run case by case).
StepCase& step_case(int cells, Formulation formulation = Formulation::Displacement);

}  // namespace geompm::bench

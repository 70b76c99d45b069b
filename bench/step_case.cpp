#include "step_case.hpp"

#include <Eigen/UmfPackSupport>
#include <vector>

#include "geompm/analysis/linear_solver_hints.hpp"
#include "process_memory.hpp"

namespace geompm::bench {

namespace {

constexpr double side = 10.0;  // m: the block is side x side whatever the cell count

spec::Fixity rollers(const char* boundary) {
  spec::Fixity f;
  f.boundary = boundary;
  f.normal_only = true;
  return f;
}

/// The soil body filling the box from the origin to `top` (the cells above stay empty).
spec::Body block_body(const Vec3& top, int points_per_cell) {
  spec::Body body;
  body.name = "block";
  body.material = "soil";
  body.region.kind = spec::Region::Kind::Box;
  body.region.min = Vec3(0, 0, 0);
  body.region.max = top;
  body.points_per_cell = points_per_cell;
  return body;
}

/// One load step of self-weight `g`, the base fixed and rollers on the `sides`.
spec::Phase gravity_phase(const Vec3& g, const std::vector<const char*>& sides) {
  spec::Phase phase;
  phase.name = "gravity";
  phase.duration = 1.0;
  phase.time_step = {1.0, 1.0, 1.0};
  phase.gravity = spec::Gravity{g, false};
  for (const char* side_name : sides) phase.fixities.push_back(rollers(side_name));
  spec::Fixity base;
  base.boundary = "bottom";
  base.components = {true, true, true};
  phase.fixities.push_back(base);
  return phase;
}

/// The 3D block: a cube of cells^3 Hex8 cells, the body filling all but the top layer, 8 points
/// per cell, rollers on the four sides and a fixed base, gravity along -z.
spec::Model block_under_gravity_3d(int cells) {
  spec::Model model;
  model.title = "benchmark: elastic block under self-weight, 3D";
  model.kinematics = Kinematics::ThreeD;
  StructuredMeshSpec mesh;
  mesh.cell_type = CellType::Hex8;
  for (int axis = 0; axis < 3; ++axis) mesh.axes[axis] = {AxisSegment{side, cells, 1.0}};
  model.mesh.generate = mesh;
  model.materials.push_back({"soil",
                             "linear_elastic",
                             {{"E", 1e5}, {"nu", 0.3}, {"density", 2.0}},
                             spec::Formulation::Displacement,
                             {}});
  model.bodies.push_back(block_body(Vec3(side, side, side - side / cells), 8));  // top layer empty
  model.phases.push_back(gravity_phase(Vec3(0, 0, -9.81), {"left", "right", "front", "back"}));
  return model;
}

}  // namespace

const char* formulation_name(Formulation f) {
  switch (f) {
    case Formulation::Displacement:
      return "displacement";
    case Formulation::MixedPerPoint:
      return "mixed_per_point";
    case Formulation::MixedCellAverage:
      return "mixed_cell_average";
    case Formulation::MixedFieldPressure:
      return "mixed_field_pressure";
    case Formulation::MixedIncrementalFitted:
      return "mixed_incremental_fitted";
    case Formulation::DisplacementCrossedTriangles:
      return "displacement_crossed_tri3";
  }
  return "";
}

spec::Model block_under_gravity(int cells, Formulation formulation, bool three_d) {
  if (three_d) return block_under_gravity_3d(cells);
  spec::Model model;
  model.title = "benchmark: elastic block under self-weight";
  model.kinematics = Kinematics::PlaneStrain;

  const bool triangles = formulation == Formulation::DisplacementCrossedTriangles;
  StructuredMeshSpec mesh;
  mesh.cell_type = triangles ? CellType::Tri3 : CellType::Quad4;
  if (triangles) mesh.diagonals = Diagonals::Crossed;
  mesh.axes[0] = {AxisSegment{side, cells, 1.0}};
  mesh.axes[1] = {AxisSegment{side, cells, 1.0}};
  model.mesh.generate = mesh;

  // A soil-like stiffness in kN, m, t: self-weight strains of about 1e-3, so Newton converges
  // in the few iterations a quasi-static soil step takes.
  const bool mixed = formulation != Formulation::Displacement && !triangles;
  model.materials.push_back({"soil",
                             "linear_elastic",
                             {{"E", 1e5}, {"nu", mixed ? 0.49 : 0.3}, {"density", 2.0}},
                             mixed ? spec::Formulation::Mixed : spec::Formulation::Displacement,
                             {}});
  model.numerics.mixed_volume_average = formulation == Formulation::MixedCellAverage ||
                                        formulation == Formulation::MixedFieldPressure ||
                                        formulation == Formulation::MixedIncrementalFitted;
  model.numerics.mixed_field_pressure = formulation == Formulation::MixedFieldPressure;
  model.numerics.mixed_incremental_pressure = model.numerics.fitted_pressure_start =
      formulation == Formulation::MixedIncrementalFitted;

  // The top row stays empty.
  model.bodies.push_back(block_body(Vec3(side, side - side / cells, 0), triangles ? 3 : 4));
  model.phases.push_back(gravity_phase(Vec3(0, -9.81, 0), {"left", "right"}));
  return model;
}

StepCase::StepCase(int cells, Formulation formulation, bool three_d)
    : cells_(cells), formulation_(formulation) {
  release_free_heap();
  baseline_resident_ = resident_bytes();
  const std::size_t before = heap_in_use();
  model_ = build_model(block_under_gravity(cells, formulation, three_d));
  phase_ = std::make_unique<PhaseContext>(*model_, model_->spec.phases.front());
  memory_.model = double(heap_in_use() - before);
}

void StepCase::map() {
  if (!grid_) {
    heap_before_grid_ = heap_in_use();
    grid_ = std::make_unique<testing::GridHarness>(
        model_->mesh, model_->topology, model_->material_pointers(), grid_settings(*model_));
  }
  grid_->initialise(model_->points);
  f_ext_ = grid_->external_force(model_->points, phase_->gravity(1.0), {});
  mapped_ = true;
}

void StepCase::constrain() {
  if (!mapped_) map();
  const int dim = grid_->dim();
  const auto& node_to_active = grid_->grid().node_to_active();
  const DofMap& dofs = grid_->system().dofs();
  const int u = dofs.find("displacement");
  constrained_dofs_.assign(grid_->num_dofs(), 0);
  for (const auto& fixity : phase_->fixities)
    for (Index node : fixity.nodes) {
      const Index n = node_to_active[node];
      if (n < 0) continue;
      for (int i = 0; i < dim; ++i)
        if (fixity.components[i]) constrained_dofs_[dofs.dof(u, n, i)] = 1;
    }
  grid_->set_constraints(constrained_dofs_);
  constrained_ = true;
}

void StepCase::evaluate() {
  if (!constrained_) constrain();
  if (du_.size() != grid_->num_dofs()) {
    const DofMap& dofs = grid_->system().dofs();
    const int u = dofs.find("displacement");
    du_ = Vector::Zero(grid_->num_dofs());
    for (std::size_t n = 0; n < grid_->active_nodes().size(); ++n)
      du_(dofs.dof(u, Index(n), 1)) = -1e-4 * model_->mesh.nodes[grid_->active_nodes()[n]].y();
  }
  grid_->internal_force(model_->points, du_, f_int_, nullptr, true);
  if (memory_.grid == 0) memory_.grid = double(heap_in_use() - heap_before_grid_);
  evaluated_ = true;
}

void StepCase::analyse() {
  if (!evaluated_) evaluate();
  // UMFPACK's symbolic analysis alone: the solver does it at its first setup after
  // LinearSolver::analyse (solver/eigen_direct_solver.hpp), which has no call for it on its own.
  Eigen::UmfPackLU<SparseMatrix> umfpack;
  umfpack.analyzePattern(grid_->system().tangent());
  if (!solver_) {
    solver_ = create_linear_solver(model_->spec.numerics.linear_solver);
    solver_->analyse(grid_->system().tangent(),
                     linear_solver_hints(grid_->system().dofs(), model_->mesh.nodes));
  }
  analysed_ = true;
}

void StepCase::factorize_and_solve() {
  if (!analysed_) analyse();
  const std::size_t before = heap_in_use();
  // The Newton right-hand side: the out-of-balance force at the free unknowns.
  const DofMap& dofs = grid_->system().dofs();
  if (residual_.size() != dofs.num_free()) dofs.restrict_to_free(f_ext_ - f_int_, residual_);
  // The first call also does the symbolic analysis (bench_step.cpp makes it before timing).
  solver_->setup(grid_->system().tangent());
  Vector dx;
  solver_->solve(residual_, dx, 1e-10);
  if (memory_.solver == 0) memory_.solver = double(heap_in_use() - before);
  factorised_ = true;
}

void StepCase::convect_and_relocate() {
  if (!evaluated_) evaluate();
  MaterialPoints& points = model_->points;
  const Index n = points.size();
  if (saved_position_.empty()) {
    saved_position_ = points.position;
    saved_cell_ = points.cell;
    saved_local_ = points.local;
  }
  // As StepSolver::convect_and_relocate: find every destination before committing anything.
  std::vector<Location> found(n);
  std::vector<char> lost(n, 0);
  const Vector nodal_du = displacement_block(grid_->system().dofs(), du_);
#pragma omp parallel for schedule(dynamic, 1024) if (n > 4096)
  for (Index p = 0; p < n; ++p) {
    const Vec3 destination = points.position[p] + grid_->grid().interpolate(points, p, nodal_du);
    if (auto where = model_->locator->locate(destination, points.cell[p]))
      found[p] = *where;
    else
      lost[p] = 1;
  }
  const Vector velocity = du_;  // quasi-static, dt = 1
  const Vector acceleration = Vector::Zero(du_.size());
  grid_->convect(points, du_, velocity, acceleration, 1.0, false);
  for (Index p = 0; p < n; ++p)
    if (!lost[p]) {
      points.cell[p] = found[p].cell;
      points.local[p] = found[p].xi;
    }
}

void StepCase::undo_convect() {
  if (saved_position_.empty()) return;
  model_->points.position = saved_position_;
  model_->points.cell = saved_cell_;
  model_->points.local = saved_local_;
}

int StepCase::full_step() {
  if (!step_) {
    step_linear_solver_ = create_linear_solver(model_->spec.numerics.linear_solver);
    step_ = std::make_unique<StepSolver>(*model_, *step_linear_solver_);
  }
  last_step_ = step_->advance(*phase_, 0.0, 1.0);
  if (!last_step_.converged)
    throw std::runtime_error("benchmark step did not converge: " + last_step_.newton.failure);
  return last_step_.newton.iterations;
}

void StepCase::save_points() {
  if (!initial_points_) initial_points_ = model_->points;
}

void StepCase::restore_points() {
  if (initial_points_) model_->points = *initial_points_;
}

void StepCase::release_stages() {
  undo_convect();
  grid_.reset();
  solver_.reset();
  f_ext_ = f_int_ = du_ = residual_ = Vector();
  constrained_dofs_ = {};
  saved_position_ = {};
  saved_cell_ = {};
  saved_local_ = {};
  mapped_ = constrained_ = evaluated_ = analysed_ = factorised_ = false;
  release_free_heap();
}

void StepCase::build_all_stages() {
  // Once: a rebuild after release_stages() would cost a factorisation and measure a heap
  // fragmented by the first build.
  if (memory_.solver == 0) factorize_and_solve();
}

double StepCase::saved_points_bytes() const {
  return initial_points_ ? initial_points_->bytes_per_point() * double(initial_points_->size())
                         : 0.0;
}

StepCase& step_case(int cells, Formulation formulation) {
  static std::unique_ptr<StepCase> current;
  if (!current || current->cells() != cells || current->formulation() != formulation) {
    current.reset();  // first free the previous case, then build the next
    current = std::make_unique<StepCase>(cells, formulation);
  }
  return *current;
}

}  // namespace geompm::bench

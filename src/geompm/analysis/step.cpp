#include "geompm/analysis/step.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "geompm/analysis/linear_solver_hints.hpp"
#include "geompm/analysis/material_formulation.hpp"
#include "geompm/analysis/step_contributions.hpp"
#include "geompm/core/byte_archive.hpp"
#include "geompm/mesh/partition.hpp"
#include "geompm/physics/inertia.hpp"
#include "geompm/physics/newmark.hpp"
#include "geompm/physics/point_integrator.hpp"
#include "geompm/physics/point_springs.hpp"
#include "geompm/points/point_exchange.hpp"
#include "geompm/solver/newton_attempts.hpp"

namespace geompm {

GridSettings grid_settings(const Model& model, const Communicator& processes) {
  GridSettings s;
  s.kinematics = model.kinematics();
  const double soil_modulus = model.softest_modulus(processes);
  s.empty_cell_modulus = model.spec.numerics.empty_cell_stiffness * soil_modulus;
  s.sparse_node_modulus = model.spec.numerics.sparse_node_stiffness * soil_modulus;
  s.sparse_node_fill = model.spec.numerics.sparse_node_fill;
  s.ghost_penalty = model.spec.numerics.ghost_penalty;
  s.ghost_penalty_fill = model.spec.numerics.ghost_penalty_fill;
  s.buffer_layers = model.spec.numerics.buffer_layers;
  s.mixed_incremental_pressure = model.spec.numerics.mixed_incremental_pressure;
  s.pressure_stabilisation_floor = model.spec.numerics.pressure_stabilisation_floor;
  s.fitted_pressure_start = model.spec.numerics.fitted_pressure_start;
  switch (model.spec.numerics.interpolation) {
    case spec::Interpolation::Standard:
      s.interpolation = GridInterpolation::Standard;
      break;
    case spec::Interpolation::DualDomain:
      s.interpolation = GridInterpolation::DualDomain;
      break;
    case spec::Interpolation::Gimp:
      s.interpolation = GridInterpolation::Gimp;
      break;
  }
  if (model.fem) s.fem_cells = model.fem->fem_cell();
  for (const auto& material : model.spec.materials) {
    const MaterialFormulation chosen = material_formulation(model.spec, model.mesh, material);
    const bool mixed = chosen.formulation == spec::Formulation::Mixed;
    s.mixed.push_back(mixed);
    s.field_pressure.push_back(chosen.field_pressure);
    s.volume_average.push_back(chosen.formulation == spec::Formulation::FBar ||
                               (mixed && model.spec.numerics.mixed_volume_average));
  }
  return s;
}

namespace {

// The Lagrangian phase as a nonlinear problem in the free unknowns: residual R = f_ext - f_int -
// M a (seed eq. 6), every term a contribution of the step's system.
class LagrangianProblem final : public NonlinearProblem {
 public:
  LagrangianProblem(StepSystem& system, Vector& du, const Inertia* inertia)
      : system_(system),
        dofs_(system.dofs()),
        du_(du),
        inertia_(inertia),
        springs_(system.find<PointSprings>()),
        points_(*system.find<PointIntegrator>()) {}

  bool evaluate(const Vector& x, Vector& residual, double& force_scale,
                SparseMatrix* tangent) override {
    for (Index k = 0; k < dofs_.num_free(); ++k) du_(dofs_.dof_of_free(k)) = x(k);
    largest_dof_ = -1;
    if (!system_.evaluate(du_, forces_, tangent != nullptr)) return false;
    const Vector r = forces_.external - forces_.internal - forces_.inertia;
    residual.resize(x.size());
    for (Index k = 0; k < dofs_.num_free(); ++k) {
      const Index d = dofs_.dof_of_free(k);
      residual(k) = r(d);
      if (largest_dof_ < 0 || std::abs(r(d)) > std::abs(r(largest_dof_))) largest_dof_ = d;
    }
    largest_value_ = largest_dof_ >= 0 ? r(largest_dof_) : 0.0;
    // The forces in play; in dynamics also the momentum rate M v / dt, so that a body moving
    // freely without loads is measured against its own motion, not against round-off.
    force_scale =
        std::max({forces_.external.norm(), forces_.internal.norm(), forces_.inertia.norm()});
    if (inertia_) force_scale = std::max(force_scale, inertia_->momentum_rate());
    // And the forces a prescribed point motion would take in the body's own stiffness: a body
    // driven through a rigid motion has nothing else but round-off.
    if (springs_) force_scale = std::max(force_scale, driving_force_scale());
    return true;
  }

  double increment_norm(const Vector& x) const override {
    // Free unknowns from x, constrained ones (prescribed) from du_.
    double sum = x.squaredNorm();
    for (Index d = 0; d < dofs_.size(); ++d)
      if (dofs_.constrained(d)) sum += du_(d) * du_(d);
    return std::sqrt(sum);
  }

  /// Contributions with a switch outside the material (contact) hold the branch the accepted
  /// iterate took.

  /// The points whose update returned them plastically at the last evaluation, and how many
  /// changed between elastic and plastic since the last call (newton.csv). A switching point
  /// changes the branch of the return, and with it the tangent, between iterates.
  ActiveSet active_set() override {
    const std::vector<char>& plastic = points_.plastic_points();
    ActiveSet set{0, last_plastic_.size() == plastic.size() ? 0 : -1};
    for (std::size_t p = 0; p < plastic.size(); ++p) {
      set.size += plastic[p];
      if (set.changed >= 0) set.changed += plastic[p] != last_plastic_[p];
    }
    last_plastic_ = plastic;
    if (const Communicator& processes = system_.communicator(); processes.distributed()) {
      std::vector<double> counts = {double(set.size), set.changed < 0 ? 1.0 : 0.0,
                                    double(std::max<Index>(set.changed, 0))};
      processes.sum(counts);
      set.size = static_cast<Index>(counts[0]);
      set.changed = counts[1] > 0 ? -1 : static_cast<Index>(counts[2]);
    }
    return set;
  }

  const SystemForces& forces() const { return forces_; }
  /// The prescribed motions' force scale, over every process's driven points.
  double driving_force_scale() const {
    const double own = springs_->driving_force_scale();
    const Communicator& processes = system_.communicator();
    return processes.distributed() ? std::sqrt(processes.sum(own * own)) : own;
  }
  /// The unknown with the largest out-of-balance force at the last admissible evaluation (-1 if
  /// the last evaluation was inadmissible), and that force.
  Index largest_residual_unknown() const override { return largest_dof_; }
  Index problem_unknown(Index free) const override { return dofs_.dof_of_free(free); }
  double largest_residual_value() const { return largest_value_; }
  std::string inadmissible_reason() const override {
    return points_.inadmissible_by_stress_update()
               ? "inadmissible stress (a point's stress update did not converge)"
               : NonlinearProblem::inadmissible_reason();
  }

 private:
  StepSystem& system_;
  const DofMap& dofs_;
  Vector& du_;
  const Inertia* inertia_;
  const PointSprings* springs_;  // prescribed point motion, if any
  const PointIntegrator& points_;
  SystemForces forces_;
  Index largest_dof_ = -1;
  double largest_value_ = 0.0;
  std::vector<char> last_plastic_;
};

// A step's unknown as the mesh node it belongs to and what it is: displacement component 0..2
// (x, y, z) or 3, the pressure.
UnknownAt unknown_at(const DofMap& dofs, Index dof) {
  const Unknown u = dofs.unknown(dof);
  const Field& field = dofs.field(u.field);
  if (!field.nodal) return {};
  return {dofs.active_nodes()[u.entity],
          field.kind == FieldKind::Pressure ? UnknownAt::kPressure : u.component};
}

// Where a step that did not converge is out of balance most: the unknown, its node and the
// force, so that a user can see which part of the model holds Newton back.
std::string out_of_balance(const DofMap& dofs, const Mesh& mesh, Index dof, double value) {
  const UnknownAt u = unknown_at(dofs, dof);
  if (u.node < 0) {
    // An unknown of no node: a structure's (its component: translations, then rotations) or a
    // contact's multiplier.
    const Unknown what = dofs.unknown(dof);
    const std::string& field = dofs.field(what.field).name;
    std::string message = fmt::format("largest out-of-balance force {:.3g} in component {} of '{}'",
                                      value, what.component, field);
    if (field.starts_with("structure:"))
      message +=
          " (a structure free in a component that touches nothing has no stiffness in a "
          "quasi-static phase: place it on the soil, or prescribe that component until it "
          "touches)";
    return message;
  }
  const Vec3& x = mesh.nodes[u.node];
  const std::string at = mesh.dim() == 3
                             ? fmt::format("({:.4g}, {:.4g}, {:.4g})", x.x(), x.y(), x.z())
                             : fmt::format("({:.4g}, {:.4g})", x.x(), x.y());
  if (u.unknown == UnknownAt::kPressure)
    return fmt::format("largest residual in the pressure equation of node {} at {}", u.node, at);
  return fmt::format("largest out-of-balance force {:.3g} in {} at node {} {}", value,
                     "xyz"[u.unknown], u.node, at);
}

// Whether a dynamic step starts where the points carry no acceleration: the first step of the
// first phase, or of a phase after a quasi-static one (whose convection zeroes it).
bool starts_from_rest(const spec::Model& model, const spec::Phase& phase, double t0) {
  if (t0 != 0.0) return false;
  const auto index = &phase - model.phases.data();  // the phase is one of the model's
  return index <= 0 || index >= std::ssize(model.phases) ||
         model.phases[std::size_t(index) - 1].dynamics.quasi_static;
}

}  // namespace

StepSolver::StepSolver(Model& model, LinearSolver& solver, const Communicator& processes)
    : model_(model),
      solver_(solver),
      grid_(model.mesh, model.topology, model.material_pointers(),
            grid_settings(model, processes)) {
  if (model.fem) relaxation_ = std::make_unique<MeshRelaxation>(model.mesh, *model.fem);
}

void StepSolver::distribute(const Communicator& communicator, std::vector<int> cell_part) {
  node_part_ = node_owners(model_.mesh, cell_part);
  grid_.distribute(communicator, std::move(cell_part));
}

// What a step carries from its set-up to its end.
struct StepSolver::Step {
  double t0 = 0.0, t1 = 0.0;
  bool dynamic = false;
  Newmark newmark;
  Vector du;                          // every unknown: the prescribed ones set before Newton
  std::vector<Vec3> prescribed;       // per point motion: its displacement at t1
  std::vector<Vec3> grid_increments;  // per grid motion: its increment over the step
};

namespace {

// The unknown's entry in last_rate_: dim displacements, then the pressure, per mesh node.
std::size_t rate_index(const UnknownAt& at, int dim) {
  return static_cast<std::size_t>(at.node) * (dim + 1) +
         (at.unknown == UnknownAt::kPressure ? dim : at.unknown);
}
}  // namespace

double StepSolver::full_step_increment(double max_step) const {
  double sum = 0.0;
  for (const double rate : last_rate_) sum += rate * rate;
  return std::sqrt(sum) * max_step;
}

bool StepSolver::extrapolated_start(double dt, Vector& x) const {
  if (last_rate_.empty()) return false;
  const DofMap& dofs = system_->dofs();
  bool any = false;
  for (Index k = 0; k < dofs.num_free(); ++k) {
    const UnknownAt at = unknown_at(dofs, dofs.dof_of_free(k));
    if (at.node < 0) {
      // An unknown of no node (a structure's): its field's rate, where the last step had it.
      const Unknown u = dofs.unknown(dofs.dof_of_free(k));
      const Field& field = dofs.field(u.field);
      // A contact's multipliers belong to groups of its surface that change from step to step:
      // they start from the last step's values (docs/theory.md eq. 18.9), not extrapolated.
      const auto it =
          field.name.starts_with("contact:") ? field_rate_.end() : field_rate_.find(field.name);
      const std::size_t local = static_cast<std::size_t>(dofs.dof_of_free(k) - field.offset);
      x(k) = it != field_rate_.end() && local < it->second.size() ? it->second[local] * dt : 0.0;
      any = any || x(k) != 0.0;
      continue;
    }
    const double rate = last_rate_[rate_index(at, grid_.dim())];
    x(k) = rate * dt;
    any = any || rate != 0.0;
  }
  return any;
}

void StepSolver::remember_increment(const Vector& du, double dt) {
  const DofMap& dofs = system_->dofs();
  last_rate_.assign(model_.mesh.nodes.size() * (grid_.dim() + 1), 0.0);
  for (Index d = 0; d < du.size(); ++d)
    if (const UnknownAt at = unknown_at(dofs, d); at.node >= 0)
      last_rate_[rate_index(at, grid_.dim())] = du(d) / dt;
  // The fields of no node (structures') by name: their unknowns are the same from step to step.
  field_rate_.clear();
  for (int f = 0; f < dofs.num_fields(); ++f) {
    const Field& field = dofs.field(f);
    if (field.nodal) continue;
    std::vector<double>& rate = field_rate_[field.name];
    for (Index k = 0; k < field.entities * field.components; ++k)
      rate.push_back(du(field.offset + k) / dt);
  }
}

void StepSolver::constrain(const PhaseContext& phase, double t0, double t1, Step& step) const {
  DofMap& dofs = system_->dofs();
  const int u = dofs.find("displacement");
  const auto& node_to_active = grid_.node_to_active();
  // Fixities of grid nodes.
  for (const auto& fixity : phase.fixities)
    for (Index node : fixity.nodes) {
      const Index a = node_to_active[node];
      if (a < 0) continue;
      for (int i = 0; i < grid_.dim(); ++i)
        if (fixity.components[i]) dofs.constrain(dofs.dof(u, a, i));
    }
  // Prescribed motion of grid nodes (docs/theory.md §5.3): constrained unknowns with a non-zero
  // increment, set before Newton. Newton solves for the free unknowns only and never changes
  // these, so every residual it evaluates sees them. On a node also fixed, the motion wins.
  for (const auto& motion : phase.grid_motions) {
    step.grid_increments.push_back(motion.increment(t0, t1));
    const Vec3& increment = step.grid_increments.back();
    for (Index node : motion.nodes) {
      const Index a = node_to_active[node];
      if (a < 0) continue;
      for (int i = 0; i < grid_.dim(); ++i)
        if (!std::isnan(increment(i))) dofs.constrain(dofs.dof(u, a, i), increment(i));
    }
  }
  // Structures (docs/theory.md §17.4): a prescribed component of the motion is a constrained
  // unknown with its increment over the step; axisymmetry holds the radial one and the rotation
  // (of a deformable structure: its driven nodes' components, its nodes on the axis radially).
  for (std::size_t k = 0; k < model_.structures.size(); ++k) {
    const int field = dofs.find(model_.structures[k]->field_name());
    for (const DriveConstraint& c : phase.structure_drives[k].constraints(t0, t1))
      dofs.constrain(dofs.dof(field, c.entity, c.component), c.value);
  }
}

void StepSolver::set_up(PhaseContext& phase, double t0, double dt, Step& step) {
  step.t0 = t0;
  step.t1 = t0 + dt;
  step.dynamic = !phase.spec->dynamics.quasi_static;
  const spec::Dynamics& dynamics = phase.spec->dynamics;
  step.newmark = Newmark{dynamics.beta, dynamics.gamma, dt, dynamics.alpha_m};
  grid_.initialise(model_.points);
  if (grid_.mixed()) pressure_.initialise(grid_, model_.points);
  system_ = std::make_unique<StepSystem>(grid_);
  // The structures' unknowns follow the grid's, before any contribution is made.
  for (const auto& structure : model_.structures) structure->add_unknowns(system_->dofs());
  StepContext context{model_,  phase,        grid_,        pressure_, step.t0,
                      step.t1, step.dynamic, step.newmark, {}};
  add_step_contributions(*system_, context);
  step.prescribed = std::move(context.prescribed);
  constrain(phase, step.t0, step.t1, step);
  system_->build_pattern();
  step.du = system_->dofs().prescribed();
  if (step.dynamic && starts_from_rest(model_.spec, *phase.spec, t0)) {
    SystemForces at_start;
    if (system_->evaluate(Vector::Zero(system_->dofs().size()), at_start, false))
      system_->find<Inertia>()->start_in_balance(at_start);
  }
}

bool writes_boundary(const spec::Model& spec) {
  if (spec.output.vtk_every <= 0) return false;
  // Where the soil's boundary matters: surface loads act on it, structures touch it.
  if (!spec.structures.empty()) return true;
  return std::any_of(spec.phases.begin(), spec.phases.end(),
                     [](const spec::Phase& phase) { return !phase.surface_loads.empty(); });
}

StepResult StepSolver::advance(PhaseContext& phase, double t0, double dt, bool last_resort) {
  StepResult result;
  Step step;
  // --- phase 1: initialise: the grid, the step's unknowns and contributions
  set_up(phase, t0, dt, step);
  result.gravity = phase.gravity(step.t1);
  result.dofs = &system_->dofs();
  // --- phase 2: Lagrangian (Newton)
  if (!solve(phase, dt, last_resort, step, result)) return result;
  result.converged = true;
  // --- phase 3: convect
  finish(phase, dt, step, result);
  return result;
}

bool StepSolver::solve(const PhaseContext& phase, double dt, bool last_resort, Step& step,
                       StepResult& result) {
  const DofMap& dofs = system_->dofs();
  LagrangianProblem problem(*system_, step.du, system_->find<Inertia>());
  NewtonSettings settings;
  settings.max_iterations = phase.spec->newton.max_iterations;
  settings.residual_tolerance = phase.spec->newton.residual_tolerance;
  settings.displacement_tolerance = phase.spec->newton.displacement_tolerance;
  // newton.line_search not set: whole corrections, and halved ones where the residual grew only
  // as the last resort of a step that failed at the smallest allowed step (theory §4.4).
  const spec::Newton& newton = phase.spec->newton;
  if (newton.last_resort_backtracking())
    settings.max_halvings = last_resort ? fallback_halvings : 0;
  else
    settings.max_halvings = newton.line_search;
  settings.energy_search = phase.spec->newton.energy_line_search;
  settings.tangent_check = phase.spec->newton.tangent_check;
  settings.increment_floor = full_step_increment(phase.spec->time_step.max);
  // Newton starts from a zero increment, or from the last step's extrapolated: the plastic zone
  // and its flow are then in place from the first iterate, so fewer points switch between
  // elastic and plastic in the iterations. Where that start fails (an inadmissible iterate, or
  // Newton cycling between the plastic states of a few points), the step is solved again from
  // zero, whose first iterate is elastic, before it is cut back; both attempts are counted.
  // The extrapolated start gets half of the iterations (or `extrapolated_patience`, where the zero
  // start is the worse bet: theory §4.5), and more only while it converges superlinearly (each
  // residual a tenth of the one before or less): one that has not reached Newton's quadratic
  // regime by then is not the quick start it is meant to be, and the zero start still gets all
  // of them; one that has would throw away an almost converged iterate.
  Vector x = Vector::Zero(dofs.num_free());
  const bool extrapolated = phase.spec->newton.extrapolate && extrapolated_start(dt, x);
  NewtonSettings first = settings;
  if (extrapolated) {
    const int patience = phase.spec->newton.extrapolated_patience;
    first.patience = patience > 0 ? patience : std::max(1, settings.max_iterations / 2);
  }
  // The step's pattern and unknowns, for the linear solver; a retry analyses again, as a direct
  // solver's symbolic analysis takes the values of the first matrix after it (UMFPACK's).
  SparseMatrix& tangent = system_->tangent();
  const LinearSolverHints hints = linear_solver_hints(dofs, model_.mesh.nodes, node_part_);
  solver_.analyse(tangent, hints);
  result.newton = solve_newton(problem, solver_, first, x, tangent);
  if (extrapolated && !result.newton.converged) {
    x.setZero();
    solver_.analyse(tangent, hints);
    NewtonResult from_zero = solve_newton(problem, solver_, settings, x, tangent);
    result.newton = join_attempts(result.newton, std::move(from_zero));
  }
  for (const Index dof : result.newton.largest)
    result.largest_residual.push_back(dof >= 0 ? unknown_at(dofs, dof) : UnknownAt{});
  for (const Index dof : result.newton.largest_correction)
    result.largest_correction.push_back(dof >= 0 ? unknown_at(dofs, dof) : UnknownAt{});
  if (result.newton.converged) {
    result.reaction =
        problem.forces().internal + problem.forces().inertia - problem.forces().external;
    return true;
  }
  const PointIntegrator& integrator = *system_->find<PointIntegrator>();
  const MaterialPoints& points = model_.points;
  if (const Index p = integrator.inadmissible_point();
      result.newton.inadmissible && p >= 0 && p < points.size()) {
    const Vec3& at = points.position[p];
    result.newton.failure +=
        grid_.dim() == 3
            ? fmt::format("; material point {} at ({:.4g}, {:.4g}, {:.4g})", points.id[p], at.x(),
                          at.y(), at.z())
            : fmt::format("; material point {} at ({:.4g}, {:.4g})", points.id[p], at.x(), at.y());
  }
  if (problem.largest_residual_unknown() >= 0)
    result.newton.failure +=
        "; " + out_of_balance(dofs, model_.mesh, problem.largest_residual_unknown(),
                              problem.largest_residual_value());
  return false;
}

void StepSolver::finish(PhaseContext& phase, double dt, Step& step, StepResult& result) {
  const DofMap& dofs = system_->dofs();
  result.displacement = step.du;
  // Its rate starts the next step with the extrapolated predictor and scales the corrections of
  // a cut-back step (full_step_increment).
  remember_increment(step.du, dt);
  if (const Inertia* inertia = system_->find<Inertia>()) {
    result.acceleration = inertia->acceleration(step.du);
    result.velocity = inertia->velocity(result.acceleration);
  } else {
    result.acceleration = Vector::Zero(dofs.size());
    result.velocity = step.du / dt;
  }
  if (grid_.mixed()) result.nodal_pressure = pressure_.nodal_pressure(dofs, step.du);
  Reactions reactions;
  system_->report(step.du, reactions);
  result.set_reactions = std::move(reactions.point_sets);
  for (std::size_t k = 0; k < model_.structures.size(); ++k)
    if (const auto* rigid = dynamic_cast<const RigidStructure*>(model_.structures[k].get()))
      result.structure_forces[rigid->name()] =
          drive_forces(*rigid, phase.structure_drives[k], dofs, result.reaction, step.t1);
    else if (const auto* body =
                 dynamic_cast<const DeformableStructure*>(model_.structures[k].get()))
      result.structure_forces[body->name()] =
          drive_forces(*body, phase.structure_drives[k], dofs, result.reaction, step.t1);
  if (writes_boundary(model_.spec)) {
    result.boundary = zero_level_set(LevelSet(grid_, model_.points));
    move_facets(result.boundary, grid_, displacement_block(dofs, step.du));
  }
  convect_and_relocate(result, dt, step.dynamic);
  if (result.lost.empty() || model_.spec.numerics.lost_points == spec::LostPointPolicy::Remove)
    commit_motions(phase, step);
}

void StepSolver::commit_motions(PhaseContext& phase, const Step& step) {
  for (std::size_t m = 0; m < phase.motions.size(); ++m) {
    const Vec3 reached = step.prescribed[m];
    for (int i = 0; i < 3; ++i)
      if (!std::isnan(reached(i))) phase.motions[m].done(i) = reached(i);
  }
  system_->commit();
  for (std::size_t m = 0; m < phase.grid_motions.size(); ++m) {
    Vec3& done = model_.grid_displacement.try_emplace(phase.grid_motions[m].name, Vec3::Zero())
                     .first->second;
    for (int i = 0; i < 3; ++i)
      if (!std::isnan(step.grid_increments[m](i))) done(i) += step.grid_increments[m](i);
  }
}

void StepSolver::convect_and_relocate(StepResult& result, double dt, bool dynamic) {
  MaterialPoints& points = model_.points;
  const Index n = points.size();
  // Where each point goes, found before anything is committed: under the "stop" policy a point
  // that leaves the mesh stops the run with the points still in the last converged state.
  std::vector<Location> found(n);
  std::vector<Vec3> destination(n);
  std::vector<char> lost(n, 0);
  const Vector nodal_du = displacement_block(system_->dofs(), result.displacement);
  const std::vector<Vec3> unmoved = model_.fem ? move_mesh(nodal_du, result) : std::vector<Vec3>{};
#pragma omp parallel for schedule(dynamic, 1024) if (n > 4096)
  for (Index p = 0; p < n; ++p) {
    destination[p] = points.position[p] + grid_.interpolate(points, p, nodal_du);
    if (auto where = model_.locator->locate(destination[p], points.cell[p]))
      found[p] = *where;
    else
      lost[p] = 1;
    // A point that crossed into an FEM cell would add its mass and stiffness to the cell's Gauss
    // points' (docs/theory.md §19): it is handled as one that left the mesh.
    if (!lost[p] && model_.fem && model_.fem->fem_cell()[found[p].cell]) lost[p] = 1;
  }
  for (Index p = 0; p < n; ++p)
    if (lost[p]) result.lost.emplace_back(points.id[p], destination[p]);
  share_lost_points(result, lost);
  if (!result.lost.empty() && model_.spec.numerics.lost_points == spec::LostPointPolicy::Stop) {
    if (model_.fem) {
      model_.mesh.nodes = unmoved;
      model_.locator = std::make_unique<PointLocator>(model_.mesh);
    }
    return;
  }

  const DofMap& dofs = system_->dofs();
  pressure_.remember(grid_, dofs, result.displacement);
  system_->find<PointIntegrator>()->commit_state(points, result.displacement);
  grid_.convect(points, displacement_block(dofs, result.displacement),
                displacement_block(dofs, result.velocity),
                displacement_block(dofs, result.acceleration), dt, dynamic);
  for (Index p = 0; p < n; ++p)
    if (!lost[p]) {
      points.cell[p] = found[p].cell;
      points.local[p] = found[p].xi;
    }
  if (!result.lost.empty()) {
    if (!grid_.communicator().distributed())
      for (Index p = 0; p < n; ++p)
        if (lost[p]) {
          model_.lost_mass += points.mass[p];
          ++model_.lost_points;
        }
    points.remove(lost);
  }
  // Points that crossed into another process's cell go to it.
  if (grid_.communicator().distributed())
    migrate_points(points, grid_.cell_part(), grid_.communicator());
}

void StepSolver::share_lost_points(StepResult& result, const std::vector<char>& lost) const {
  const Communicator& processes = grid_.communicator();
  if (!processes.distributed()) return;
  ByteWriter mine;
  double mass = 0.0;
  for (std::size_t p = 0; p < lost.size(); ++p)
    if (lost[p]) mass += model_.points.mass[p];
  mine.put(result.lost);
  mine.put(mass);
  result.lost.clear();
  double lost_mass = 0.0;
  for (const std::string& part : processes.all_gather(mine.take())) {
    ByteReader in(part, "lost points of another process");
    const auto theirs = in.get<std::vector<std::pair<Index, Vec3>>>();
    result.lost.insert(result.lost.end(), theirs.begin(), theirs.end());
    lost_mass += in.get<double>();
  }
  // Whether they are removed is the policy's: counted where the serial run counts them.
  if (!result.lost.empty() && model_.spec.numerics.lost_points == spec::LostPointPolicy::Remove) {
    model_.lost_mass += lost_mass;
    model_.lost_points += static_cast<Index>(result.lost.size());
  }
}

}  // namespace geompm

namespace geompm {

std::vector<Vec3> StepSolver::move_mesh(const Vector& nodal_du, StepResult& result) {
  std::vector<Vec3> before = model_.mesh.nodes;
  const std::vector<Index>& active = grid_.node_to_active();
  const int dim = grid_.dim();
  model_.fem->move_nodes(model_.mesh, [&](Index a) {
    Vec3 d = Vec3::Zero();
    for (int i = 0; i < dim; ++i) d(i) = nodal_du(active[a] * dim + i);
    return d;
  });
  relaxation_->relax(model_.mesh);
  std::vector<char> mpm(model_.fem->fem_cell().size());
  for (std::size_t c = 0; c < mpm.size(); ++c) mpm[c] = !model_.fem->fem_cell()[c];
  result.mesh_quality = mesh_quality(model_.mesh, mpm);
  model_.locator = std::make_unique<PointLocator>(model_.mesh);
  return before;
}

}  // namespace geompm

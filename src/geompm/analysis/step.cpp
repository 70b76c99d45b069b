#include "geompm/analysis/step.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <unordered_map>

#include "geompm/analysis/linear_solver_hints.hpp"
#include "geompm/boundary/contact_hold.hpp"
#include "geompm/physics/gimp_weights.hpp"
#include "geompm/physics/newmark.hpp"

namespace geompm {

GridSettings grid_settings(const Model& model) {
  GridSettings s;
  s.kinematics = model.kinematics();
  s.empty_cell_modulus = model.spec.numerics.empty_cell_stiffness * model.largest_modulus();
  s.sparse_node_modulus = model.spec.numerics.sparse_node_stiffness * model.largest_modulus();
  s.sparse_node_fill = model.spec.numerics.sparse_node_fill;
  s.ghost_penalty = model.spec.numerics.ghost_penalty;
  s.ghost_penalty_fill = model.spec.numerics.ghost_penalty_fill;
  s.buffer_layers = model.spec.numerics.buffer_layers;
  s.mixed_field_pressure = model.spec.numerics.mixed_field_pressure;
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
  for (const auto& material : model.spec.materials) {
    const auto formulation = material.formulation.value_or(model.spec.numerics.formulation);
    const bool mixed = formulation == spec::Formulation::Mixed;
    s.mixed.push_back(mixed);
    s.volume_average.push_back(formulation == spec::Formulation::FBar ||
                               (mixed && model.spec.numerics.mixed_volume_average));
  }
  return s;
}

namespace {

// The Lagrangian phase as a nonlinear problem in the free displacement increments: residual
// R = f_ext - f_int - M a (seed eq. 6) with a from Newmark (eq. 8) in dynamics.
class LagrangianProblem final : public NonlinearProblem {
 public:
  LagrangianProblem(GridSystem& grid, const MaterialPoints& points, const Vector& f_ext, Vector& du,
                    bool dynamic, const Newmark& newmark)
      : grid_(grid), points_(points), f_ext_(f_ext), du_(du), dynamic_(dynamic), newmark_(newmark) {
    // Positions of the diagonal entries, to add the inertia term M / (beta dt^2).
    const SparseMatrix& pattern = grid.pattern();
    diagonal_.resize(pattern.cols());
    const auto& free = grid.free_index();
    grid_dof_.assign(pattern.cols(), -1);
    for (Index d = 0; d < static_cast<Index>(free.size()); ++d)
      if (free[d] >= 0) grid_dof_[free[d]] = d;
    for (Index j = 0; j < pattern.cols(); ++j)
      for (int at = pattern.outerIndexPtr()[j]; at < pattern.outerIndexPtr()[j + 1]; ++at)
        if (pattern.innerIndexPtr()[at] == j) diagonal_[j] = at;
  }

  bool evaluate(const Vector& x, Vector& residual, double& force_scale,
                SparseMatrix* tangent) override {
    scatter(x);
    largest_dof_ = -1;
    if (!grid_.internal_force(points_, du_, f_int_, tangent)) return false;
    inertia_ = Vector::Zero(du_.size());
    if (dynamic_)
      inertia_ = grid_.mass().cwiseProduct(
          newmark_.acceleration(du_, grid_.velocity(), grid_.acceleration()));
    const Vector r = f_ext_ - f_int_ - inertia_;
    residual.resize(x.size());
    const auto& free = grid_.free_index();
    for (Index d = 0; d < static_cast<Index>(free.size()); ++d)
      if (free[d] >= 0) {
        residual(free[d]) = r(d);
        if (largest_dof_ < 0 || std::abs(r(d)) > std::abs(r(largest_dof_))) largest_dof_ = d;
      }
    largest_value_ = largest_dof_ >= 0 ? r(largest_dof_) : 0.0;
    // The forces in play; in dynamics also the momentum rate M v / dt, so that a body moving
    // freely without loads is measured against its own motion, not against round-off.
    force_scale = std::max({f_ext_.norm(), f_int_.norm(), inertia_.norm()});
    if (dynamic_)
      force_scale =
          std::max(force_scale, grid_.mass().cwiseProduct(grid_.velocity()).norm() / newmark_.dt);
    if (tangent && dynamic_) {
      double* values = tangent->valuePtr();
      for (Index d = 0; d < static_cast<Index>(free.size()); ++d)
        if (free[d] >= 0) values[diagonal_[free[d]]] += newmark_.mass_factor() * grid_.mass()(d);
    }
    return true;
  }

  double increment_norm(const Vector& x) const override {
    // Free unknowns from x, constrained ones (fixed: zero) from du_.
    double sum = x.squaredNorm();
    const auto& free = grid_.free_index();
    for (Index d = 0; d < static_cast<Index>(free.size()); ++d)
      if (free[d] < 0) sum += du_(d) * du_(d);
    return std::sqrt(sum);
  }

  /// Holds the branches of switches outside the material (contact) that the accepted iterate
  /// took, through `hold` (StepSolver::hold_footing_contacts).
  void iterate_accepted() override {
    if (hold) hold();
  }
  std::function<void()> hold;

  /// The points whose update returned them plastically at the last evaluation, and how many
  /// changed between elastic and plastic since the last call (newton.csv). A switching point
  /// changes the branch of the return, and with it the tangent, between iterates.
  ActiveSet active_set() override {
    const std::vector<char>& plastic = grid_.plastic_points();
    ActiveSet set{0, last_plastic_.size() == plastic.size() ? 0 : -1};
    for (std::size_t p = 0; p < plastic.size(); ++p) {
      set.size += plastic[p];
      if (set.changed >= 0) set.changed += plastic[p] != last_plastic_[p];
    }
    last_plastic_ = plastic;
    return set;
  }

  const Vector& internal_force() const { return f_int_; }
  /// The grid unknown with the largest out-of-balance force at the last admissible evaluation
  /// (-1 if the last evaluation turned a point inside out), and that force.
  Index largest_residual_unknown() const override { return largest_dof_; }
  Index problem_unknown(Index free) const override { return grid_dof_[free]; }
  double largest_residual_value() const { return largest_value_; }
  std::string inadmissible_reason() const override {
    return grid_.inadmissible_by_stress_update()
               ? "inadmissible stress (a point's stress update did not converge)"
               : NonlinearProblem::inadmissible_reason();
  }
  const Vector& inertia() const { return inertia_; }

 private:
  void scatter(const Vector& x) {
    const auto& free = grid_.free_index();
    for (Index d = 0; d < static_cast<Index>(free.size()); ++d)
      if (free[d] >= 0) du_(d) = x(free[d]);
  }

  GridSystem& grid_;
  const MaterialPoints& points_;
  const Vector& f_ext_;
  Vector& du_;
  bool dynamic_;
  Newmark newmark_;
  std::vector<int> diagonal_;
  std::vector<Index> grid_dof_;  // free unknown -> grid dof (inverse of grid.free_index())
  Vector f_int_, inertia_;
  Index largest_dof_ = -1;
  double largest_value_ = 0.0;
  std::vector<char> last_plastic_;
};

// A grid unknown as the mesh node it belongs to and what it is: displacement component 0..2
// (x, y, z) or 3, the pressure (displacements first, then the pressures: theory eq. 11.6).
UnknownAt unknown_at(const GridSystem& grid, Index dof) {
  const int dim = grid.dim();
  const Index displacements = static_cast<Index>(grid.active_nodes().size()) * dim;
  if (dof >= displacements) return {grid.active_nodes()[dof - displacements], UnknownAt::kPressure};
  return {grid.active_nodes()[dof / dim], static_cast<int>(dof % dim)};
}

// Where a step that did not converge is out of balance most: the unknown, its node and the
// force, so that a user can see which part of the model holds Newton back.
std::string out_of_balance(const GridSystem& grid, const Mesh& mesh, Index dof, double value) {
  const UnknownAt u = unknown_at(grid, dof);
  const Vec3& x = mesh.nodes[u.node];
  const std::string at = grid.dim() == 3
                             ? fmt::format("({:.4g}, {:.4g}, {:.4g})", x.x(), x.y(), x.z())
                             : fmt::format("({:.4g}, {:.4g})", x.x(), x.y());
  if (u.unknown == UnknownAt::kPressure)
    return fmt::format("largest residual in the pressure equation of node {} at {}", u.node, at);
  return fmt::format("largest out-of-balance force {:.3g} in {} at node {} {}", value,
                     "xyz"[u.unknown], u.node, at);
}

}  // namespace

StepSolver::StepSolver(Model& model, LinearSolver& solver)
    : model_(model),
      solver_(solver),
      grid_(model.mesh, model.topology, model.material_pointers(), grid_settings(model)) {}

void StepSolver::prescribe_point_motions(const PhaseContext& phase, double t0, double t1,
                                         std::vector<Vec3>& prescribed) {
  prescribed.clear();
  if (phase.motions.empty()) return;
  const MaterialPoints& points = model_.points;
  const Index n = points.size();
  std::vector<double> stiffness(n, 0.0);
  std::vector<Vec3> target(n, Vec3::Zero());
  std::vector<unsigned char> mask(n, 0);
  for (const auto& motion : phase.motions) {
    // Target: the prescribed displacement since the phase start at t1, so that the error of a
    // step is corrected in the next one rather than accumulated.
    const Vec3 increment = phase.motion_increment(motion, t0, t1);
    prescribed.push_back(motion.done + increment);
    for (Index p = 0; p < n; ++p) {
      if (!(points.sets[p] >> motion.set & 1u)) continue;
      const double h = grid_.cell_size(p);
      // Stiffness far above the point's own: k = alpha E V / h^2 with alpha = 1e4, so the
      // motion is met to about 1e-4 of the deformation without a user parameter.
      stiffness[p] = 1e4 * model_.materials[points.material[p]]->reference_modulus() *
                     points.volume[p] / (h * h);
      for (int i = 0; i < grid_.dim(); ++i)
        if (!std::isnan(increment(i))) {
          mask[p] |= static_cast<unsigned char>(1u << i);
          target[p](i) = prescribed.back()(i) - points.phase_displacement[p](i);
        }
    }
  }
  grid_.set_point_targets(std::move(stiffness), std::move(target), std::move(mask));
}

// The rigid footings of a step (docs/theory.md §13): each footing's displacement and pose at the
// end of the step, the points that may touch it with what the contact law needs of them, and,
// after convergence, the points touching it with the anchors they used.
struct StepSolver::FootingStep {
  std::vector<Vec3> displacement;
  std::vector<FootingPose> pose;
  std::vector<std::vector<std::pair<Index, FootingContactPoint>>> points;
  std::vector<std::vector<int>> slot;  // per footing and point: its entry in `points`, or -1
  std::vector<std::unordered_map<Index, Vec3>> touching;  // point id -> anchor, per footing
  /// Per footing and candidate: pressed against the base at the contact law's last evaluation.
  std::vector<std::vector<char>> pressed;
  std::vector<ContactHold> hold;  // per footing: the candidates held in contact (eqs. 13.8-9)
  std::vector<Vec3> offset;       // per point: from the point to the top of its domain
};

void StepSolver::prepare_footings(const PhaseContext& phase, double t0, double t1,
                                  FootingStep& step) {
  if (phase.footings.empty()) return;
  const MaterialPoints& points = model_.points;
  const Index n = points.size();
  const int dim = grid_.dim(), v = dim - 1;
  const bool axisymmetric = model_.kinematics() == Kinematics::Axisymmetric;
  std::vector<char> acts(n, 0);
  std::vector<Vec3> offset(n, Vec3::Zero());
  for (Index p = 0; p < n; ++p) {
    // The footing touches a point at the top of its domain: the image of the seeded domain's
    // top under the point's F (eq. 13.1), carried by the step's deformation within the step.
    offset[p] = points.domain_deformation(p, dim) * points.initial_top_offset[p];
    for (int i = dim; i < 3; ++i) offset[p](i) = 0.0;
  }
  for (const RigidFooting& footing : phase.footings) {
    const Vec3 d = footing.displacement(t0, t1);
    const FootingPose pose = footing.pose(d);
    std::vector<char> in_body(model_.spec.bodies.size(), footing.spec().bodies.empty());
    for (const std::string& body : footing.spec().bodies)
      for (std::size_t b = 0; b < in_body.size(); ++b)
        if (model_.spec.bodies[b].name == body) in_body[b] = 1;
    std::vector<std::pair<Index, FootingContactPoint>> candidates;
    std::vector<int> slot(n, -1);
    for (Index p = 0; p < n; ++p) {
      if (!in_body[points.body[p]]) continue;
      // Its horizontal extent: the cpGIMP half-lengths (eq. 9.4) at the start of the step.
      Vec3 half = particle_half_lengths(points.initial_half_size[p],
                                        points.domain_deformation(p, dim), dim);
      half(v) = 0.0;
      const Vec3 top = points.position[p] + offset[p];
      // A point may touch the base in this step if its domain, grown by a cell, reaches it.
      const double reach = grid_.cell_size(p);
      bool near = top(v) > pose.base - reach;
      for (int t = 0; t < v; ++t)
        near = near && top(t) + half(t) > pose.low(t) - reach &&
               top(t) - half(t) < pose.high(t) + reach;
      if (!near) continue;
      FootingContactPoint c;
      c.position = top;
      c.half = half;
      // kappa = factor x E / h by default (eq. 13.7): the point's stiffness over its cell size.
      c.kappa = footing.spec().penalty.value_or(
          footing.spec().penalty_factor *
          model_.materials[points.material[p]]->reference_modulus() / reach);
      c.rough = footing.rough();
      // A point pressed against the base at the end of the last step stays in contact in both
      // directions through this step's iterations (eq. 13.8). A rough one sticks where it was
      // first touched: where its path met the base in the step of its first contact (eq. 13.4a),
      // from its position and gap at the start of that step.
      const auto anchor = footing.anchor(points.id[p]);
      c.bilateral = anchor.has_value();
      c.anchored = anchor.has_value();
      c.anchor = anchor ? *anchor : Vec3(top - footing.done());
      c.anchor(v) = 0.0;
      c.start_gap = top(v) - footing.pose(footing.done()).base;
      slot[p] = static_cast<int>(candidates.size());
      candidates.emplace_back(p, c);
      acts[p] = 1;
    }
    std::vector<char> held;
    for (const auto& candidate : candidates) held.push_back(candidate.second.bilateral);
    step.pressed.emplace_back(candidates.size(), 0);
    step.hold.emplace_back(std::move(held));
    step.displacement.push_back(d);
    step.pose.push_back(pose);
    step.points.push_back(std::move(candidates));
    step.slot.push_back(std::move(slot));
  }
  step.offset = offset;
  grid_.set_point_force_law(std::move(acts), std::move(offset),
                            [&step, dim, axisymmetric](Index p, const Vec3& u, Vec3& f, Mat3& K) {
                              f.setZero();
                              K.setZero();
                              for (std::size_t k = 0; k < step.pose.size(); ++k)
                                if (const int at = step.slot[k][p]; at >= 0) {
                                  const FootingContactForce c =
                                      footing_contact(step.pose[k], step.points[k][at].second, u,
                                                      dim, axisymmetric);
                                  // Each point is evaluated by one thread only.
                                  step.pressed[k][at] = c.on_base && c.penetration > 0.0;
                                  f += c.force;
                                  K += c.stiffness;
                                }
                            });
}

void StepSolver::hold_footing_contacts(FootingStep& step, bool restart) {
  // After an accepted Newton iterate, or before a new solve of the step: the points the contact
  // law holds in both directions (ContactHold, docs/theory.md §13). At the iterate a newly held
  // point touches, so the residual Newton has there does not change.
  for (std::size_t k = 0; k < step.points.size(); ++k) {
    ContactHold& hold = step.hold[k];
    if (restart)
      hold.restart();
    else
      hold.accept(step.pressed[k]);
    for (std::size_t at = 0; at < hold.size(); ++at)
      step.points[k][at].second.bilateral = hold.held(at);
  }
}

void StepSolver::footing_reactions(PhaseContext& phase, FootingStep& step, StepResult& result) {
  // At the converged increment (before the points move): the force each footing exerts on the
  // soil, and the points touching it, which keep (or take) their anchors.
  const MaterialPoints& points = model_.points;
  const int dim = grid_.dim();
  const bool axisymmetric = model_.kinematics() == Kinematics::Axisymmetric;
  auto& touching = step.touching;
  touching.assign(phase.footings.size(), {});
  for (std::size_t k = 0; k < phase.footings.size(); ++k) {
    Vec3 force = Vec3::Zero();
    for (const auto& [p, point] : step.points[k]) {
      const Vec3 u = grid_.interpolate_at(points, p, step.offset[p], result.displacement);
      const FootingContactForce c = footing_contact(step.pose[k], point, u, dim, axisymmetric);
      force -= c.force;
      if (c.on_base && c.penetration > 0.0) touching[k][points.id[p]] = c.stuck_at;
    }
    result.footing_reactions.try_emplace(phase.footings[k].name(), Vec3::Zero()).first->second +=
        force;
  }
}

namespace {
// `later` with `earlier` in front, `earlier` padded with `pad` to `size` entries.
template <typename T>
void put_in_front(std::vector<T>& later, std::vector<T> earlier, std::size_t size, T pad = T{}) {
  if (earlier.size() < size) earlier.resize(size, pad);
  earlier.insert(earlier.end(), later.begin(), later.end());
  later = std::move(earlier);
}

// A Newton solve that followed a failed one in the same step, with the failed one's iterations
// in front: the counts include both, and the log (newton.csv) shows both in turn. The log pairs
// residual k with corrections[k - 1] and largest_correction[k - 1] (the correction that led to
// it) and tangent_errors[k], so
// those are padded to the failed attempt's residuals (a zero where the second attempt starts). A
// failed attempt that ended on an inadmissible iterate has one correction more than it logged
// residuals after the first (the one that led there): it is dropped, so that the second attempt's
// first row shows no correction.
NewtonResult after_attempt(const NewtonResult& failed, NewtonResult second) {
  const std::size_t n = failed.residuals.size();
  second.iterations += failed.iterations;
  second.halvings += failed.halvings;
  second.searches += failed.searches;
  second.linear_iterations += failed.linear_iterations;
  put_in_front(second.residuals, failed.residuals, n);
  put_in_front(second.largest, failed.largest, n);
  put_in_front(second.active, failed.active, n);
  // Per correction: the failed attempt's logged ones only, padded to its residuals.
  const auto logged = [n](auto per_correction) {
    per_correction.resize(std::min(per_correction.size(), n > 0 ? n - 1 : 0));
    return per_correction;
  };
  put_in_front(second.corrections, logged(failed.corrections), n);
  put_in_front(second.largest_correction, logged(failed.largest_correction), n, Index{-1});
  if (!second.tangent_errors.empty() || !failed.tangent_errors.empty())
    put_in_front(second.tangent_errors, failed.tangent_errors, n);
  return second;
}

// The unknown's entry in last_rate_: dim displacements, then the pressure, per mesh node.
std::size_t rate_index(const UnknownAt& at, int dim) {
  return static_cast<std::size_t>(at.node) * (dim + 1) +
         (at.unknown == UnknownAt::kPressure ? dim : at.unknown);
}
}  // namespace

bool StepSolver::extrapolated_start(double dt, Vector& x) const {
  if (last_rate_.empty()) return false;
  const auto& free = grid_.free_index();
  bool any = false;
  for (Index d = 0; d < static_cast<Index>(free.size()); ++d)
    if (free[d] >= 0) {
      const UnknownAt at = unknown_at(grid_, d);
      const double rate = last_rate_[rate_index(at, grid_.dim())];
      x(free[d]) = rate * dt;
      any = any || rate != 0.0;
    }
  return any;
}

void StepSolver::remember_increment(const Vector& du, double dt) {
  last_rate_.assign(model_.mesh.nodes.size() * (grid_.dim() + 1), 0.0);
  for (Index d = 0; d < du.size(); ++d)
    last_rate_[rate_index(unknown_at(grid_, d), grid_.dim())] = du(d) / dt;
}

StepResult StepSolver::advance(PhaseContext& phase, double t0, double dt) {
  StepResult result;
  MaterialPoints& points = model_.points;
  const int dim = grid_.dim();
  const double t1 = t0 + dt;
  const bool dynamic = !phase.spec->dynamics.quasi_static;

  // --- phase 1: initialise --------------------------------------------------------------
  grid_.initialise(points);
  const Index n_dofs = grid_.num_dofs();
  const auto& node_to_active = grid_.node_to_active();

  result.gravity = phase.gravity(t1);
  std::vector<PointSetForce> forces;
  for (const auto& load : phase.loads) forces.push_back({load.set, phase.load(load, t1)});
  const Vector f_ext = grid_.external_force(points, result.gravity, forces);

  // Prescribed motions of point sets: penalty springs on the points (docs/theory.md §5).
  std::vector<Vec3> prescribed;
  prescribe_point_motions(phase, t0, t1, prescribed);
  // Rigid footings: penalty contact at the points (docs/theory.md §13).
  FootingStep footings;
  prepare_footings(phase, t0, t1, footings);

  // Fixities of grid nodes.
  result.constrained.assign(n_dofs, 0);
  Vector du = Vector::Zero(n_dofs);
  for (const auto& fixity : phase.fixities)
    for (Index node : fixity.nodes) {
      const Index n = node_to_active[node];
      if (n < 0) continue;
      for (int i = 0; i < dim; ++i)
        if (fixity.components[i]) result.constrained[n * dim + i] = 1;
    }
  // Prescribed motion of grid nodes (docs/theory.md §5.3): constrained unknowns with a non-zero
  // increment, set before Newton. Newton solves for the free unknowns only and never changes
  // these, so every residual it evaluates sees them. On a node also fixed, the motion wins.
  std::vector<Vec3> grid_increments;
  for (const auto& motion : phase.grid_motions) {
    grid_increments.push_back(motion.increment(t0, t1));
    for (Index node : motion.nodes) {
      const Index n = node_to_active[node];
      if (n < 0) continue;
      for (int i = 0; i < dim; ++i)
        if (!std::isnan(grid_increments.back()(i))) {
          result.constrained[n * dim + i] = 1;
          du(n * dim + i) = grid_increments.back()(i);
        }
    }
  }
  grid_.set_constraints(result.constrained);

  // --- phase 2: Lagrangian (Newton) -------------------------------------------------------
  Newmark newmark{phase.spec->dynamics.beta, phase.spec->dynamics.gamma, dt};
  LagrangianProblem problem(grid_, points, f_ext, du, dynamic, newmark);
  if (!phase.footings.empty())
    problem.hold = [&footings] { hold_footing_contacts(footings, false); };
  NewtonSettings settings;
  settings.max_iterations = phase.spec->newton.max_iterations;
  settings.residual_tolerance = phase.spec->newton.residual_tolerance;
  settings.displacement_tolerance = phase.spec->newton.displacement_tolerance;
  settings.max_halvings = phase.spec->newton.line_search;
  settings.energy_search = phase.spec->newton.energy_line_search;
  settings.tangent_check = phase.spec->newton.tangent_check;
  // Newton starts from a zero increment, or from the last step's extrapolated: the plastic zone
  // and its flow are then in place from the first iterate, so fewer points switch between
  // elastic and plastic in the iterations. Where that start fails (an inadmissible iterate, or
  // Newton cycling between the plastic states of a few points), the step is solved again from
  // zero, whose first iterate is elastic, before it is cut back; both attempts are counted.
  // The extrapolated start gets half of the iterations (or `extrapolated_patience`, where the zero
  // start is the worse bet: theory §4.5), and more only while it converges
  // superlinearly (each residual a tenth of the one before or less): one that has not reached
  // Newton's quadratic regime by then is not the quick start it is meant to be, and the zero
  // start still gets all of them; one that has would throw away an almost converged iterate.
  Vector x = Vector::Zero(grid_.num_free());
  const bool extrapolated = phase.spec->newton.extrapolate && extrapolated_start(dt, x);
  NewtonSettings first = settings;
  if (extrapolated) {
    const int patience = phase.spec->newton.extrapolated_patience;
    first.patience = patience > 0 ? patience : std::max(1, settings.max_iterations / 2);
  }
  // The step's pattern and unknowns, for the linear solver; a retry analyses again, as a direct
  // solver's symbolic analysis takes the values of the first matrix after it (UMFPACK's).
  const LinearSolverHints hints = linear_solver_hints(grid_, model_.mesh.nodes);
  solver_.analyse(grid_.pattern(), hints);
  result.newton = solve_newton(problem, solver_, first, x, grid_.tangent_storage());
  if (extrapolated && !result.newton.converged) {
    x.setZero();
    hold_footing_contacts(footings, true);
    solver_.analyse(grid_.pattern(), hints);
    NewtonResult from_zero = solve_newton(problem, solver_, settings, x, grid_.tangent_storage());
    result.newton = after_attempt(result.newton, std::move(from_zero));
  }
  for (const Index dof : result.newton.largest)
    result.largest_residual.push_back(dof >= 0 ? unknown_at(grid_, dof) : UnknownAt{});
  for (const Index dof : result.newton.largest_correction)
    result.largest_correction.push_back(dof >= 0 ? unknown_at(grid_, dof) : UnknownAt{});
  if (!result.newton.converged) {
    if (const Index p = grid_.inadmissible_point();
        result.newton.inadmissible && p >= 0 && p < points.size()) {
      const Vec3& x = points.position[p];
      result.newton.failure +=
          grid_.dim() == 3
              ? fmt::format("; material point {} at ({:.4g}, {:.4g}, {:.4g})", points.id[p], x.x(),
                            x.y(), x.z())
              : fmt::format("; material point {} at ({:.4g}, {:.4g})", points.id[p], x.x(), x.y());
    }
    if (problem.largest_residual_unknown() >= 0)
      result.newton.failure +=
          "; " + out_of_balance(grid_, model_.mesh, problem.largest_residual_unknown(),
                                problem.largest_residual_value());
    return result;
  }
  result.converged = true;

  // --- phase 3: convect ---------------------------------------------------------------------
  result.displacement = du;
  if (phase.spec->newton.extrapolate) remember_increment(du, dt);
  if (dynamic) {
    result.acceleration = newmark.acceleration(du, grid_.velocity(), grid_.acceleration());
    result.velocity = newmark.velocity(grid_.velocity(), grid_.acceleration(), result.acceleration);
  } else {
    result.acceleration = Vector::Zero(n_dofs);
    result.velocity = du / dt;
  }
  result.reaction = problem.internal_force() + problem.inertia() - f_ext;
  for (std::size_t m = 0; m < phase.motions.size(); ++m) {
    Vec3 force = Vec3::Zero();
    for (Index p = 0; p < points.size(); ++p)
      if (points.sets[p] >> phase.motions[m].set & 1u) force += grid_.point_reactions()[p];
    result.set_reactions.try_emplace(phase.motions[m].set, Vec3::Zero()).first->second += force;
  }
  if (!phase.footings.empty()) footing_reactions(phase, footings, result);
  convect_and_relocate(result, dt, dynamic);
  if (result.lost.empty() || model_.spec.numerics.lost_points == spec::LostPointPolicy::Remove) {
    for (std::size_t m = 0; m < phase.motions.size(); ++m) {
      const Vec3 reached = prescribed[m];
      for (int i = 0; i < 3; ++i)
        if (!std::isnan(reached(i))) phase.motions[m].done(i) = reached(i);
    }
    for (std::size_t k = 0; k < phase.footings.size(); ++k) {
      RigidFooting& footing = phase.footings[k];
      Vec3& done =
          model_.footing_displacement.try_emplace(footing.name(), Vec3::Zero()).first->second;
      done += footings.displacement[k] - footing.done();
      footing.commit(footings.displacement[k], std::move(footings.touching[k]));
    }
    for (std::size_t m = 0; m < phase.grid_motions.size(); ++m) {
      Vec3& done = model_.grid_displacement.try_emplace(phase.grid_motions[m].name, Vec3::Zero())
                       .first->second;
      for (int i = 0; i < 3; ++i)
        if (!std::isnan(grid_increments[m](i))) done(i) += grid_increments[m](i);
    }
  }
  return result;
}

void StepSolver::convect_and_relocate(StepResult& result, double dt, bool dynamic) {
  MaterialPoints& points = model_.points;
  const Index n = points.size();
  // Where each point goes, found before anything is committed: under the "stop" policy a point
  // that leaves the mesh stops the run with the points still in the last converged state.
  std::vector<Location> found(n);
  std::vector<Vec3> destination(n);
  std::vector<char> lost(n, 0);
#pragma omp parallel for schedule(dynamic, 1024) if (n > 4096)
  for (Index p = 0; p < n; ++p) {
    destination[p] = points.position[p] + grid_.interpolate(points, p, result.displacement);
    if (auto where = model_.locator->locate(destination[p], points.cell[p]))
      found[p] = *where;
    else
      lost[p] = 1;
  }
  for (Index p = 0; p < n; ++p)
    if (lost[p]) result.lost.emplace_back(points.id[p], destination[p]);
  if (!result.lost.empty() && model_.spec.numerics.lost_points == spec::LostPointPolicy::Stop)
    return;

  grid_.convect(points, result.displacement, result.velocity, result.acceleration, dt, dynamic);
  for (Index p = 0; p < n; ++p)
    if (!lost[p]) {
      points.cell[p] = found[p].cell;
      points.local[p] = found[p].xi;
    }
  if (!result.lost.empty()) {
    for (Index p = 0; p < n; ++p)
      if (lost[p]) {
        model_.lost_mass += points.mass[p];
        ++model_.lost_points;
      }
    points.remove(lost);
  }
}

}  // namespace geompm

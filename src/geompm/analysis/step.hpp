// One step of the implicit MPM (seed paper Fig. 1): initialise the grid from the points and set
// up the step's equations (its unknowns and contributions), solve the Lagrangian phase by Newton,
// convect the solution back to the points and relocate them. A step that does not converge leaves
// the points as they were, so the caller can cut the time step back and retry from the last
// converged state.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geompm/analysis/phase_context.hpp"
#include "geompm/coupling/mesh_quality.hpp"
#include "geompm/coupling/mesh_relaxation.hpp"
#include "geompm/levelset/zero_level_set.hpp"
#include "geompm/physics/grid_system.hpp"
#include "geompm/physics/pressure_field.hpp"
#include "geompm/physics/step_system.hpp"
#include "geompm/solver/linear_solver.hpp"
#include "geompm/solver/newton.hpp"
#include "geompm/structures/deformable_structure_term.hpp"
#include "geompm/structures/rigid_structure_term.hpp"

namespace geompm {

/// A grid unknown: the mesh node it belongs to and what it is (0, 1, 2: displacement in x, y,
/// z; kPressure: pressure); node -1 if not known.
struct UnknownAt {
  static constexpr int kPressure = 3;
  Index node = -1;
  int unknown = -1;
};

struct StepResult {
  bool converged = false;
  NewtonResult newton;
  /// Per entry of newton.residuals: the unknown with the largest residual (newton.csv).
  std::vector<UnknownAt> largest_residual;
  /// Per entry of newton.corrections: the unknown the correction moved most (newton.csv).
  std::vector<UnknownAt> largest_correction;
  /// The step's unknowns (valid until the next step), and the converged solution over them.
  const DofMap* dofs = nullptr;
  Vector displacement, velocity, acceleration;
  Vector reaction;  // f_int + M a - f_ext, non-zero at constrained unknowns
  /// Nodal pressures per active node of the mixed p-u formulation (empty without it).
  Vector nodal_pressure;
  std::map<int, Vec3> set_reactions;  // point-set bit -> force its prescribed motion exerts
  /// Structure -> what its drive exerts on it (docs/theory.md §17.4).
  std::map<std::string, DriveForces> structure_forces;
  Vec3 gravity = Vec3::Zero();
  std::vector<std::pair<Index, Vec3>> lost;  // points that left the mesh: id, position
  /// The bodies' boundary, the zero level set of the step's start carried by its displacement to
  /// its end, where the output writes it (writes_boundary); empty otherwise.
  std::vector<SurfaceFacet> boundary;
  /// With an FEM region: the MPM cells' shape after the mesh's relaxation (docs/theory.md §19.3).
  std::optional<MeshQuality> mesh_quality;
};

/// Whether the run writes the boundary (boundary.pvd): with ParaView output, in a model with
/// surface loads.
bool writes_boundary(const spec::Model& spec);

/// The grid's settings for a model: kinematics, interpolation, empty-cell stiffness, buffer
/// layers and, per material, the formulation and the mixed points' volume change.
/// The materials' moduli that scale the stiffness of empty cells are those every process's points
/// carry (`processes`, collective).
GridSettings grid_settings(const Model& model,
                           const Communicator& processes = serial_communicator());

class StepSolver {
 public:
  /// In a distributed run, pass its processes (collective): each holds only its own points.
  StepSolver(Model& model, LinearSolver& solver,
             const Communicator& processes = serial_communicator());

  /// Advances the model from phase time t0 by dt. If the step converges the points are updated
  /// (and points that left the mesh handled by the model's policy: result.lost lists them; under
  /// "stop" the points are NOT updated and the caller stops the run).
  /// `last_resort`: the step failed at the smallest allowed step; with newton.line_search not
  /// set its corrections are now halved where the residual grows (docs/theory.md §4.4).
  StepResult advance(PhaseContext& phase, double t0, double dt, bool last_resort = false);

  /// A distributed run: this process holds the points of the cells `cell_part` gives it
  /// (docs/architecture.md, "Distributed runs"); points that cross into another process's cell
  /// are sent to it after each step.
  void distribute(const Communicator& communicator, std::vector<int> cell_part);

  GridSystem& grid() { return grid_; }
  PressureField& pressure() { return pressure_; }
  const PressureField& pressure() const { return pressure_; }

  /// Forgets the last step's increment, so that the phase's first step does not extrapolate the
  /// previous phase's path (`newton: {predictor: extrapolated}`), and the last nodal pressure
  /// (`mixed_pressure_start: fitted`), so that it starts from its points' pressures.
  void start_phase() {
    last_rate_.clear();
    field_rate_.clear();
    pressure_.forget();
  }

  /// The last converged step's increment per unit time, per mesh node and unknown (for
  /// checkpoints).
  const std::vector<double>& last_rate() const { return last_rate_; }
  void set_last_rate(std::vector<double> rate) { last_rate_ = std::move(rate); }
  /// The same for the fields of no node (a structure's), by field name, per unknown.
  const std::map<std::string, std::vector<double>>& field_rate() const { return field_rate_; }
  void set_field_rate(std::map<std::string, std::vector<double>> rate) {
    field_rate_ = std::move(rate);
  }

 private:
  struct Step;
  void set_up(PhaseContext& phase, double t0, double dt, Step& step);
  void constrain(const PhaseContext& phase, double t0, double t1, Step& step) const;
  /// The increment the last converged step's rate gives over the phase's largest step (0 at a
  /// phase's first step): the scale of a cut-back step's corrections (docs/theory.md eq. 4.5).
  double full_step_increment(double max_step) const;
  bool solve(const PhaseContext& phase, double dt, bool last_resort, Step& step,
             StepResult& result);
  void finish(PhaseContext& phase, double dt, Step& step, StepResult& result);
  bool extrapolated_start(double dt, Vector& x) const;
  void remember_increment(const Vector& du, double dt);
  void convect_and_relocate(StepResult& result, double dt, bool dynamic);
  /// Distributed: every process's lost points in result.lost, so that all take the same
  /// decision; the model's lost mass counts them all.
  void share_lost_points(StepResult& result, const std::vector<char>& lost) const;
  void commit_motions(PhaseContext& phase, const Step& step);
  /// With an FEM region: moves its nodes by the converged increment, relaxes the MPM region's
  /// and finds the points' cells anew in the moved mesh (docs/theory.md §19.3). Returns the
  /// mesh's nodes before, to restore if the step is not kept.
  std::vector<Vec3> move_mesh(const Vector& nodal_du, StepResult& result);

  Model& model_;
  LinearSolver& solver_;
  GridSystem grid_;
  PressureField pressure_;
  std::unique_ptr<StepSystem> system_;          // the last step's equations
  std::unique_ptr<MeshRelaxation> relaxation_;  // with an FEM region
  std::vector<int> node_part_;  // distributed: per mesh node, the process owning its unknowns
  // The last converged step's increment per unit time, per mesh node and unknown (dim
  // displacements, then the pressure): Newton's first iterate with `predictor: extrapolated`.
  std::vector<double> last_rate_;
  std::map<std::string, std::vector<double>> field_rate_;  // of the fields of no node
};

}  // namespace geompm

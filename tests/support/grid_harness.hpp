// A step's equations assembled as analysis/step.cpp assembles them, for the unit tests of the
// physics: the grid of the step, its unknowns (StepSystem) and the contributions that follow
// from the grid settings alone (the material points, the empty cells, the sparse-node springs
// and the ghost penalty), plus prescribed-motion springs and a point force law where a test asks
// for them. Its calls follow the order of a step: initialise, the point terms, set_constraints,
// then evaluations.
#pragma once

#include <memory>
#include <vector>

#include "geompm/physics/body_loads.hpp"
#include "geompm/physics/empty_cell_stiffness.hpp"
#include "geompm/physics/ghost_penalty.hpp"
#include "geompm/physics/inertia.hpp"
#include "geompm/physics/point_integrator.hpp"
#include "geompm/physics/point_springs.hpp"
#include "geompm/physics/sparse_node_springs.hpp"
#include "geompm/physics/step_system.hpp"

namespace geompm::testing {

class GridHarness {
 public:
  GridHarness(const Mesh& mesh, const MeshTopology& topology,
              const std::vector<const Material*>& materials, const GridSettings& settings)
      : grid_(mesh, topology, materials, settings) {}

  void initialise(MaterialPoints& points) {
    points_ = &points;
    grid_.initialise(points);
    if (grid_.mixed()) pressure_.initialise(grid_, points);
    system_ = std::make_unique<StepSystem>(grid_);
    integrator_ = &system_->add(
        std::make_unique<PointIntegrator>(grid_, points, system_->dofs(), &pressure_));
    auto empty = std::make_unique<EmptyCellStiffness>(grid_, system_->dofs(), &pressure_);
    if (!empty->empty()) integrator_->add_cell_term(std::move(empty));
    for (auto* make : {&sparse_node_springs, &ghost_penalty_blocks}) {
      auto blocks = make(grid_, points);
      if (!blocks.empty())
        system_->add(std::make_unique<NodeBlocks>("blocks", std::move(blocks), system_->dofs(),
                                                  grid_.dim()));
    }
  }
  void set_point_targets(std::vector<double> stiffness, std::vector<Vec3> target,
                         std::vector<unsigned char> mask) {
    auto& springs = system_->add(std::make_unique<PointSprings>(
        grid_, *points_,
        PointTargets{std::move(stiffness), std::move(target), std::move(mask), {}}));
    integrator_->add_point_term(&springs);
  }
  /// Per unknown: 1 if constrained (its prescribed value 0).
  void set_constraints(const std::vector<char>& constrained) {
    for (Index d = 0; d < num_dofs(); ++d)
      if (constrained[d]) system_->dofs().constrain(d);
    system_->build_pattern();
  }

  /// f_int at du (every unknown) and, with K or `tangent`, the tangent at the free unknowns (in
  /// system().tangent(), and copied to K).
  bool internal_force(const MaterialPoints& /*points*/, const Vector& du, Vector& f,
                      SparseMatrix* K, bool tangent = false) {
    SystemForces forces;
    const bool admissible = system_->evaluate(du, forces, K != nullptr || tangent);
    f = forces.internal;
    if (K) *K = system_->tangent();
    return admissible;
  }
  bool commit_state(MaterialPoints& points, const Vector& du) {
    return integrator_->commit_state(points, du);
  }
  /// Commits the points' state at du and moves them with it (phase 3 of a step).
  void convect(MaterialPoints& points, const Vector& du, const Vector& velocity,
               const Vector& acceleration, double dt, bool dynamic) {
    integrator_->commit_state(points, du);
    const DofMap& dofs = system_->dofs();
    grid_.convect(points, displacement_block(dofs, du), displacement_block(dofs, velocity),
                  displacement_block(dofs, acceleration), dt, dynamic);
  }
  /// f_ext of gravity and point-set forces, per unknown.
  Vector external_force(const MaterialPoints& points, const Vec3& gravity,
                        const std::vector<PointSetForce>& forces) const {
    return BodyLoads(grid_, points, system_->dofs(), gravity, forces).force();
  }

  Index num_dofs() const { return system_->dofs().size(); }
  const std::vector<Index>& free_index() const { return system_->dofs().free_indices(); }
  Index pressure_dof(Index a) const {
    return system_->dofs().dof(pressure_field(system_->dofs()), a);
  }
  /// The lumped mass and the start velocity per unknown (the displacement field's).
  Vector mass() const {
    const DofMap& dofs = system_->dofs();
    Vector m = Vector::Zero(dofs.size());
    const int u = dofs.find("displacement");
    for (Index a = 0; a < static_cast<Index>(grid_.active_nodes().size()); ++a)
      for (int i = 0; i < grid_.dim(); ++i) m(dofs.dof(u, a, i)) = grid_.nodal_mass()(a);
    return m;
  }
  Vector velocity() const {
    return from_displacement_block(system_->dofs(), grid_.nodal_velocity());
  }
  int dim() const { return grid_.dim(); }
  const std::vector<Index>& active_nodes() const { return grid_.active_nodes(); }
  const std::vector<Index>& active_cells() const { return grid_.active_cells(); }
  Index inadmissible_point() const { return integrator_->inadmissible_point(); }
  bool inadmissible_by_stress_update() const {
    return integrator_->inadmissible_by_stress_update();
  }
  const GridSystem& grid() const { return grid_; }
  StepSystem& system() { return *system_; }

 private:
  GridSystem grid_;
  PressureField pressure_;
  MaterialPoints* points_ = nullptr;
  std::unique_ptr<StepSystem> system_;
  PointIntegrator* integrator_ = nullptr;
};

}  // namespace geompm::testing

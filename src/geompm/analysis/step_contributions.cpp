#include "geompm/analysis/step_contributions.hpp"

#include <cmath>

#include "geompm/contact/level_set_contact.hpp"
#include "geompm/core/error.hpp"
#include "geompm/core/expression.hpp"
#include "geompm/coupling/fem_region_term.hpp"
#include "geompm/levelset/surface_load.hpp"
#include "geompm/physics/body_loads.hpp"
#include "geompm/physics/empty_cell_stiffness.hpp"
#include "geompm/physics/ghost_penalty.hpp"
#include "geompm/physics/inertia.hpp"
#include "geompm/physics/point_integrator.hpp"
#include "geompm/physics/point_springs.hpp"
#include "geompm/physics/sparse_node_springs.hpp"
#include "geompm/structures/deformable_structure_term.hpp"
#include "geompm/structures/rigid_structure_term.hpp"

namespace geompm {
namespace {

void material_points(StepSystem& system, StepContext& c) {
  system.add(std::make_unique<PointIntegrator>(c.grid, c.model.points, system.dofs(), &c.pressure));
}

void fem_region(StepSystem& system, StepContext& c) {
  // The FEM cells' Gauss points and their self-weight (docs/theory.md §19).
  if (c.model.fem)
    system.add(std::make_unique<FemRegionTerm>(*c.model.fem, c.grid, system.dofs(),
                                               c.phase.gravity(c.t1)));
}

void empty_cells(StepSystem& system, StepContext& c) {
  auto empty = std::make_unique<EmptyCellStiffness>(c.grid, system.dofs(), &c.pressure);
  if (!empty->empty()) system.find<PointIntegrator>()->add_cell_term(std::move(empty));
}

void sparse_node_springs(StepSystem& system, StepContext& c) {
  auto blocks = sparse_node_springs(c.grid, c.model.points);
  if (!blocks.empty())
    system.add(std::make_unique<NodeBlocks>("sparse-node springs", std::move(blocks), system.dofs(),
                                            c.grid.dim()));
}

void ghost_penalty(StepSystem& system, StepContext& c) {
  auto blocks = ghost_penalty_blocks(c.grid, c.model.points);
  if (!blocks.empty())
    system.add(std::make_unique<NodeBlocks>("ghost penalty", std::move(blocks), system.dofs(),
                                            c.grid.dim()));
}

void point_motions(StepSystem& system, StepContext& c) {
  // Prescribed motions of point sets: penalty springs on the points (docs/theory.md §5).
  if (c.phase.motions.empty()) return;
  const MaterialPoints& points = c.model.points;
  const Index n = points.size();
  PointTargets targets;
  targets.stiffness.assign(n, 0.0);
  targets.target.assign(n, Vec3::Zero());
  targets.mask.assign(n, 0);
  for (const auto& motion : c.phase.motions) {
    // Target: the prescribed displacement since the phase start at t1, so that the error of a
    // step is corrected in the next one rather than accumulated.
    const Vec3 increment = c.phase.motion_increment(motion, c.t0, c.t1);
    c.prescribed.push_back(motion.done + increment);
    targets.sets.push_back(motion.set);
    for (Index p = 0; p < n; ++p) {
      if (!(points.sets[p] >> motion.set & 1u)) continue;
      const double h = c.grid.cell_size(p);
      // Stiffness far above the point's own: k = alpha E V / h^2 with alpha = spring_ratio.
      targets.stiffness[p] = spring_ratio *
                             c.model.materials[points.material[p]]->reference_modulus() *
                             points.volume[p] / (h * h);
      for (int i = 0; i < c.grid.dim(); ++i)
        if (!std::isnan(increment(i))) {
          targets.mask[p] |= static_cast<unsigned char>(1u << i);
          targets.target[p](i) = c.prescribed.back()(i) - points.phase_displacement[p](i);
        }
    }
  }
  auto& springs = system.add(std::make_unique<PointSprings>(c.grid, points, std::move(targets)));
  system.find<PointIntegrator>()->add_point_term(&springs);
}

void body_loads(StepSystem& system, StepContext& c) {
  std::vector<PointSetForce> forces;
  for (const auto& load : c.phase.loads) forces.push_back({load.set, c.phase.load(load, c.t1)});
  system.add(std::make_unique<BodyLoads>(c.grid, c.model.points, system.dofs(),
                                         c.phase.gravity(c.t1), forces));
}

void structures(StepSystem& system, StepContext& c) {
  // Structures' self-weight, applied loads and, in dynamics, inertia (docs/theory.md §17); a
  // deformable structure's internal forces too (§17.7).
  const auto newmark = c.dynamic ? std::optional<Newmark>(c.newmark) : std::nullopt;
  for (std::size_t k = 0; k < c.model.structures.size(); ++k) {
    const StructureDrive& drive = c.phase.structure_drives[k];
    if (auto* rigid = dynamic_cast<RigidStructure*>(c.model.structures[k].get()))
      system.add(std::make_unique<RigidStructureTerm>(*rigid, system.dofs(), c.phase.gravity(c.t1),
                                                      drive.load(c.t1), newmark, c.t1 - c.t0));
    else if (auto* body = dynamic_cast<DeformableStructure*>(c.model.structures[k].get()))
      system.add(std::make_unique<DeformableStructureTerm>(
          *body, system.dofs(), c.phase.gravity(c.t1), drive.nodal_load(c.t1, body->num_nodes()),
          newmark, c.t1 - c.t0));
  }
}

void contacts(StepSystem& system, StepContext& c) {
  // Each structure's contact with the soil's level set (docs/theory.md §18), its multipliers
  // after the structures' unknowns.
  if (c.model.contacts.empty()) return;
  // The stiffest material the points carry, on every process's points.
  const double modulus = c.model.largest_modulus(c.grid.communicator());
  for (ContactPair& pair : c.model.contacts)
    if (pair.enabled)
      system.add(std::make_unique<LevelSetContact>(c.grid, c.model.points, *c.model.locator,
                                                   *c.model.structures[pair.structure], pair,
                                                   modulus, system.dofs()));
}

void surface_loads(StepSystem& system, StepContext& c) {
  // Pressures and tractions on the zero level set of the bodies' points at the step's start
  // (seed §3.5, docs/theory.md §16), at the step's end time t1 as point-set loads are.
  for (const spec::SurfaceLoad& load : c.phase.spec->surface_loads) {
    std::vector<char> bodies;
    if (!load.bodies.empty()) {
      bodies.assign(c.model.spec.bodies.size(), 0);
      for (const std::string& body : load.bodies)
        for (std::size_t b = 0; b < bodies.size(); ++b)
          if (c.model.spec.bodies[b].name == body) bodies[b] = 1;
    }
    FacetBox where;
    where.range = load.where;
    auto facets = zero_level_set(LevelSet(c.grid, c.model.points, std::move(bodies)), &where);
    if (facets.empty()) continue;
    const std::array<Expression, 3> value = {
        Expression(load.components[0], component_place(load.source, 0)),
        Expression(load.components[1], component_place(load.source, 1)),
        Expression(load.components[2], component_place(load.source, 2))};
    const double t = c.t1;
    system.add(std::make_unique<SurfaceLoad>(
        c.grid, system.dofs(), std::move(facets),
        load.pressure ? SurfaceLoad::Kind::Pressure : SurfaceLoad::Kind::Traction, load.following,
        [&](const Vec3& x) {
          return Vec3(value[0](x.x(), x.y(), x.z(), t), value[1](x.x(), x.y(), x.z(), t),
                      value[2](x.x(), x.y(), x.z(), t));
        }));
  }
}

void inertia(StepSystem& system, StepContext& c) {
  if (c.dynamic) system.add(std::make_unique<Inertia>(c.grid, system.dofs(), c.newmark));
}

// The terms of a step, in the order they are evaluated.
using Maker = void (*)(StepSystem&, StepContext&);
// Contact comes first: it adds its multipliers to the unknowns, which the others size their
// vectors by.
constexpr Maker makers[] = {
    contacts,      material_points, fem_region, empty_cells,   sparse_node_springs,
    ghost_penalty, point_motions,   body_loads, surface_loads, structures,
    inertia};

}  // namespace

void add_step_contributions(StepSystem& system, StepContext& context) {
  for (Maker make : makers) make(system, context);
}

}  // namespace geompm

#include "geompm/analysis/model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <limits>

#include "geompm/analysis/body_seeding.hpp"
#include "geompm/analysis/distribution.hpp"
#include "geompm/analysis/fem_region_seeding.hpp"
#include "geompm/analysis/geostatic_stress.hpp"
#include "geompm/analysis/initial_stress.hpp"
#include "geompm/analysis/material_formulation.hpp"
#include "geompm/analysis/model_size.hpp"
#include "geompm/analysis/region_test.hpp"
#include "geompm/boundary/fixities.hpp"
#include "geompm/boundary/grid_motions.hpp"
#include "geompm/core/agreement.hpp"
#include "geompm/core/byte_archive.hpp"
#include "geompm/core/error.hpp"
#include "geompm/core/expression.hpp"
#include "geompm/mesh/cell_geometry.hpp"
#include "geompm/mesh/gmsh_import.hpp"
#include "geompm/mesh/rectilinear_grid.hpp"
#include "geompm/mesh/structured_mesh.hpp"
#include "geompm/structures/structure_builder.hpp"

namespace geompm {

void Model::save_state(ByteWriter& out) const {
  save_state_before_gauss_points(out);
  if (fem) fem->gauss_points().save(out);  // last: its load() expects the end
}

void Model::save_state_before_gauss_points(ByteWriter& out) const {
  out.put(grid_displacement);
  out.put(lost_mass);
  out.put(lost_points);
  // The moved mesh and (save_state) the FEM region's Gauss points (docs/theory.md §19), only with
  // one, so that a model without keeps its checkpoint's layout.
  if (fem) out.put(mesh.nodes);
}

void Model::load_state(ByteReader& in) {
  in.get(grid_displacement);
  in.get(lost_mass);
  in.get(lost_points);
  if (fem) {
    in.get(mesh.nodes);
    fem->gauss_points().load(in);
    locator = std::make_unique<PointLocator>(mesh);
  }
  in.expect_end();
}

std::vector<const Material*> Model::material_pointers() const {
  std::vector<const Material*> out;
  for (const auto& m : materials) out.push_back(m.get());
  return out;
}

int Model::point_set_bit(const std::string& name) const {
  for (std::size_t k = 0; k < point_set_names.size(); ++k)
    if (point_set_names[k] == name) return static_cast<int>(k);
  return -1;
}

namespace {

/// The reference moduli of the materials some point of some process carries: a material only
/// listed (or whose points have all left the mesh) sets no scale.
std::vector<double> carried_moduli(const Model& model, const Communicator& processes) {
  std::vector<int> carried(model.materials.size(), 0);
  for (const Index m : model.points.material) carried[static_cast<std::size_t>(m)] = 1;
  processes.max(carried.data(), carried.size());
  std::vector<double> moduli;
  for (std::size_t m = 0; m < model.materials.size(); ++m)
    if (carried[m]) moduli.push_back(model.materials[m]->reference_modulus());
  return moduli;
}

}  // namespace

double Model::largest_modulus(const Communicator& processes) const {
  const std::vector<double> moduli = carried_moduli(*this, processes);
  return moduli.empty() ? 0.0 : *std::max_element(moduli.begin(), moduli.end());
}

double Model::softest_modulus(const Communicator& processes) const {
  const std::vector<double> moduli = carried_moduli(*this, processes);
  return moduli.empty() ? 0.0 : *std::min_element(moduli.begin(), moduli.end());
}

Index body_material_at(const spec::Model& spec, const spec::Body& body, double elevation) {
  std::string name = body.material;
  if (!body.layers.empty()) {
    name = body.layers.back().material;
    for (const spec::Layer& layer : body.layers)
      if (layer.bottom && elevation >= *layer.bottom) {
        name = layer.material;
        break;
      }
  }
  for (std::size_t m = 0; m < spec.materials.size(); ++m)
    if (spec.materials[m].name == name) return static_cast<Index>(m);
  throw std::logic_error("body '" + body.name + "' refers to an unknown material " + name);
}

namespace {

// The generator's cell type per rectangle from the regions that give one (regions' `cell`): the
// last region holding the rectangle's centre; the generator's own type elsewhere.
StructuredMeshSpec with_region_cell_types(const spec::Model& spec) {
  StructuredMeshSpec generate = *spec.mesh.generate;
  std::vector<std::pair<RegionTest, CellType>> typed;
  const Mesh no_mesh;
  for (const spec::MeshRegion& region : spec.regions) {
    if (!region.cell) continue;
    if (region.region.kind == spec::Region::Kind::Group)
      throw InputError(region.cell_source,
                       fmt::format("region '{}' gives a cell type but is a group of cells; a "
                                   "generated mesh is typed by shapes (box, polygon, circle)",
                                   region.name));
    typed.emplace_back(RegionTest(region.region, no_mesh, cell_dimension(generate.cell_type)),
                       *region.cell);
  }
  if (typed.empty()) return generate;
  const CellType base = generate.cell_type;
  generate.cell_type_at = [typed, base](const Vec3& centre) {
    CellType type = base;
    for (const auto& [test, cell] : typed)
      if (test.contains(centre, -1)) type = cell;
    return type;
  };
  return generate;
}

Mesh make_mesh(const spec::Model& spec) {
  const int dim = spatial_dimension(spec.kinematics);
  SourceLocation mesh_file = spec.mesh.source;  // errors in an imported file name the model too
  if (!spec.mesh.file.empty()) mesh_file.key_path += ".file";
  Mesh mesh;
  if (spec.mesh.generate) {
    try {
      mesh = generate_structured_mesh(with_region_cell_types(spec));
    } catch (const std::invalid_argument& e) {
      throw InputError(spec.mesh.source, e.what());
    }
  } else {
    try {
      mesh = read_gmsh_mesh(spec.mesh.file, dim);
    } catch (const InputError& e) {
      throw InputError(mesh_file, e.what());
    }
  }
  if (mesh.dim() != dim)
    throw InputError(spec.mesh.source,
                     fmt::format("the mesh is {}D ({} cells) but the analysis is {}", mesh.dim(),
                                 cell_type_names(mesh), to_string(spec.kinematics)));
  try {
    validate_mesh(mesh, spec.mesh.file.empty() ? "generated mesh" : spec.mesh.file);
  } catch (const InputError& e) {
    throw InputError(mesh_file, e.what());
  }
  if (spec.kinematics == Kinematics::Axisymmetric) {
    for (Index n = 0; n < mesh.num_nodes(); ++n)
      if (mesh.nodes[n].x() < -1e-12)
        throw InputError(spec.mesh.source,
                         fmt::format("axisymmetric meshes must lie in x >= 0 (x is the radius); "
                                     "node {} is at x = {}",
                                     n, mesh.nodes[n].x()));
  }
  return mesh;
}

// Node sets join the mesh's boundaries (node groups), so that everything naming a boundary can
// name them.
void add_node_sets(const spec::Model& spec, Mesh& mesh) {
  const int dim = mesh.dim();
  const double tol = node_tolerance(mesh);
  for (const auto& set : spec.node_sets) {
    if (mesh.node_groups.count(set.name))
      throw InputError(set.source, fmt::format("'{}' is a boundary of the mesh already; give the "
                                               "node set another name",
                                               set.name));
    std::vector<Index> nodes;
    for (Index n = 0; n < mesh.num_nodes(); ++n) {
      const Vec3& x = mesh.nodes[n];
      bool inside = true;
      for (int d = 0; d < dim; ++d)
        inside = inside && x(d) >= set.min(d) - tol && x(d) <= set.max(d) + tol;
      if (inside) nodes.push_back(n);
    }
    if (nodes.empty())
      throw InputError(set.source, fmt::format("node set '{}' holds no mesh node: no node lies in "
                                               "its box",
                                               set.name));
    mesh.node_groups[set.name] = std::move(nodes);
  }
}

void check_boundary(const Mesh& mesh, const std::string& boundary, const SourceLocation& source) {
  if (!boundary.empty() && !mesh.node_groups.count(boundary))
    throw InputError(source, fmt::format("the mesh has no boundary '{}'; its boundaries are: {}",
                                         boundary, group_names(mesh.node_groups)));
}

// Numerical options the mesh cannot carry.
void check_numerics_fit_mesh(const spec::Model& spec, const Mesh& mesh) {
  if (spec.numerics.interpolation == spec::Interpolation::Gimp) {
    // GIMP weights are tensor products along grid lines (docs/theory.md §9).
    std::string why;
    if (!find_rectilinear_grid(mesh, why))
      throw InputError(spec.numerics.interpolation_source,
                       fmt::format("gimp needs a rectilinear grid (axis-aligned quad4 or hex8 "
                                   "cells on complete grid lines, uniform or graded, as the "
                                   "built-in generator makes), but {}; use standard or ddmp",
                                   why));
  }
  if (!mesh.mixed()) return;
  // What reads the cells as one type: the wide stencils and the ghost penalty's faces.
  if (spec.numerics.interpolation != spec::Interpolation::Standard)
    throw InputError(spec.numerics.interpolation_source,
                     "ddmp and gimp need a mesh of one cell type, but the mesh mixes cell types; "
                     "use interpolation: standard");
  if (spec.numerics.ghost_penalty > 0.0)
    throw InputError(spec.mesh.source,
                     "numerics.ghost_penalty needs a mesh of one cell type (its faces between a "
                     "triangle and a quadrilateral are not penalised), but the mesh mixes cell "
                     "types; set ghost_penalty: 0 or use one cell type");
}

void create_materials(const spec::Model& spec, Model& model) {
  for (const auto& m : spec.materials) {
    try {
      model.materials.push_back(create_material(m.model, m.parameters));
    } catch (const ParameterError& e) {
      SourceLocation where = m.source;
      where.key_path += "." + e.key();
      throw InputError(where, e.what());
    }
  }
}

/// The box the mesh's nodes span, and a tolerance of coordinates relative to its size.
struct MeshBounds {
  Vec3 lo, hi;
  double tol = 0.0;
};

// Mesh bounds, to report bodies that stick out of the mesh.
MeshBounds mesh_bounds(const Mesh& mesh) {
  const int dim = mesh.dim();
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max()), hi = -lo;
  for (const auto& x : mesh.nodes) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  const double tol = 1e-9 * head_norm(hi - lo, dim);
  return {lo, hi, tol};
}

void check_body_inside_mesh(const spec::Body& body, const RegionTest& region,
                            const MeshBounds& mesh_box, int dim) {
  const Vec3& lo = mesh_box.lo;
  const Vec3& hi = mesh_box.hi;
  const double tol = mesh_box.tol;
  if (auto box = region.bounds()) {
    for (int d = 0; d < dim; ++d)
      if (box->first(d) < lo(d) - tol || box->second(d) > hi(d) + tol)
        throw InputError(
            body.region.source,
            fmt::format("body '{}' reaches outside the mesh: its region spans "
                        "[{}, {}] in {} but the mesh spans [{}, {}]",
                        body.name, box->first(d), box->second(d), "xyz"[d], lo(d), hi(d)));
  }
}

// Every body inside the mesh, before it is seeded.
void check_bodies_inside_mesh(const spec::Model& spec, const Mesh& mesh) {
  const int dim = mesh.dim();
  const MeshBounds mesh_box = mesh_bounds(mesh);
  for (const spec::Body& body : spec.bodies)
    check_body_inside_mesh(body, RegionTest(body.region, mesh, dim), mesh_box, dim);
}

// Point set k as bit k of each point's set mask: the points of its body (any, if it names
// none) in its region; of every process's points (collective), so that a set whose points all lie
// in another process's cells is no empty set.
void add_point_sets(const spec::Model& spec, Model& model, const Communicator& processes) {
  const Mesh& mesh = model.mesh;
  const int dim = mesh.dim();
  if (spec.point_sets.size() > 64)
    throw InputError(spec.point_sets[64].source, "at most 64 point sets are supported");
  for (std::size_t k = 0; k < spec.point_sets.size(); ++k) {
    const auto& set = spec.point_sets[k];
    model.point_set_names.push_back(set.name);
    RegionTest region(set.region, mesh, dim);
    Index body = -1;
    for (std::size_t b = 0; b < spec.bodies.size(); ++b)
      if (spec.bodies[b].name == set.body) body = static_cast<Index>(b);
    Index count = 0;
    for (Index p = 0; p < model.points.size(); ++p) {
      if (body >= 0 && model.points.body[p] != body) continue;
      if (!region.contains(model.points.position[p], model.points.cell[p])) continue;
      model.points.sets[p] |= std::uint64_t{1} << k;
      ++count;
    }
    if (processes.sum(count) == 0)
      throw InputError(set.source, fmt::format("point set '{}' holds no material point", set.name));
  }
}

// Fixities and grid motions are resolved again when their phase starts; resolving them here
// reports a plane with no node, or a node driven twice, before the run starts.
void check_boundaries(const spec::Model& spec, const Mesh& mesh) {
  for (const auto& phase : spec.phases) {
    for (const auto& fixity : phase.fixities) check_boundary(mesh, fixity.boundary, fixity.source);
    for (const auto& motion : phase.grid_motions)
      check_boundary(mesh, motion.boundary, motion.source);
    resolve_fixities(mesh, phase.fixities);
    resolve_grid_motions(mesh, phase.grid_motions);
  }
  for (const auto& history : spec.output.histories)
    check_boundary(mesh, history.boundary, history.source);
}

}  // namespace

namespace {
// Contact acts only inside the background mesh, where the soil's points and level set are: a
// structure in contact whose whole surface lies outside it would run with no force at all.
void check_structure_reaches_mesh(const Model& model, std::size_t s, const spec::Structure& spec) {
  if (!spec.contact.enabled) return;  // `contact: none`: a structure on its own
  const StructureMesh& mesh = model.structures[s]->mesh();
  for (const Facet& facet : mesh.surface())
    if (model.locator->locate(facet.centre(mesh.nodes()))) return;
  const MeshBounds box = mesh_bounds(model.mesh);
  throw InputError(
      spec.source,
      fmt::format("the structure '{}' lies outside the mesh (which spans [{:g}, {:g}] x [{:g}, "
                  "{:g}]{}): contact acts only inside it, so it would touch no soil; place it in "
                  "the mesh, or extend the mesh over it",
                  spec.name, box.lo(0), box.hi(0), box.lo(1), box.hi(1),
                  model.mesh.dim() == 3 ? fmt::format(" x [{:g}, {:g}]", box.lo(2), box.hi(2))
                                        : std::string()));
}

// Adhesion as a fraction alpha of s_u needs soil that has one: every material the touched bodies'
// points carry must keep an undrained strength per point (Tresca's internal variable "su"). The
// first such point of every process's (collective) names the material that has none.
void check_adhesion_strength(const Model& model, const ContactPair& pair,
                             const spec::Contact& contact, const Communicator& processes) {
  if (!(pair.law.alpha > 0.0)) return;
  // Per material, minus the first id of a touched point that carries it (max: the first of all).
  std::vector<double> first(model.materials.size(), -std::numeric_limits<double>::max());
  for (Index p = 0; p < model.points.size(); ++p) {
    const Index body = model.points.body[p], m = model.points.material[p];
    if (!pair.bodies.empty() && !pair.bodies[body]) continue;
    first[m] = std::max(first[m], -static_cast<double>(model.points.id[p]));
  }
  processes.max(first.data(), first.size());
  std::size_t lacking = first.size();
  for (std::size_t m = 0; m < first.size(); ++m) {
    if (first[m] == -std::numeric_limits<double>::max()) continue;  // carried by no touched point
    const Material& material = *model.materials[m];
    bool has_su = false;
    for (int k = 0; k < material.internal_variable_count(); ++k)
      has_su |= std::string(material.internal_variable_name(k)) == "su";
    if (!has_su && (lacking == first.size() || first[m] > first[lacking])) lacking = m;
  }
  if (lacking == first.size()) return;
  throw InputError(contact.source,
                   fmt::format("contact of '{}': alpha needs soil with an undrained strength "
                               "s_u (model tresca), but material '{}' is {}; give the "
                               "adhesion as a stress instead (adhesion: ...)",
                               pair.name, model.spec.materials[lacking].name,
                               model.materials[lacking]->model_name()));
}

// A structure's contact with the soil (docs/theory.md §18) as the model file gives it.
ContactPair contact_pair(const spec::Model& spec, const spec::Structure& structure, Index index) {
  ContactPair pair;
  pair.name = structure.name;
  pair.structure = index;
  const spec::Contact& c = structure.contact;
  pair.enabled = c.enabled;
  if (!c.bodies.empty()) {
    pair.bodies.assign(spec.bodies.size(), 0);
    for (std::size_t b = 0; b < spec.bodies.size(); ++b)
      pair.bodies[b] =
          std::find(c.bodies.begin(), c.bodies.end(), spec.bodies[b].name) != c.bodies.end();
  }
  const std::map<std::string, TangentialContact> laws = {{"smooth", TangentialContact::Smooth},
                                                         {"rough", TangentialContact::Rough},
                                                         {"adhesion", TangentialContact::Adhesion},
                                                         {"friction", TangentialContact::Friction}};
  pair.law.tangential = laws.at(c.tangential);
  pair.law.adhesion = c.adhesion;
  pair.law.alpha = c.alpha;
  pair.law.friction = c.friction;
  if (c.cap) pair.law.cap = *c.cap;
  return pair;
}

// Work on this process's points that may meet bad input at a point; in a distributed run every
// process learns whether it did on any (core/agreement.hpp). An expression evaluated there (initial
// velocities and stresses) that gives no finite value is bad input, found by `geompm check`.
void on_own_points(const Communicator& processes, const std::function<void()>& work) {
  together(processes, [&] {
    try {
      work();
    } catch (const NonFiniteValue& e) {
      throw InputError(e.what());
    }
  });
}

std::unique_ptr<Model> build_model_parts(const spec::Model& spec, const Communicator& processes) {
  check_model_size(spec);  // before the first allocation that could not fit
  auto model = std::make_unique<Model>();
  model->spec = spec;
  model->mesh = make_mesh(spec);
  add_node_sets(spec, model->mesh);
  const Mesh& mesh = model->mesh;
  model->topology = build_mesh_topology(mesh);
  check_numerics_fit_mesh(spec, mesh);
  check_material_formulations(spec, mesh);
  model->locator = std::make_unique<PointLocator>(mesh);
  create_materials(spec, *model);
  // The structures before the FEM region: its cells may be given by their distance from one.
  for (const spec::Structure& structure : spec.structures) {
    model->structures.push_back(build_structure(structure, spec, model->material_pointers()));
    model->contacts.push_back(contact_pair(spec, structure, model->structures.size() - 1));
    check_structure_reaches_mesh(*model, model->structures.size() - 1, structure);
  }
  build_fem_region(spec, *model);
  // The points counted in every cell, the cells cut among the processes by them, and each process
  // seeds its own (analysis/body_seeding.hpp); a serial run seeds as it counts.
  check_bodies_inside_mesh(spec, mesh);
  if (processes.distributed()) {
    const SeedCensus census = count_body_points(*model);
    model->cell_part = partition_by_work(*model, census.points_in_cell(), processes.size());
    on_own_points(processes,
                  [&] { seed_own_cells(census, model->cell_part, processes.rank(), *model); });
  } else {
    on_own_points(processes, [&] { count_body_points(*model, /*add_points=*/true); });
  }
  add_point_sets(spec, *model, processes);
  check_boundaries(spec, mesh);
  for (std::size_t s = 0; s < spec.structures.size(); ++s)
    check_adhesion_strength(*model, model->contacts[s], spec.structures[s].contact, processes);
  // Initial stresses given directly, and the geostatic stresses of the first phase's K0 procedure
  // (docs/theory.md §10), before any step.
  on_own_points(processes, [&] { apply_initial_stresses(*model); });
  apply_k0_procedure(*model, processes);
  return model;
}

}  // namespace

std::unique_ptr<Model> build_model(const spec::Model& spec, const Communicator& processes) {
  // An expression evaluated while the model is built (initial velocities and stresses) that
  // gives no finite value is bad input, found by `geompm check`.
  try {
    return build_model_parts(spec, processes);
  } catch (const NonFiniteValue& e) {
    throw InputError(e.what());
  }
}

namespace {

std::string dynamics_description(const spec::Dynamics& dynamics) {
  if (dynamics.quasi_static) return "quasi-static";
  if (dynamics.alpha_m != 0.0)
    return fmt::format("Bossak alpha_m={:g} (beta={:g} gamma={:g})", dynamics.alpha_m,
                       dynamics.beta, dynamics.gamma);
  return fmt::format("Newmark beta={:g} gamma={:g}", dynamics.beta, dynamics.gamma);
}

}  // namespace

namespace {

/// The counts and sums describe_model reports, over every process's points: the points, their
/// volume and mass, then the points of each body and of each point set.
std::vector<double> point_totals(const Model& model, const Communicator& processes) {
  const MaterialPoints& points = model.points;
  const std::size_t bodies = model.spec.bodies.size();
  std::vector<double> totals(3 + bodies + model.point_set_names.size(), 0.0);
  totals[0] = static_cast<double>(points.size());
  for (Index p = 0; p < points.size(); ++p) {
    totals[1] += points.volume[p];
    totals[2] += points.mass[p];
    totals[3 + points.body[p]] += 1.0;
    for (std::size_t k = 0; k < model.point_set_names.size(); ++k)
      totals[3 + bodies + k] += (points.sets[p] >> k) & 1u;
  }
  processes.sum(totals);
  return totals;
}

}  // namespace

std::string describe_model(const Model& model, const Communicator& processes) {
  const auto& spec = model.spec;
  const std::vector<double> totals = point_totals(model, processes);
  const auto count_of = [&](std::size_t k) { return static_cast<Index>(totals[k]); };
  std::string out;
  out += fmt::format("model      {}{}\n", spec.file, spec.title.empty() ? "" : " — " + spec.title);
  out += fmt::format("analysis   {}\n", to_string(spec.kinematics));
  out += fmt::format("mesh       {} {} cells, {} nodes{}\n", model.mesh.num_cells(),
                     cell_type_names(model.mesh), model.mesh.num_nodes(),
                     spec.mesh.file.empty() ? " (generated)" : " from " + spec.mesh.file);
  out += fmt::format("points     {} (volume {:.6g}{}, mass {:.6g})\n", count_of(0), totals[1],
                     spec.kinematics == Kinematics::Axisymmetric ? " per radian" : "", totals[2]);
  for (std::size_t m = 0; m < spec.materials.size(); ++m) {
    std::string params;
    for (const auto& [k, v] : spec.materials[m].parameters) params += fmt::format(" {}={:g}", k, v);
    out += fmt::format("material   {}: {}{}, {}\n", spec.materials[m].name, spec.materials[m].model,
                       params, describe(material_formulation(spec, model.mesh, spec.materials[m])));
  }
  for (std::size_t b = 0; b < spec.bodies.size(); ++b) {
    const Index count = count_of(3 + b);
    const auto& body = spec.bodies[b];
    std::string material = "material " + body.material;
    if (!body.layers.empty()) {
      material = "layers";
      for (const auto& layer : body.layers)
        material += " " + layer.material +
                    (layer.bottom ? fmt::format(" down to {:g},", *layer.bottom) : " below");
    }
    const Index inside =
        b < model.seeds_inside_structures.size() ? model.seeds_inside_structures[b] : 0;
    const std::string left_out =
        inside > 0 ? fmt::format(" ({} seeding positions inside structures left out)", inside) : "";
    const std::string per_cell =
        body.points_per_cell > 0 || model.mesh.dim() == 2
            ? fmt::format("{} per cell", body.points_per_cell > 0 ? body.points_per_cell : 4)
            : std::string("4 per tetrahedron, 8 per hexahedron or pyramid");
    out += fmt::format("body       {}: {} points{}, {}, {}\n", body.name, count, left_out, per_cell,
                       material);
  }
  for (std::size_t k = 0; k < model.point_set_names.size(); ++k) {
    const Index count = count_of(3 + spec.bodies.size() + k);
    out += fmt::format("point set  {}: {} points\n", model.point_set_names[k], count);
  }
  for (const auto& structure : model.structures)
    out += fmt::format(
        "structure  {}: {} {} cells, {} surface facets, {} {:.6g}{}\n", structure->name(),
        structure->mesh().num_cells(), to_string(structure->mesh().mesh().cell_type),
        structure->mesh().surface().size(),
        spec.kinematics == Kinematics::PlaneStrain ? "area" : "volume", structure->mesh().measure(),
        spec.kinematics == Kinematics::Axisymmetric ? " per radian" : "");
  for (const auto& phase : spec.phases)
    out += fmt::format(
        "phase      {}: duration {:g}, dt {:g} [{:g}, {:g}], {}{}{}\n", phase.name, phase.duration,
        phase.time_step.initial, phase.time_step.min, phase.time_step.max,
        dynamics_description(phase.dynamics),
        phase.k0_procedure ? ", starts from the K0 procedure's geostatic stresses" : "",
        phase.surface_loads.empty()
            ? std::string()
            : fmt::format(", {} surface load{} on the bodies' boundary", phase.surface_loads.size(),
                          phase.surface_loads.size() > 1 ? "s" : ""));
  return out;
}

}  // namespace geompm

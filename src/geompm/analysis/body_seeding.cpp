#include "geompm/analysis/body_seeding.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <stdexcept>

#include "geompm/analysis/region_test.hpp"
#include "geompm/core/error.hpp"
#include "geompm/core/expression.hpp"
#include "geompm/points/seeding.hpp"

namespace geompm {

namespace {

// Tri6's corner shape functions are negative over part of the cell: a point there gives its
// corner nodes negative mass and load. Measured: 2.3 times the settlement once the points cross
// cells, DDMP stops, a K0 state 19 % out of balance on the N_gamma footing. Material points
// need linear cells; tri6 serves FEM regions and structures, integrated at Gauss points.
void check_cell_carries_points(const spec::Body& body, const Mesh& mesh, Index c) {
  if (mesh.type_of(c) != CellType::Tri6) return;
  throw InputError(
      body.region.source,
      fmt::format("body '{}' would put material points in tri6 cell {} (an MPM "
                  "cell), but material points need linear cells (tri3, quad4; tet4, "
                  "hex8, pyramid5): tri6 corner shape functions give nodes negative mass; make "
                  "the body's tri6 cells an FEM region (regions: {{kind: fem}}) or "
                  "use tri3 or quad4",
                  body.name, c));
}

/// What both passes ask of a cell: which of its seeding positions a body keeps.
struct BodyRegions {
  const Model& model;
  std::vector<RegionTest> regions;       // each body's
  std::vector<PointLocator> structures;  // a locator of each structure's cells: inside it or not

  explicit BodyRegions(const Model& m) : model(m) {
    for (const spec::Body& body : m.spec.bodies)
      regions.emplace_back(body.region, m.mesh, m.mesh.dim());
    for (const auto& structure : m.structures) structures.emplace_back(structure->mesh().mesh());
  }

  /// Whether body b may hold points in cell c (its cell group's cell, an MPM cell); `fem_cell`
  /// is set when the cell is an FEM cell, seeded at its Gauss points (docs/theory.md §19).
  bool may_seed(std::size_t b, Index c, bool& fem_cell) const {
    if (model.spec.bodies[b].region.kind == spec::Region::Kind::Group &&
        !regions[b].contains(Vec3::Zero(), c))
      return false;
    if (!model.cell_kinds.empty() && model.cell_kinds[c] != CellKind::Mpm) {
      fem_cell = fem_cell || model.cell_kinds[c] == CellKind::Fem;
      return false;
    }
    return true;
  }

  /// The seeding positions of cell c that body b keeps: those in its region, outside every
  /// structure (a structure that starts inside the soil takes its place, docs/theory.md §17.1;
  /// `inside_structures` counts those left out), which none of the bodies before it holds.
  std::vector<SeedPoint> kept(std::size_t b, Index c, Index& inside_structures) const {
    const spec::Body& body = model.spec.bodies[b];
    const Mesh& mesh = model.mesh;
    std::vector<SeedPoint> seeds;
    try {
      const int count = body.points_per_cell > 0 ? body.points_per_cell
                                                 : default_points_per_cell(mesh.type_of(c));
      seeds = seed_cell(mesh, c, count, model.spec.kinematics == Kinematics::Axisymmetric);
    } catch (const std::invalid_argument& e) {
      throw InputError(body.points_per_cell_source, e.what());
    }
    std::vector<SeedPoint> out;
    for (const SeedPoint& s : seeds) {
      if (!regions[b].contains(s.position, c)) continue;
      check_cell_carries_points(body, mesh, c);
      if (std::any_of(structures.begin(), structures.end(),
                      [&](const PointLocator& inside) { return inside.locate(s.position); })) {
        ++inside_structures;
        continue;
      }
      for (std::size_t other = 0; other < b; ++other)
        if (regions[other].contains(s.position, c))
          throw InputError(body.region.source,
                           fmt::format("bodies '{}' and '{}' overlap (at x = [{:g}, {:g}, {:g}])",
                                       body.name, model.spec.bodies[other].name, s.position.x(),
                                       s.position.y(), s.position.z()));
      out.push_back(s);
    }
    return out;
  }
};

// One material point of body b at a seeding position of cell c: its material (by its layer),
// its point-dependent state and its initial velocity.
void add_body_point(std::size_t b, const SeedPoint& s, Index c, Index id,
                    const std::array<Expression, 3>& v0, Model& model) {
  const spec::Model& spec = model.spec;
  const spec::Body& body = spec.bodies[b];
  const int dim = model.mesh.dim();
  const Index material = body_material_at(spec, body, s.position(dim - 1));
  const Index p = model.points.add(static_cast<Index>(b), material, s.position, s.volume,
                                   model.materials[material]->density(), c, s.xi, s.half_size);
  model.points.id[p] = id;
  // Point-dependent state, e.g. a strength growing with depth.
  try {
    model.materials[material]->initialise_point(s.position, dim, model.points.internal[p]);
  } catch (const ParameterError& e) {
    SourceLocation where = spec.materials[material].source;
    where.key_path += "." + e.key();
    throw InputError(where,
                     fmt::format("{} (at the point x = [{:g}, {:g}, {:g}] of body '{}')", e.what(),
                                 s.position.x(), s.position.y(), s.position.z(), body.name));
  }
  for (int d = 0; d < dim; ++d)
    model.points.velocity[p](d) = v0[d](s.position.x(), s.position.y(), s.position.z(), 0.0);
}

// A body's initial velocity, one expression of x, y, z per component.
std::array<Expression, 3> initial_velocity(const spec::Body& body) {
  std::array<Expression, 3> v0;
  for (int d = 0; d < 3; ++d)
    v0[d] = Expression(body.initial_velocity[d],
                       fmt::format("{}.initial_velocity[{}]", body.source.describe(), d));
  return v0;
}

}  // namespace

std::vector<double> SeedCensus::points_in_cell() const {
  std::vector<double> count(per_cell.empty() ? 0 : per_cell.front().size(), 0.0);
  for (const auto& body : per_cell)
    for (std::size_t c = 0; c < body.size(); ++c) count[c] += body[c];
  return count;
}

SeedCensus count_body_points(Model& model, bool add_points) {
  const spec::Model& spec = model.spec;
  const BodyRegions bodies(model);
  SeedCensus census;
  model.seeds_inside_structures.assign(spec.bodies.size(), 0);
  Index next_id = 0;
  for (std::size_t b = 0; b < spec.bodies.size(); ++b) {
    std::vector<std::uint8_t>& count = census.per_cell.emplace_back(model.mesh.num_cells(), 0);
    const std::array<Expression, 3> v0 = initial_velocity(spec.bodies[b]);
    Index total = 0;
    bool fem_cells = false;  // the body holds FEM cells, seeded at their Gauss points
    for (Index c = 0; c < model.mesh.num_cells(); ++c) {
      if (!bodies.may_seed(b, c, fem_cells)) continue;
      const std::vector<SeedPoint> seeds = bodies.kept(b, c, model.seeds_inside_structures[b]);
      count[c] = static_cast<std::uint8_t>(seeds.size());
      total += static_cast<Index>(seeds.size());
      if (add_points)
        for (const SeedPoint& s : seeds) add_body_point(b, s, c, next_id++, v0, model);
    }
    if (total == 0 && !fem_cells)
      throw InputError(spec.bodies[b].region.source,
                       fmt::format("body '{}' has no material points: its region holds no "
                                   "seeding position of any cell",
                                   spec.bodies[b].name));
  }
  return census;
}

void seed_own_cells(const SeedCensus& census, const std::vector<int>& cell_part, int rank,
                    Model& model) {
  const spec::Model& spec = model.spec;
  const BodyRegions bodies(model);
  Index next_id = 0, inside_structures = 0;
  for (std::size_t b = 0; b < spec.bodies.size(); ++b) {
    const std::array<Expression, 3> v0 = initial_velocity(spec.bodies[b]);
    for (Index c = 0; c < model.mesh.num_cells(); ++c) {
      const Index count = census.per_cell[b][c];
      if (count == 0) continue;
      if (!cell_part.empty() && cell_part[c] != rank) {
        next_id += count;  // another process's points
        continue;
      }
      const std::vector<SeedPoint> seeds = bodies.kept(b, c, inside_structures);
      if (static_cast<Index>(seeds.size()) != count)
        throw std::logic_error(fmt::format("seed_own_cells: {} points in cell {}, counted {}",
                                           seeds.size(), c, count));
      for (const SeedPoint& s : seeds) add_body_point(b, s, c, next_id++, v0, model);
    }
  }
}

}  // namespace geompm

#include "geompm/analysis/geostatic_stress.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "geompm/analysis/region_test.hpp"
#include "geompm/core/agreement.hpp"

namespace geompm {

namespace {

// Which material of the procedure's bodies is at a position (-1: none).
class SoilLocator {
 public:
  SoilLocator(const Model& model, const std::vector<Index>& bodies) : model_(model) {
    const int dim = model.mesh.dim();
    for (Index b : bodies) {
      bodies_.push_back(&model.spec.bodies[b]);
      regions_.emplace_back(model.spec.bodies[b].region, model.mesh, dim);
      needs_cell_ = needs_cell_ || regions_.back().needs_cell();
    }
  }

  Index material_at(const Vec3& x) const {
    Index cell = -1;
    if (needs_cell_) {
      const auto where = model_.locator->locate(x, -1);
      if (!where) return -1;
      cell = where->cell;
    }
    for (std::size_t k = 0; k < regions_.size(); ++k)
      if (regions_[k].contains(x, cell))
        return body_material_at(model_.spec, *bodies_[k], x(model_.mesh.dim() - 1));
    return -1;
  }

 private:
  const Model& model_;
  std::vector<const spec::Body*> bodies_;
  std::vector<RegionTest> regions_;
  bool needs_cell_ = false;
};

std::string position(const Vec3& x, int dim) {
  return dim == 3 ? fmt::format("[{:g}, {:g}, {:g}]", x.x(), x.y(), x.z())
                  : fmt::format("[{:g}, {:g}]", x.x(), x.y());
}

std::string material_name(const Model& model, Index m) {
  return m < 0 ? "no soil" : "'" + model.spec.materials[m].name + "'";
}

SoilProfile profile_from(const Model& model, const SoilLocator& soil, const Vec3& through) {
  const int dim = model.mesh.dim(), v = dim - 1;
  double low = std::numeric_limits<double>::max(), high = -low;
  for (const auto& x : model.mesh.nodes) {
    low = std::min(low, x(v));
    high = std::max(high, x(v));
  }
  auto at = [&](double z) {
    Vec3 x = through;
    x(v) = z;
    return soil.material_at(x);
  };
  // Samples fine enough to see any layer a cell can hold, then each change of material located
  // by bisection to round-off.
  constexpr int samples = 4096;
  SoilProfile profile;
  profile.through = through;
  double bottom = low;
  Index current = at(low);
  for (int k = 1; k <= samples; ++k) {
    const double z = low + (high - low) * k / samples;
    const Index next = at(z);
    if (next == current) continue;
    double a = low + (high - low) * (k - 1) / samples, b = z;
    for (int i = 0; i < 64 && b - a > 1e-15 * (high - low); ++i) {
      const double mid = 0.5 * (a + b);
      (at(mid) == current ? a : b) = mid;
    }
    profile.segments.push_back({bottom, 0.5 * (a + b), current});
    bottom = 0.5 * (a + b);
    current = next;
  }
  profile.segments.push_back({bottom, high, current});
  // Drop the empty space above the ground; what is left must be soil all the way up.
  while (!profile.segments.empty() && profile.segments.back().material < 0)
    profile.segments.pop_back();
  while (!profile.segments.empty() && profile.segments.front().material < 0)
    profile.segments.erase(profile.segments.begin());
  profile.surface = profile.segments.empty() ? low : profile.segments.back().top;
  return profile;
}

// The bodies the K0 procedure names (all bodies when it names none).
std::vector<Index> procedure_bodies(const spec::Model& spec, const spec::K0Procedure& procedure) {
  std::vector<Index> bodies;
  for (std::size_t b = 0; b < spec.bodies.size(); ++b)
    if (procedure.bodies.empty() || std::find(procedure.bodies.begin(), procedure.bodies.end(),
                                              spec.bodies[b].name) != procedure.bodies.end())
      bodies.push_back(static_cast<Index>(b));
  return bodies;
}

bool in_procedure(const MaterialPoints& points, const std::vector<Index>& bodies, Index p) {
  return std::find(bodies.begin(), bodies.end(), points.body[p]) != bodies.end();
}

// The position of the lowest point of the procedure's soil over every process's points
// (collective; none: no such point). Of points equally low, the first seeded (the lowest id), as
// on one process.
std::optional<Vec3> lowest_point(const MaterialPoints& points, const std::vector<Index>& bodies,
                                 int v, const Communicator& processes) {
  Index lowest = -1;
  for (Index p = 0; p < points.size(); ++p)
    if (in_procedure(points, bodies, p) &&
        (lowest < 0 || points.position[p](v) < points.position[lowest](v)))
      lowest = p;
  // max of minus the elevation, then of minus the id among the points that low: the lowest id.
  const double none = -std::numeric_limits<double>::max();
  double depth = lowest < 0 ? none : -points.position[lowest](v);
  processes.max(&depth, 1);
  if (depth == none) return std::nullopt;
  const bool here = lowest >= 0 && -points.position[lowest](v) == depth;
  double first = here ? -static_cast<double>(points.id[lowest]) : none;
  processes.max(&first, 1);
  // Its position from its process: the others add zeros, which leave it exact.
  std::vector<double> x(3, 0.0);
  if (here && -static_cast<double>(points.id[lowest]) == first)
    for (int d = 0; d < 3; ++d) x[d] = points.position[lowest](d);
  processes.sum(x);
  return Vec3(x[0], x[1], x[2]);
}

/// The K0 procedure's reference vertical: its soil profile and what the points are measured
/// against on it.
struct ReferenceVertical {
  SoilProfile profile;
  std::string vertical;           // "the vertical through [x, y]", for the messages
  std::vector<double> densities;  // of every material
  double tolerance = 0.0;         // of elevations, relative to the profile's height
  double stress_scale = 0.0;      // the vertical stress at the profile's bottom
};

// The profile on the vertical through `through`, which must hold soil all the way up to the
// surface.
ReferenceVertical reference_vertical(const Model& model, const SoilLocator& soil,
                                     const Vec3& through, double g, const SourceLocation& where) {
  const int dim = model.mesh.dim(), v = dim - 1;
  ReferenceVertical r;
  r.profile = profile_from(model, soil, through);
  const SoilProfile& profile = r.profile;
  r.vertical = fmt::format("the vertical through {}", position(profile.through, dim));
  const std::string& vertical = r.vertical;
  for (const auto& s : profile.segments)
    if (s.material < 0)
      throw InputError(
          where, fmt::format("the K0 procedure needs soil all the way up to the surface, but on "
                             "{} there is a gap with no soil of its bodies between {} = {:g} "
                             "and {:g}",
                             vertical, "xyz"[v], s.bottom, s.top));

  for (const auto& m : model.materials) r.densities.push_back(m->density());
  const double height = profile.surface - profile.segments.front().bottom;
  r.tolerance = 1e-9 * std::max(height, 1.0);
  r.stress_scale = g * profile.mass_above(profile.segments.front().bottom, r.densities);
  return r;
}

// Level ground in horizontal layers: the point is below the surface, its material is the
// one on the reference vertical at its elevation, and the soil above it reaches the surface.
void check_level_ground(const Model& model, const SoilLocator& soil, const ReferenceVertical& r,
                        const SourceLocation& where, const std::string& point, const Vec3& x,
                        Index material) {
  const int v = model.mesh.dim() - 1;
  const SoilProfile& profile = r.profile;
  const std::string& vertical = r.vertical;
  const double tolerance = r.tolerance;
  if (x(v) > profile.surface + tolerance)
    throw InputError(where, fmt::format("the ground is not level: {} lies above the surface "
                                        "{} = {:g} found on {}",
                                        point, "xyz"[v], profile.surface, vertical));
  const SoilProfile::Segment* layer = profile.at(x(v));
  const SoilProfile::Segment* below = profile.at(x(v) - tolerance);
  const SoilProfile::Segment* above = profile.at(x(v) + tolerance);
  auto same = [&](const SoilProfile::Segment* s) { return s && s->material == material; };
  if (!same(layer) && !same(below) && !same(above))
    throw InputError(where, fmt::format("the layers are not horizontal: {} is at {} = {:g}, "
                                        "where {} has {}",
                                        point, "xyz"[v], x(v), vertical,
                                        material_name(model, layer ? layer->material : -1)));
  Vec3 top = x;
  top(v) = profile.surface - tolerance;
  if (soil.material_at(top) != profile.segments.back().material)
    throw InputError(where,
                     fmt::format("the ground is not level: above {} the soil does not reach "
                                 "the surface {} = {:g} found on {} (at {} = {:g} there is {})",
                                 point, "xyz"[v], profile.surface, vertical, "xyz"[v], top(v),
                                 material_name(model, soil.material_at(top))));
}

// Point p's geostatic stress and the elastic strain that gives it, which the material must
// accept as admissible.
void set_geostatic_stress(Model& model, const spec::K0Procedure& procedure,
                          const ReferenceVertical& r, double g, Index p, const std::string& point) {
  const SourceLocation& where = procedure.source;
  const int v = model.mesh.dim() - 1;
  MaterialPoints& points = model.points;
  const Vec3& x = points.position[p];
  const Index material = points.material[p];
  const std::string name = model.spec.materials[material].name;
  // Eq. 9.1-9.2: the geostatic Cauchy stress (F = I, so tau = sigma), then the elastic strain
  // that gives it (eq. 10.3).
  const auto k0_given = procedure.k0.find(name);
  const double k0 = k0_given != procedure.k0.end()
                        ? k0_given->second
                        : model.materials[material]->default_k0().value();
  const double sigma_v = -g * r.profile.mass_above(x(v), r.densities);
  Mat3 sigma = k0 * sigma_v * Mat3::Identity();
  sigma(v, v) = sigma_v;
  const Material& law = *model.materials[material];
  const std::optional<Mat3> strain = law.elastic_strain_for_stress(sigma, points.internal[p]);
  if (!strain)
    throw InputError(where, fmt::format("the material model '{}' of material '{}' cannot start "
                                        "from a given stress; use a gravity-loading phase "
                                        "(ramped gravity) instead",
                                        law.model_name(), name));
  // Admissible: the material's update at that strain gives the same stress back; a stress
  // outside the yield surface would be returned to it.
  StressUpdate check;
  law.update(*strain, points.internal[p], check);
  if ((check.kirchhoff - sigma).norm() > 1e-9 * std::max(sigma.norm(), r.stress_scale))
    throw InputError(
        where,
        fmt::format(
            "the K0 stress of {} lies outside the yield surface of '{}': sigma_v = {:g}, "
            "sigma_h = K0 sigma_v = {:g} (K0 = {:g}){}; choose a K0 nearer 1 or a "
            "stronger soil there, or start with a gravity-loading phase (ramped "
            "gravity), in which the soil may yield",
            point, law.model_name(), sigma_v, k0 * sigma_v, k0,
            law.model_name() == std::string("tresca")
                ? fmt::format(", |sigma_v - sigma_h| = {:g} > 2 s_u", std::abs((1 - k0) * sigma_v))
                : ""));
  points.stress[p] = sigma;
  points.elastic_left_cauchy_green[p] = symmetric_exp(2.0 * *strain);
}

}  // namespace

double SoilProfile::mass_above(double elevation, const std::vector<double>& densities) const {
  // Eq. 9.1: the integral of the density from the elevation up to the surface, layer by layer.
  double sum = 0.0;
  for (const Segment& s : segments)
    if (s.top > elevation) sum += densities[s.material] * (s.top - std::max(s.bottom, elevation));
  return sum;
}

const SoilProfile::Segment* SoilProfile::at(double elevation) const {
  for (const Segment& s : segments)
    if (elevation >= s.bottom && elevation <= s.top) return &s;
  return nullptr;
}

SoilProfile soil_profile(const Model& model, const std::vector<Index>& bodies,
                         const Vec3& through) {
  return profile_from(model, SoilLocator(model, bodies), through);
}

void apply_k0_procedure(Model& model, const Communicator& processes) {
  const spec::Model& spec = model.spec;
  if (spec.phases.empty() || !spec.phases.front().k0_procedure) return;
  const spec::Phase& phase = spec.phases.front();
  const spec::K0Procedure& procedure = *phase.k0_procedure;
  const SourceLocation& where = procedure.source;
  const int dim = model.mesh.dim(), v = dim - 1;
  const double g = phase.gravity->acceleration.norm();  // vertical and downward: the reader
  MaterialPoints& points = model.points;

  const std::vector<Index> bodies = procedure_bodies(spec, procedure);
  // The reference vertical: through the lowest point of the procedure's soil.
  const std::optional<Vec3> lowest = lowest_point(points, bodies, v, processes);
  if (!lowest) return;  // every body holds points (build_model), so not reached
  const SoilLocator soil(model, bodies);
  const ReferenceVertical reference = reference_vertical(model, soil, *lowest, g, where);

  // This process's points; every process learns whether one was refused on any
  // (core/agreement.hpp).
  together(processes, [&] {
    for (Index p = 0; p < points.size(); ++p) {
      if (!in_procedure(points, bodies, p)) continue;
      const Vec3& x = points.position[p];
      const Index material = points.material[p];
      const std::string& body = spec.bodies[points.body[p]].name;
      const std::string name = spec.materials[material].name;
      const std::string point =
          fmt::format("the point at {} of body '{}' (material '{}')", position(x, dim), body, name);
      check_level_ground(model, soil, reference, where, point, x, material);
      set_geostatic_stress(model, procedure, reference, g, p, point);
    }
  });
}

}  // namespace geompm

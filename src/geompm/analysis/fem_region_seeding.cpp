#include "geompm/analysis/fem_region_seeding.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "geompm/analysis/material_formulation.hpp"
#include "geompm/analysis/mesh_regions.hpp"
#include "geompm/analysis/region_test.hpp"
#include "geompm/core/error.hpp"

namespace geompm {
namespace {

// The region that made cell c FEM, for messages.
const spec::MeshRegion& fem_region_of(const spec::Model& spec, const Mesh& mesh, Index c) {
  for (const spec::MeshRegion& region : spec.regions)
    if (region.kind == CellKind::Fem &&
        RegionTest(region.region, mesh, mesh.dim()).contains(cell_centroid(mesh, c), c))
      return region;
  return spec.regions.front();
}

// What the FEM cells' Gauss points cannot take yet: inertia (their mass is not in the grid's),
// a pressure field (its unknowns live at the points' nodes) and GIMP (a moving mesh is not a
// rectilinear grid).
void check_supported(const spec::Model& spec, const Mesh& mesh, const spec::MeshRegion& region) {
  const auto fail = [&](const std::string& what) {
    throw InputError(region.source, fmt::format("FEM region '{}': {}", region.name, what));
  };
  for (const spec::Phase& phase : spec.phases)
    if (!phase.dynamics.quasi_static)
      fail(
          fmt::format("FEM regions are quasi-static, but phase '{}' is dynamic; use "
                      "dynamics: quasi_static or no FEM region",
                      phase.name));
  for (const spec::Material& material : spec.materials)
    if (material_formulation(spec, mesh, material).formulation == spec::Formulation::Mixed)
      fail(
          fmt::format("material '{}' takes the mixed p-u formulation, which FEM regions do not "
                      "support; use formulation: f_bar (nearly incompressible soil) or no FEM "
                      "region",
                      material.name));
  if (spec.numerics.interpolation == spec::Interpolation::Gimp)
    fail(
        "GIMP needs a fixed rectilinear grid, but FEM regions move the mesh; use standard or "
        "ddmp");
}

// Contact acts on the material points of MPM cells (docs/theory.md §18-§19): a structure whose
// surface lies in an FEM cell at the start would pass through the soil there.
void check_structures_clear(const spec::Model& spec, const Model& model) {
  for (std::size_t s = 0; s < model.structures.size(); ++s) {
    const StructureMesh& mesh = model.structures[s]->mesh();
    for (const Facet& facet : mesh.surface())
      for (int k = 0; k <= facet.corners; ++k) {
        const Vec3 x =
            k < facet.corners ? mesh.nodes()[facet.nodes[k]] : facet.centre(mesh.nodes());
        const auto at = model.locator->locate(x);
        if (!at || !model.fem->fem_cell()[at->cell]) continue;
        throw InputError(spec.structures[s].source,
                         fmt::format("the surface of structure '{}' lies in FEM cell {} at "
                                     "[{:g}, {:g}, {:g}]: contact acts on the material points of "
                                     "MPM cells only; make the cells around the structure and "
                                     "along its path MPM cells (regions, e.g. beyond: "
                                     "{{structure: {}, distance: ...}})",
                                     spec.structures[s].name, at->cell, x.x(), x.y(), x.z(),
                                     spec.structures[s].name));
      }
  }
}

// The Gauss points of FEM cell c, of body b.
void seed_cell(const spec::Model& spec, std::size_t b, Index c, Model& model) {
  const int dim = model.mesh.dim();
  MaterialPoints& gauss = model.fem->gauss_points();
  const bool axisymmetric = spec.kinematics == Kinematics::Axisymmetric;
  for_each_gauss_point(
      model.mesh, c, axisymmetric, [&](int, const Vec3& xi, const Vec3& x, double volume) {
        const Index m = body_material_at(spec, spec.bodies[b], x(dim - 1));
        const Material& material = *model.materials[m];
        const Index g =
            gauss.add(static_cast<Index>(b), m, x, volume, material.density(), c, xi, Vec3::Zero());
        material.initialise_point(x, dim, gauss.internal[g]);
      });
}

}  // namespace

void build_fem_region(const spec::Model& spec, Model& model) {
  const Mesh& mesh = model.mesh;
  std::vector<CellKind> kinds = classify_cells(spec, mesh, model.structures);
  if (kinds.empty()) return;
  model.cell_kinds = kinds;
  if (std::none_of(kinds.begin(), kinds.end(), [](CellKind k) { return k == CellKind::Fem; }))
    return;
  for (const spec::MeshRegion& region : spec.regions)
    if (region.kind == CellKind::Fem) check_supported(spec, mesh, region);
  model.fem = std::make_unique<FemRegion>(mesh, kinds);
  check_structures_clear(spec, model);
  std::vector<RegionTest> bodies;
  for (const spec::Body& body : spec.bodies) bodies.emplace_back(body.region, mesh, mesh.dim());
  for (Index c : model.fem->cells()) {
    const Vec3 centroid = cell_centroid(mesh, c);
    std::size_t b = 0;
    while (b < bodies.size() && !bodies[b].contains(centroid, c)) ++b;
    if (b == bodies.size()) {
      const spec::MeshRegion& region = fem_region_of(spec, mesh, c);
      throw InputError(region.source,
                       fmt::format("FEM region '{}' holds cell {} (centroid [{:g}, {:g}, {:g}]), "
                                   "which no body holds: an FEM cell needs the material of a body",
                                   region.name, c, centroid.x(), centroid.y(), centroid.z()));
    }
    seed_cell(spec, b, c, model);
  }
}

}  // namespace geompm

#include "geompm/analysis/material_formulation.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "geompm/core/error.hpp"

namespace geompm {
namespace {

using spec::Formulation;

/// The Poisson's ratio from which an elastic material takes the mixed formulation. On the elastic
/// thick cylinder (Lamé; examples/thick_cylinder/ made linear elastic, 5 cells across the wall,
/// docs/validation.md §22) the displacement formulation's excess over the mixed one grows as
/// 1/(1 - 2 nu): 0.3 % at nu = 0.3, 0.7 % at 0.4, 1.4 % at 0.45, 3 % at 0.475, 7.5 % at 0.49, 77 %
/// at 0.499; from 0.45 on it is more than 1 %.
constexpr double kNearlyIncompressible = 0.45;

double parameter(const spec::Material& material, const char* key, double fallback) {
  const auto at = material.parameters.find(key);
  return at == material.parameters.end() ? fallback : at->second;
}

bool has_fem_region(const spec::Model& model) {
  return std::any_of(model.regions.begin(), model.regions.end(),
                     [](const spec::MeshRegion& r) { return r.kind == CellKind::Fem; });
}

bool has_simplex_cells(const Mesh& mesh) {
  for (const CellType type : mesh.types_present())
    if (type == CellType::Tri3 || type == CellType::Tri6 || type == CellType::Tet4) return true;
  return false;
}

/// What suits a material whose volume its plastic flow or its elasticity constrains: the
/// formulation that relieves the constraint; else the displacement formulation. `mixed` false:
/// the model has FEM regions, which take no pressure field (theory §19), or triangles or
/// tetrahedra: on the rough rigid strip of validation.md §4 on crossed triangles (nu = 0.49,
/// h = B/20) the mixed formulation stops at 0.042 B carrying 3.55 s_u, 31 % below Prandtl's,
/// where F-bar reaches 0.1 B at 5.81 s_u (the triangles' first-order over-estimate, §11); a
/// constant-strain triangle's points share one volume change, so F-bar is the displacement
/// formulation there (tetrahedra by the same token, not measured).
MaterialFormulation suited(const spec::Material& material, bool mixed) {
  const std::string origin = "default for " + material.model;
  const Formulation relieved = mixed ? Formulation::Mixed : Formulation::FBar;
  // Tresca's flow is isochoric: bilinear cells in the displacement formulation lock on it (8 x
  // Prandtl's load at nu = 0.4999, validation.md §4); the mixed p-u formulation (theory §11) does
  // not, and F-bar (§12), one volume per cell, neither.
  if (material.model == "tresca") return {relieved, false, origin};
  // Mohr-Coulomb with isochoric flow (psi = 0): F-bar. In the displacement formulation the stiff
  // c-phi strip (phi = 20 deg) stops at 0.0006 B; with F-bar it levels off at +0.5 % of N_c, and
  // the slope and layered-ground examples run through, where the mixed formulation at the
  // field's pressure stops the slope (validation.md §8).
  if (material.model == "mohr_coulomb" && parameter(material, "psi", 0.0) == 0.0)
    return {Formulation::FBar, false, origin};
  // Nearly incompressible elasticity, of any model.
  if (parameter(material, "nu", 0.0) >= kNearlyIncompressible) return {relieved, false, origin};
  // Dilatant Mohr-Coulomb flow (psi > 0) locks bilinear cells in the displacement formulation too
  // (Sloan & Randolph 1982; +16 % over Prandtl-Reissner's N_c on the stiff strip at h = B/20),
  // but it stays there: F-bar stops early, and the mixed formulation at the field's pressure,
  // which does not lock, stops 6 of the 8 dilatant examples (validation.md §8).
  return {Formulation::Displacement, false, origin};
}

}  // namespace

MaterialFormulation material_formulation(const spec::Model& model, const Mesh& mesh,
                                         const spec::Material& material) {
  MaterialFormulation chosen;
  if (material.formulation)
    chosen = {*material.formulation, false, "given"};
  else if (model.numerics.formulation)
    chosen = {*model.numerics.formulation, false, "numerics.formulation"};
  else
    chosen = suited(material, !has_fem_region(model) && !has_simplex_cells(mesh));
  // The pressure a mixed material sees: as numerics.mixed_material_pressure says, else the one
  // that suits it (the field's for Mohr-Coulomb, whose yield condition depends on it).
  if (chosen.formulation != Formulation::Mixed)
    chosen.field_pressure = false;
  else if (model.numerics.mixed_field_pressure)
    chosen.field_pressure = *model.numerics.mixed_field_pressure;
  else
    chosen.field_pressure = material.model == "mohr_coulomb";
  return chosen;
}

std::string describe(const MaterialFormulation& formulation) {
  const char* name = formulation.formulation == Formulation::Mixed  ? "mixed p-u"
                     : formulation.formulation == Formulation::FBar ? "F-bar"
                                                                    : "displacement";
  return fmt::format("{}{} ({})", name,
                     formulation.field_pressure ? " at the field's pressure" : "",
                     formulation.origin);
}

void check_material_formulations(const spec::Model& model, const Mesh& mesh) {
  if (!model.numerics.mixed_incremental_pressure) return;
  for (const spec::Material& material : model.materials)
    if (const MaterialFormulation chosen = material_formulation(model, mesh, material);
        chosen.field_pressure)
      throw InputError(
          model.numerics.incremental_pressure_source,
          fmt::format("expected 'total': material '{}' takes the mixed p-u formulation at the "
                      "field's pressure ({}), which carries its volume mismatch over the steps "
                      "(docs/theory.md §14); 'incremental' applies to the material's own pressure: "
                      "give numerics.mixed_material_pressure: own, or the material another "
                      "formulation",
                      material.name, chosen.origin));
}

}  // namespace geompm

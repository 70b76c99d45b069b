// The formulation a material takes (analysis/material_formulation.hpp, docs/user-guide.md
// "materials"): what the model file gives wins; otherwise the one that suits the material, with
// F-bar in its place where FEM regions take no pressure field; geompm check names the choice.
#include "geompm/analysis/material_formulation.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "geompm/analysis/model.hpp"
#include "geompm/core/error.hpp"
#include "geompm/io/model_reader.hpp"

namespace geompm {
namespace {

using spec::Formulation;

spec::Material material(const std::string& model, std::map<std::string, double> parameters) {
  spec::Material m;
  m.name = "soil";
  m.model = model;
  m.parameters = std::move(parameters);
  return m;
}

const Mesh kQuads;  // a quad4 mesh (its cells do not matter here, only their type)

spec::Model model_of(const spec::Material& m) {
  spec::Model model;
  model.materials.push_back(m);
  return model;
}

TEST(MaterialFormulation, EachModelTakesTheFormulationThatSuitsIt) {
  const auto tresca = material("tresca", {{"su", 1}, {"E", 500}, {"nu", 0.3}});
  const auto chosen = material_formulation(model_of(tresca), kQuads, tresca);
  EXPECT_EQ(chosen.formulation, Formulation::Mixed);  // isochoric flow, whatever nu
  EXPECT_FALSE(chosen.field_pressure);
  EXPECT_EQ(describe(chosen), "mixed p-u (default for tresca)");

  for (const char* model : {"linear_elastic", "hencky", "neo_hookean"}) {
    const auto stiff = material(model, {{"E", 1}, {"nu", 0.45}});
    EXPECT_EQ(material_formulation(model_of(stiff), kQuads, stiff).formulation, Formulation::Mixed)
        << model;
    const auto soft = material(model, {{"E", 1}, {"nu", 0.449}});
    EXPECT_EQ(material_formulation(model_of(soft), kQuads, soft).formulation,
              Formulation::Displacement)
        << model;
  }

  // Mohr-Coulomb: isochoric flow (psi = 0) one volume per cell; dilatant flow the displacement
  // formulation (docs/validation.md §8: the non-locking field pressure is not robust).
  const auto isochoric = material("mohr_coulomb", {{"c", 1}, {"phi", 30}, {"psi", 0}});
  EXPECT_EQ(describe(material_formulation(model_of(isochoric), kQuads, isochoric)),
            "F-bar (default for mohr_coulomb)");
  const auto dilatant = material("mohr_coulomb", {{"c", 1}, {"phi", 30}, {"psi", 10}, {"nu", 0.3}});
  EXPECT_EQ(describe(material_formulation(model_of(dilatant), kQuads, dilatant)),
            "displacement (default for mohr_coulomb)");
  // Nearly incompressible elasticity relieved whatever the model: Mohr-Coulomb then at the
  // field's pressure, which its yield condition depends on.
  const auto undrained =
      material("mohr_coulomb", {{"c", 1}, {"phi", 30}, {"psi", 10}, {"nu", 0.49}});
  EXPECT_EQ(describe(material_formulation(model_of(undrained), kQuads, undrained)),
            "mixed p-u at the field's pressure (default for mohr_coulomb)");
}

TEST(MaterialFormulation, WhatTheModelFileGivesWins) {
  auto tresca = material("tresca", {{"su", 1}, {"E", 500}, {"nu", 0.49}});
  tresca.formulation = Formulation::Displacement;
  EXPECT_EQ(describe(material_formulation(model_of(tresca), kQuads, tresca)),
            "displacement (given)");

  auto elastic = material("linear_elastic", {{"E", 1}, {"nu", 0.2}});
  spec::Model model = model_of(elastic);
  model.numerics.formulation = Formulation::Mixed;
  EXPECT_EQ(describe(material_formulation(model, kQuads, elastic)),
            "mixed p-u (numerics.formulation)");
  elastic.formulation = Formulation::FBar;  // the material's own over numerics'
  EXPECT_EQ(describe(material_formulation(model, kQuads, elastic)), "F-bar (given)");
}

TEST(MaterialFormulation, MohrCoulombInTheMixedFormulationSeesTheFieldsPressure) {
  // docs/validation.md §8: at its own pressure the mixed c-phi strip stops at 0.013 B.
  auto mc = material("mohr_coulomb", {{"c", 1}, {"phi", 20}, {"psi", 20}});
  mc.formulation = Formulation::Mixed;
  spec::Model model = model_of(mc);
  EXPECT_EQ(describe(material_formulation(model, kQuads, mc)),
            "mixed p-u at the field's pressure (given)");
  model.numerics.mixed_field_pressure = false;  // numerics.mixed_material_pressure: own
  EXPECT_FALSE(material_formulation(model, kQuads, mc).field_pressure);
  auto tresca = material("tresca", {{"su", 1}, {"E", 500}, {"nu", 0.49}});
  model.numerics.mixed_field_pressure = true;
  EXPECT_TRUE(material_formulation(model, kQuads, tresca).field_pressure);
}

TEST(MaterialFormulation, TrianglesTakeFBarWhereTheRuleSaysMixed) {
  Mesh triangles;
  triangles.cell_type = CellType::Tri3;
  const auto tresca = material("tresca", {{"su", 1}, {"E", 500}, {"nu", 0.49}});
  EXPECT_EQ(describe(material_formulation(model_of(tresca), triangles, tresca)),
            "F-bar (default for tresca)");
  Mesh tetrahedra_and_hexahedra;  // a mixed 3D mesh with a tetrahedron
  const std::vector<Index> hex = {0, 1, 2, 3, 4, 5, 6, 7}, tet = {1, 8, 2, 5};
  tetrahedra_and_hexahedra.add_cell(CellType::Hex8, hex);
  tetrahedra_and_hexahedra.add_cell(CellType::Tet4, tet);
  EXPECT_EQ(material_formulation(model_of(tresca), tetrahedra_and_hexahedra, tresca).formulation,
            Formulation::FBar);
  Mesh hexahedra;
  hexahedra.add_cell(CellType::Hex8, hex);
  EXPECT_EQ(material_formulation(model_of(tresca), hexahedra, tresca).formulation,
            Formulation::Mixed);
}

TEST(MaterialFormulation, FemRegionsTakeFBarWhereTheRuleSaysMixed) {
  spec::MeshRegion far_field;
  far_field.kind = CellKind::Fem;
  const auto tresca = material("tresca", {{"su", 1}, {"E", 500}, {"nu", 0.49}});
  spec::Model model = model_of(tresca);
  model.regions.push_back(far_field);
  EXPECT_EQ(describe(material_formulation(model, kQuads, tresca)), "F-bar (default for tresca)");
  const auto dilatant = material("mohr_coulomb", {{"c", 1}, {"phi", 30}, {"psi", 30}});
  EXPECT_EQ(material_formulation(model, kQuads, dilatant).formulation, Formulation::Displacement);
  const auto steel = material("linear_elastic", {{"E", 1e5}, {"nu", 0.2}});
  EXPECT_EQ(material_formulation(model, kQuads, steel).formulation, Formulation::Displacement);
}

constexpr const char* kModel = R"m(
analysis: {kinematics: plane_strain}
mesh: {generate: {x: {length: 1, cells: 2}, y: {length: 1, cells: 2}}}
materials:
  clay: {model: tresca, su: 5, E: 10000, nu: 0.49, density: 0}
  steel: {model: linear_elastic, E: 1.0e6, nu: 0.2, density: 0}
bodies:
  block: {material: clay, region: {box: {min: [0, 0], max: [1, 0.5]}}}
  plate: {material: steel, region: {box: {min: [0, 0.5], max: [1, 1]}}}
phases:
  - name: rest
    time_step: 1
    fixities: [{boundary: bottom, fix: all}]
)m";

TEST(MaterialFormulation, GeompmCheckNamesEachMaterialsFormulation) {
  const auto model = build_model(read_model_from_string(kModel, "model.yaml"));
  const std::string summary = describe_model(*model);
  EXPECT_NE(summary.find("material   clay: tresca E=10000 density=0 nu=0.49 su=5, mixed p-u "
                         "(default for tresca)\n"),
            std::string::npos)
      << summary;
  EXPECT_NE(summary.find("steel: linear_elastic E=1e+06 density=0 nu=0.2, displacement "
                         "(default for linear_elastic)\n"),
            std::string::npos)
      << summary;
}

TEST(MaterialFormulation, AFieldPressureMaterialRefusesTheIncrementalPressureEquation) {
  std::string text = std::string(kModel) + "numerics: {mixed_pressure_equation: incremental}\n";
  const auto at = text.find("nu: 0.49, density: 0}");
  text.replace(at, 21, "nu: 0.49, density: 0, formulation: mixed}");
  // The clay at its own pressure (Tresca's default): accepted.
  EXPECT_NO_THROW(build_model(read_model_from_string(text, "model.yaml")));
  text.replace(text.find("clay: {model: tresca, su: 5,"), 28,
               "clay: {model: mohr_coulomb, c: 5, phi: 20, psi: 20,");
  try {
    build_model(read_model_from_string(text, "model.yaml"));
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("numerics.mixed_pressure_equation"), std::string::npos) << what;
    EXPECT_NE(what.find("material 'clay' takes the mixed p-u formulation at the field's pressure"),
              std::string::npos)
        << what;
  }
}

}  // namespace
}  // namespace geompm

// The model reader on malformed models: each case edits one thing in a valid model and expects an
// InputError whose message names the file, the line (computed from the edited text) and the key
// path of the offending value, and says what is wrong.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "geompm/io/model_reader.hpp"
#include "model_reader_support.hpp"

namespace geompm {
namespace {

using namespace geompm::testing;

// The cases edit kValidModel (model_reader_support.hpp).

// A former penalty rigid footing, inserted in the second phase of kValidModel.
const std::string kFooting =
    "    rigid_footings:\n"
    "      - {name: plate, base: 55, x: [0, 0.5], contact: smooth, displacement: [0, "
    "\"-0.2*t\"]}\n";
struct MalformedCase {
  std::string name;
  std::vector<Edit> edits;  // applied in turn; each `from` must occur exactly once
  std::string line_marker;  // the expected line is the one where this text starts
  std::string key_path;     // expected key path ("" for YAML syntax errors)
  std::string explanation;  // a piece of the expected message
};

// The message of the InputError thrown for `text`, or a failure.
std::string input_error(const std::string& text, const std::string& file = "model.yaml") {
  try {
    read_model_from_string(text, file);
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected an InputError, got another exception: " << e.what();
    return "";
  }
  ADD_FAILURE() << "expected an InputError, the model was accepted";
  return "";
}

TEST(ModelReader, TheBaseOfTheMalformedCasesIsValid) {
  EXPECT_NO_THROW(read_model_from_string(kValidModel, "model.yaml"));
}

// Test names instead of a byte dump when a case fails.
void PrintTo(const MalformedCase& c, std::ostream* os) { *os << c.name; }

class ModelReaderMalformed : public ::testing::TestWithParam<MalformedCase> {};

TEST_P(ModelReaderMalformed, NamesFileLineKeyPathAndProblem) {
  const MalformedCase& c = GetParam();
  const std::string text = apply(kValidModel, c.edits);
  const std::string message = input_error(text);
  const int line = line_of(text, c.line_marker);
  // SourceLocation::describe(): "file:line: key.path: what"
  const std::string where = c.key_path.empty()
                                ? fmt::format("model.yaml:{}: ", line)
                                : fmt::format("model.yaml:{}: {}: ", line, c.key_path);
  EXPECT_EQ(message.rfind(where, 0), 0u)
      << "expected the message to start with '" << where << "'\n  message: " << message;
  EXPECT_NE(message.find(c.explanation), std::string::npos)
      << "expected '" << c.explanation << "' in\n  " << message;
}

const std::vector<MalformedCase> kMalformedCases = {
    // Unknown and missing keys.
    {"unknown_top_level_key",
     {{"materials:\n", "materails:\n"}},
     "materails:",
     "materails",
     "(did you mean 'materials'?)"},
    {"misspelt_nested_key",
     {{"{initial: 0.1, min", "{intial: 0.1, min"}},
     "intial",
     "phases[0].time_step.intial",
     "(did you mean 'initial'?)"},
    {"unknown_key_lists_the_allowed_ones",
     {{"vtk: {every: 2,", "vtk: {each: 2,"}},
     "each:",
     "output.vtk.each",
     "allowed keys: every, grid"},
    {"missing_section",
     {{"analysis:\n  kinematics: plane_strain\n", ""}},
     "title: Column",
     "analysis",
     "missing required key 'analysis'"},
    {"missing_required_key",
     {{"    material: soil\n    region: {box: {min: [0, 0]", "    region: {box: {min: [0, 0]"}},
     "  column:",
     "bodies.column.material",
     "missing required key 'material'"},
    {"duplicate_key",
     {{"bodies:\n", "  soil: {model: linear_elastic, E: 5, nu: 0.3}\nbodies:\n"}},
     "soil: {model",
     "materials.soil",
     "appears twice"},

    // Wrong types.
    {"text_for_a_number",
     {{"E: 1000", "E: soft"}},
     "E: soft",
     "materials.soil.E",
     "expected a number, found 'soft'"},
    {"quoted_number",
     {{"{length: 40, cells: 16}", "{length: 40, cells: \"16\"}"}},
     "\"16\"",
     "mesh.generate.y[0].cells",
     "quoted"},
    {"fraction_for_a_whole_number",
     {{"{length: 40, cells: 16}", "{length: 40, cells: 16.5}"}},
     "16.5",
     "mesh.generate.y[0].cells",
     "whole number"},
    {"map_for_a_list",
     {{"    fixities:\n      - {boundary: left, fix: normal}\n      - {plane: {axis: x, value: "
       "1.0}, fix: normal}\n      - {boundary: bottom, fix: all}\n",
       "    fixities: {boundary: left, fix: normal}\n"}},
     "fixities: {",
     "phases[0].fixities",
     "expected a list, found a map"},
    {"text_for_a_map",
     {{"analysis:\n  kinematics: plane_strain", "analysis: plane_strain"}},
     "analysis:",
     "analysis",
     "expected a map"},
    {"text_for_a_boolean",
     {{"ramp: true", "ramp: sometimes"}},
     "sometimes",
     "phases[0].gravity.ramp",
     "expected true or false"},

    // Unknown names.
    {"unknown_kinematics",
     {{"kinematics: plane_strain", "kinematics: plane_stress"}},
     "plane_stress",
     "analysis.kinematics",
     "(did you mean 'plane_strain'?)"},
    {"unknown_cell_type",
     {{"cell: quad4", "cell: quad8"}},
     "quad8",
     "mesh.generate.cell",
     "expected one of: tri3, tri6, quad4, tet4, hex8"},
    {"cell_of_the_wrong_dimension",
     {{"cell: quad4", "cell: hex8"}},
     "hex8",
     "mesh.generate.cell",
     "'hex8' cells are 3D"},
    {"crossed_diagonals_of_quadrilaterals",
     {{"cell: quad4", "cell: quad4\n    diagonals: crossed"}},
     "diagonals: crossed",
     "mesh.generate.diagonals",
     "split each rectangle into four tri3 cells, but the cell is 'quad4'"},
    {"unknown_diagonals",
     {{"cell: quad4", "cell: tri3\n    diagonals: both"}},
     "both",
     "mesh.generate.diagonals",
     "expected one of: alternating, crossed"},
    {"unknown_material_model",
     {{"model: linear_elastic", "model: cam_clay_9000"}},
     "cam_clay_9000",
     "materials.soil.model",
     "unknown material model 'cam_clay_9000'"},
    {"unknown_material",
     {{"    material: soil\n    region: {box: {min: [0, 0]",
       "    material: sand\n    region: {box: {min: [0, 0]"}},
     "material: sand",
     "bodies.column.material",
     "no material named 'sand'"},
    {"unknown_body",
     {{"    body: column", "    body: pile"}},
     "body: pile",
     "point_sets.top.body",
     "no body named 'pile'"},
    {"unknown_point_set",
     {{"{point_set: top, displacement", "{point_set: head, displacement"}},
     "point_set: head",
     "phases[1].prescribed_motion[0].point_set",
     "no point set named 'head'"},
    {"unknown_boundary",
     {{"{boundary: bottom, fix: all}", "{boundary: base, fix: all}"}},
     "boundary: base",
     "phases[0].fixities[2].boundary",
     "its boundaries are: left, right, bottom"},
    {"unknown_history_quantity",
     {{"{quantity: kinetic_energy}", "{quantity: stress}"}},
     "quantity: stress",
     "output.history[2].quantity",
     "expected one of: reaction"},

    // output.checkpoint.
    {"checkpoint_steps_negative",
     {{"  vtk: {every: 2, grid: false}\n",
       "  vtk: {every: 2, grid: false}\n"
       "  checkpoint: {every_steps: -5}\n"}},
     "every_steps: -5",
     "output.checkpoint.every_steps",
     "expected a whole number of steps >= 0 (0 = not by steps), found -5"},
    {"checkpoint_steps_fractional",
     {{"  vtk: {every: 2, grid: false}\n",
       "  vtk: {every: 2, grid: false}\n"
       "  checkpoint: {every_steps: 2.5}\n"}},
     "every_steps: 2.5",
     "output.checkpoint.every_steps",
     "expected a whole number, found '2.5'"},
    {"checkpoint_minutes_negative",
     {{"  vtk: {every: 2, grid: false}\n",
       "  vtk: {every: 2, grid: false}\n"
       "  checkpoint: {every_minutes: -1}\n"}},
     "every_minutes: -1",
     "output.checkpoint.every_minutes",
     "expected a number of minutes >= 0 (0 = not by time), found -1"},
    {"checkpoint_minutes_text",
     {{"  vtk: {every: 2, grid: false}\n",
       "  vtk: {every: 2, grid: false}\n"
       "  checkpoint: {every_minutes: often}\n"}},
     "every_minutes: often",
     "output.checkpoint.every_minutes",
     "expected a number, found 'often'"},
    {"checkpoint_unknown_key",
     {{"  vtk: {every: 2, grid: false}\n",
       "  vtk: {every: 2, grid: false}\n"
       "  checkpoint: {every_step: 5}\n"}},
     "every_step: 5",
     "output.checkpoint.every_step",
     "(did you mean 'every_steps'?)"},
    {"checkpoint_not_a_map",
     {{"  vtk: {every: 2, grid: false}\n",
       "  vtk: {every: 2, grid: false}\n"
       "  checkpoint: 10\n"}},
     "checkpoint: 10",
     "output.checkpoint",
     "expected a map (key: value, ...), found '10'"},

    // Material parameters, checked by the material model itself.
    {"young_modulus_not_positive",
     {{"E: 1000", "E: -5"}},
     "E: -5",
     "materials.soil.E",
     "must be > 0"},
    {"poisson_ratio_of_one_half",
     {{"nu: 0.0", "nu: 0.5"}},
     "nu: 0.5",
     "materials.soil.nu",
     "(-1, 0.5)"},
    {"poisson_ratio_below_minus_one",
     {{"nu: 0.0", "nu: -1.2"}},
     "nu: -1.2",
     "materials.soil.nu",
     "(-1, 0.5)"},
    {"missing_material_parameter",
     {{"    E: 1000\n", ""}},
     "  soil:",
     "materials.soil.E",
     "needs the parameter 'E'"},
    {"unknown_material_parameter",
     {{"    density: 0.08", "    density: 0.08\n    phi: 30"}},
     "phi:",
     "materials.soil.phi",
     "unknown parameter 'phi'"},

    // Non-finite numbers.
    {"nan",
     {{"density: 0.08", "density: .nan"}},
     ".nan",
     "materials.soil.density",
     "expected a finite number"},
    {"infinity_in_a_vector",
     {{"acceleration: [0, -10], ramp", "acceleration: [0, -.inf], ramp"}},
     "-.inf",
     "phases[0].gravity.acceleration[1]",
     "expected a finite number"},

    // Sizes and ranges.
    {"vector_of_the_wrong_length",
     {{"origin: [0, 0]", "origin: [0, 0, 0]"}},
     "origin:",
     "mesh.generate.origin",
     "expected a list of 2 numbers"},
    {"z_axis_in_2d",
     {{"x: {length: 1, cells: 1}", "x: {length: 1, cells: 1}\n    z: {length: 1}"}},
     "z: {",
     "mesh.generate.z",
     "no z axis"},
    {"segment_without_cells",
     {{"x: {length: 1, cells: 1}", "x: {length: 1, cells: 0}"}},
     "cells: 0",
     "mesh.generate.x.cells",
     "at least 1 cell"},
    {"negative_grading_ratio",
     {{"ratio: 2", "ratio: -2"}},
     "ratio: -2",
     "mesh.generate.y[1].ratio",
     "> 0"},
    {"points_per_cell_that_seeding_cannot_place",
     {{"points_per_cell: 4", "points_per_cell: 6"}},
     "points_per_cell: 6",
     "bodies.column.points_per_cell",
     "one of 1, 4, 9, 16"},
    {"box_with_min_not_below_max",
     {{"region: {box: {min: [0, 0], max: [1, 50]}}", "region: {box: {min: [0, 0], max: [0, 50]}}"}},
     "max: [0, 50]",
     "bodies.column.region.box.max",
     "min < max"},
    {"polygon_with_two_vertices",
     {{"polygon: [[0, 50], [1, 50], [0.5, 55]]", "polygon: [[0, 50], [1, 50]]"}},
     "polygon:",
     "bodies.block.region.polygon",
     "at least 3 vertices"},
    {"circle_without_radius",
     {{"radius: 0.5", "radius: 0"}},
     "radius: 0",
     "point_sets.side.region.circle.radius",
     "> 0"},
    {"empty_materials",
     {{kMaterials, "materials: {}\n"}},
     "materials:",
     "materials",
     "at least one material"},
    {"empty_phase_list", {{kPhases, "phases: []\n"}}, "phases:", "phases", "at least one phase"},
    {"zero_duration", {{"duration: 2", "duration: 0"}}, "duration: 0", "phases[1].duration", "> 0"},
    {"time_step_min_above_max",
     {{"{initial: 0.1, min: 1.0e-4, max: 0.2,", "{initial: 0.1, min: 0.5, max: 0.2,"}},
     "min: 0.5",
     "phases[0].time_step.min",
     "must not exceed max"},
    {"time_step_initial_above_max",
     {{"{initial: 0.1, min: 1.0e-4, max: 0.2,", "{initial: 0.3, min: 1.0e-4, max: 0.2,"}},
     "initial: 0.3",
     "phases[0].time_step.initial",
     "between min"},
    {"cutback_of_one",
     {{"cutback: 0.5", "cutback: 1.0"}},
     "cutback: 1.0",
     "phases[0].time_step.cutback",
     "(0, 1)"},
    {"growth_below_one",
     {{"growth: 1.5", "growth: 0.9"}},
     "growth: 0.9",
     "phases[0].time_step.growth",
     ">= 1"},
    {"newmark_beta_too_large",
     {{"beta: 0.3", "beta: 0.6"}},
     "beta: 0.6",
     "phases[1].dynamics.newmark.beta",
     "(0, 0.5]"},
    {"bossak_alpha_out_of_range",
     {{"{newmark: {beta: 0.3, gamma: 0.6}}", "{bossak: {alpha_m: -0.5}}"}},
     "alpha_m: -0.5",
     "phases[1].dynamics.bossak.alpha_m",
     "[-1/3, 0]"},
    {"newmark_and_bossak_together",
     {{"{newmark: {beta: 0.3, gamma: 0.6}}", "{newmark: , bossak: }"}},
     "{newmark: , bossak: }",
     "phases[1].dynamics",
     "one of newmark and bossak"},
    {"newton_without_iterations",
     {{"max_iterations: 15", "max_iterations: 0"}},
     "max_iterations: 0",
     "phases[0].newton.max_iterations",
     ">= 1"},
    {"tangent_check_step_too_large",
     {{"max_iterations: 15", "max_iterations: 15, tangent_check: 0.5"}},
     "tangent_check: 0.5",
     "phases[0].newton.tangent_check",
     "from 0 (off) to 0.1"},
    {"fixed_component_outside_the_model",
     {{"fix: [x, y]", "fix: [x, w]"}},
     "fix: [x, w]",
     "phases[1].fixities[0].fix[1]",
     "x, y (or 0, 1)"},

    // Expressions.
    {"bad_expression",
     {{"\"-0.1*t\"]}", "\"-0.1*t +\"]}"}},
     "-0.1*t +",
     "phases[1].prescribed_motion[0].displacement[1]",
     "invalid expression '-0.1*t +'"},
    {"load_as_a_function_of_position",
     {{"\"-10*t\"", "\"-10*x\""}},
     "-10*x",
     "phases[1].loads[0].force[1]",
     "uses 'x'"},
    {"initial_velocity_as_a_function_of_time",
     {{"0.1*sin(pi*y/50)", "0.1*sin(pi*t/50)"}},
     "0.1*sin(pi*t/50)",
     "bodies.column.initial_velocity[0]",
     "uses 't'"},
    {"motion_with_every_component_free",
     {{"[~, \"-0.1*t\"]", "[~, null]"}},
     "[~, null]",
     "phases[1].prescribed_motion[0].displacement",
     "every component is free"},
    {"motion_with_too_many_components",
     {{"[~, \"-0.1*t\"]", "[~, \"-0.1*t\", 0]"}},
     "[~, \"-0.1*t\", 0]",
     "phases[1].prescribed_motion[0].displacement",
     "expected a list of 2 components"},

    // The former penalty rigid footings: a model that still has them is told what replaced them.
    {"rigid_footings_replaced_by_structures",
     {{"    loads:\n", kFooting + "    loads:\n"}},
     "rigid_footings:",
     "phases[1].rigid_footings",
     "rigid footings are structures in contact with the soil"},
    {"history_of_a_footing",
     {{"    - {quantity: kinetic_energy}\n",
       "    - {quantity: kinetic_energy}\n    - {quantity: reaction, footing: pile, component: "
       "y}\n"}},
     "pile",
     "output.history[3].footing",
     "measure the footing with structure: <name>"},

    // Conflicts and duplicates.
    {"motion_and_load_on_one_point_set",
     {{"{point_set: side, force", "{point_set: top, force"}},
     "{point_set: top, force",
     "phases[1].loads[0]",
     "already has a prescribed motion"},
    {"duplicate_phase_name",
     {{"  - name: loading", "  - name: gravity"}},
     "name: gravity\n    duration: 2",
     "phases[1].name",
     "already used by phases[0]"},
    {"mesh_generated_and_imported",
     {{"mesh:\n  generate:", "mesh:\n  file: pile.msh\n  generate:"}},
     "file: pile.msh",
     "mesh.file",
     "give only one of generate, file"},
    {"missing_mesh_file",
     {{kMesh, "mesh:\n  file: meshes/none.msh\n"}},
     "file: meshes",
     "mesh.file",
     "mesh file 'meshes/none.msh' not found"},

    // Output.
    {"duplicate_history_column",
     {{"{quantity: kinetic_energy}", "{quantity: kinetic_energy, name: top_uy}"}},
     "name: top_uy}\n  plots",
     "output.history[2].name",
     "already defined by output.history[0]"},
    {"history_named_like_an_engine_column",
     {{"name: top_uy}", "name: time}"}},
     "name: time",
     "output.history[0].name",
     "always has"},
    {"reaction_without_target",
     {{"{quantity: reaction, boundary: bottom, component: y}",
       "{quantity: reaction, component: y}"}},
     "{quantity: reaction",
     "output.history[1]",
     "expected one of the keys boundary, point_set"},
    {"component_outside_the_model",
     {{"point_set: top, component: y", "point_set: top, component: z"}},
     "component: z",
     "output.history[0].component",
     "x, y (or 0, 1)"},
    {"scalar_quantity_with_component",
     {{"{quantity: kinetic_energy}", "{quantity: kinetic_energy, component: x}"}},
     "component: x",
     "output.history[2].component",
     "takes no component"},
    {"plot_of_an_unknown_column",
     {{"y: [reaction_bottom_y]", "y: [reaction_bottom_x]"}},
     "reaction_bottom_x",
     "output.plots[0].y[0]",
     "(did you mean 'reaction_bottom_y'?)"},
    {"plot_file_not_png",
     {{"file: settlement.png", "file: settlement.jpg"}},
     "settlement.jpg",
     "output.plots[0].file",
     "must end in .png"},
    {"plot_reference_band_upside_down",
     {{"y_scale: -1}", "y_scale: -1, reference: {y: [5.4, 5.14]}}"}},
     "reference:",
     "output.plots[0].reference.y",
     "must be below its upper"},
    {"plot_reference_without_value",
     {{"y_scale: -1}", "y_scale: -1, reference: {label: Prandtl}}"}},
     "reference:",
     "output.plots[0].reference.y",
     "missing required key 'y'"},
    {"unknown_lost_point_policy",
     {{"lost_points: remove", "lost_points: keep"}},
     "lost_points:",
     "numerics.lost_points",
     "expected one of: stop, remove"},
    {"unknown_formulation",
     {{"buffer_layers: 2,", "buffer_layers: 2, formulation: up,"}},
     "buffer_layers:",
     "numerics.formulation",
     "expected one of: displacement, f_bar, mixed"},
    {"surface_tangent_not_a_choice",
     {{"    density: 0.08\n", "    density: 0.08\n    surface_tangent: 1\n"}},
     "surface_tangent: 1",
     "materials.soil.surface_tangent",
     "expected one of: elastic, plastic"},
    {"material_formulation_not_a_choice",
     {{"    density: 0.08\n", "    density: 0.08\n    formulation: [mixed]\n"}},
     "formulation: [mixed]",
     "materials.soil.formulation",
     "expected"},
    {"negative_buffer_layers",
     {{"buffer_layers: 2", "buffer_layers: -1"}},
     "buffer_layers:",
     "numerics.buffer_layers",
     "from 0 to 100"},
    {"unknown_linear_solver",
     {{"linear_solver: sparse_lu", "linear_solver: petsc"}},
     "petsc",
     "numerics.linear_solver",
     "umfpack, sparse_lu"},
    {"petsc_options_for_a_solver_without_petsc",
     {{"linear_solver: sparse_lu", "linear_solver: sparse_lu, petsc_options: -ksp_type cg"}},
     "petsc_options",
     "numerics.petsc_options",
     "has no effect with linear_solver: sparse_lu"},
    {"petsc_options_not_in_petscs_syntax",
     {{"linear_solver: sparse_lu", "linear_solver: petsc_gamg, petsc_options: ksp_type cg"}},
     "petsc_options",
     "numerics.petsc_options",
     "'ksp_type' is not a PETSc option"},
    {"direct_limit_without_auto",
     {{"linear_solver: sparse_lu", "linear_solver: petsc_hypre, direct_limit: 1000"}},
     "direct_limit",
     "numerics.direct_limit",
     "has no effect without linear_solver: auto"},

    // Dimension-specific rules.
    {"axisymmetric_gravity_along_the_radius",
     {{"kinematics: plane_strain", "kinematics: axisymmetric"},
      {"acceleration: [0, -10], ramp", "acceleration: [1, -10], ramp"}},
     "acceleration: [1",
     "phases[0].gravity.acceleration",
     "x component must be 0"},
    {"sphere_in_2d",
     {{"{circle: {center", "{sphere: {center"}},
     "sphere:",
     "point_sets.side.region.sphere",
     "in 2D use circle"},

    // YAML syntax: yaml-cpp's message and line.
    {"yaml_syntax_error",
     {{"dynamics: quasi_static", "dynamics: quasi: static"}},
     "quasi: static",
     "",
     "YAML syntax error"},
    {"tab_indentation",
     {{"    duration: 2\n", "\tduration: 2\n"}},
     "\tduration",
     "",
     "YAML syntax error"},
};

INSTANTIATE_TEST_SUITE_P(ModelReader, ModelReaderMalformed, ::testing::ValuesIn(kMalformedCases),
                         [](const auto& info) { return info.param.name; });

TEST(ModelReader, RejectsAnEmptyModelFile) {
  EXPECT_NE(input_error("# nothing here\n").find("model.yaml:1: the model file is empty"),
            std::string::npos);
}

TEST(ModelReader, ReportsJsonErrorsWithTheirLine) {
  const std::string text = R"m({
  "analysis": {"kinematics": "3d"},
  "mesh": {"generate": {"x": {"length": 1, "cells": 1}, "y": {"length": 1, "cells": 1},
                        "z": {"length": 1, "cells": 1}}},
  "materials": {"clay": {"model": "linear_elastic", "E": 5000, "nu": 0.3}},
  "bodies": {
    "seabed": {"material": "clay",
               "region": {"polygon": [[0, 0], [1, 0], [1, 1]]}}
  },
  "phases": [{"name": "push", "time_step": 0.1}]
})m";
  const std::string message = input_error(text, "spudcan.json");
  EXPECT_EQ(message.rfind("spudcan.json:8: bodies.seabed.region.polygon: ", 0), 0u) << message;
  EXPECT_NE(message.find("in 3D use box or sphere"), std::string::npos) << message;
}

TEST(ModelReader, ReportsAJsonSyntaxErrorWithItsLine) {
  const std::string message = input_error(
      "{\n  \"analysis\": {\"kinematics\": \"3d\"}\n"
      "  \"mesh\": {}\n}\n",
      "broken.json");
  EXPECT_EQ(message.rfind("broken.json:3: YAML syntax error", 0), 0u) << message;
}

TEST(ModelReader, KeepsTheDefaultPointsPerCellValidForHexahedra) {
  // 4 points per cell is a quad's 2 x 2; asking for it in a hexahedron is an error, not a default.
  const std::string text = R"m(analysis: {kinematics: 3d}
mesh: {generate: {x: {length: 1, cells: 1}, y: {length: 1, cells: 1}, z: {length: 1, cells: 1}}}
materials: {clay: {model: linear_elastic, E: 5000, nu: 0.3}}
bodies: {seabed: {material: clay, region: all, points_per_cell: 4}}
phases: [{name: push, time_step: 0.1}]
)m";
  const std::string message = input_error(text);
  EXPECT_EQ(message.rfind("model.yaml:4: bodies.seabed.points_per_cell: ", 0), 0u) << message;
  EXPECT_NE(message.find("hex8 cells must be one of 1, 8, 27, 64"), std::string::npos) << message;
}

}  // namespace
}  // namespace geompm

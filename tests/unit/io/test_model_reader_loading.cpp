// The model reader on the keys of initial stresses and loading: bodies layered by depth
// (bodies.*.layers), the K0 procedure (phases[0].k0_procedure), node sets (node_sets) and the
// prescribed motion of grid nodes (phases[*].grid_motion). A valid model is read into the spec;
// each malformed case edits one thing and expects the file, line, key path and problem.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "geompm/io/model_reader.hpp"
#include "model_reader_support.hpp"

namespace geompm {
namespace {

using namespace geompm::testing;

// Level ground in two layers (K0 procedure), then a smooth strip footing pushed into it by the
// grid nodes under it.
const std::string kLoadingModel = R"m(analysis: {kinematics: plane_strain}
mesh:
  generate: {x: {length: 4, cells: 8}, y: {length: 6, cells: 12}}
materials:
  sand: {model: mohr_coulomb, c: 0, phi: 30, psi: 0, E: 20000, nu: 0.3, density: 1.8}
  clay: {model: linear_elastic, E: 10000, nu: 0.4, density: 2.0}
  rock: {model: linear_elastic, E: 100000, nu: 0.2, density: 2.4}
bodies:
  ground:
    region: {box: {min: [0, 0], max: [4, 5]}}
    layers:
      - {material: sand, bottom: 3}
      - {material: clay, bottom: 1}
      - {material: rock}
node_sets:
  footing_base: {box: {min: [0, 5], max: [0.5, 5]}}
phases:
  - name: geostatic
    time_step: 1
    gravity: {acceleration: [0, -10]}
    k0_procedure:
      K0: {clay: 0.7, rock: 0.4}
      bodies: [ground]
    fixities:
      - {boundary: left, fix: normal}
      - {boundary: right, fix: normal}
      - {boundary: bottom, fix: all}
  - name: footing
    time_step: 0.1
    gravity: {acceleration: [0, -10]}
    grid_motion:
      - {boundary: footing_base, displacement: [~, "-0.05*t"]}
      - {plane: {axis: x, value: 4}, velocity: [0, ~]}
    fixities:
      - {boundary: left, fix: normal}
      - {boundary: bottom, fix: all}
output:
  history:
    - {quantity: displacement, boundary: footing_base, component: y, name: settlement}
    - {quantity: reaction, boundary: footing_base, component: y, name: footing_force}
)m";

TEST(ModelReaderLoading, ReadsLineSearchAndMixedVolume) {
  std::string text =
      kLoadingModel + "numerics: {mixed_volume: cell_average, mixed_material_pressure: field}\n";
  const std::string step = "    time_step: 0.1\n";
  text.replace(text.find(step), step.size(),
               step +
                   "    newton: {line_search: 4, energy_line_search: 0.1, predictor: extrapolated, "
                   "extrapolated_patience: 20}\n");
  const spec::Model model = read_model_from_string(text, "model.yaml");
  EXPECT_TRUE(model.numerics.mixed_volume_average);
  EXPECT_EQ(model.numerics.mixed_field_pressure, true);
  EXPECT_FALSE(model.numerics.mixed_incremental_pressure);
  EXPECT_EQ(model.phases.at(1).newton.line_search, 4);
  EXPECT_EQ(model.phases.at(0).newton.line_search, -1);  // not set: automatic
  EXPECT_DOUBLE_EQ(model.phases.at(1).newton.energy_line_search, 0.1);
  EXPECT_DOUBLE_EQ(model.phases.at(0).newton.energy_line_search, 0.0);  // off
  EXPECT_TRUE(model.phases.at(1).newton.extrapolate);
  EXPECT_FALSE(model.phases.at(0).newton.extrapolate);
  EXPECT_EQ(model.phases.at(1).newton.extrapolated_patience, 20);
  EXPECT_EQ(model.phases.at(0).newton.extrapolated_patience, 0);  // half of max_iterations
  const spec::Model defaults = read_model_from_string(kLoadingModel, "model.yaml");
  EXPECT_FALSE(defaults.numerics.mixed_volume_average);              // per_point
  EXPECT_FALSE(defaults.numerics.mixed_field_pressure.has_value());  // by material
  const spec::Model incremental = read_model_from_string(
      kLoadingModel + "numerics: {mixed_pressure_equation: incremental}\n", "model.yaml");
  EXPECT_TRUE(incremental.numerics.mixed_incremental_pressure);
  EXPECT_EQ(defaults.numerics.pressure_stabilisation_floor, 0.0);
  const spec::Model floor = read_model_from_string(
      kLoadingModel + "numerics: {pressure_stabilisation_floor: 0.2}\n", "model.yaml");
  EXPECT_EQ(floor.numerics.pressure_stabilisation_floor, 0.2);
  EXPECT_FALSE(defaults.numerics.fitted_pressure_start);
  const spec::Model fitted = read_model_from_string(
      kLoadingModel + "numerics: {mixed_pressure_start: fitted}\n", "model.yaml");
  EXPECT_TRUE(fitted.numerics.fitted_pressure_start);
  EXPECT_EQ(defaults.numerics.sparse_node_stiffness, 0.0);  // off
  EXPECT_EQ(defaults.numerics.sparse_node_fill, 0.05);
  const spec::Model sparse = read_model_from_string(
      kLoadingModel + "numerics: {sparse_node_stiffness: 1.0e-2, sparse_node_fill: 0.02}\n",
      "model.yaml");
  EXPECT_EQ(sparse.numerics.sparse_node_stiffness, 1.0e-2);
  EXPECT_EQ(sparse.numerics.sparse_node_fill, 0.02);
  EXPECT_EQ(defaults.numerics.ghost_penalty, 0.0);  // off
  EXPECT_EQ(defaults.numerics.ghost_penalty_fill, 0.5);
  const spec::Model ghost = read_model_from_string(
      kLoadingModel + "numerics: {ghost_penalty: 3.0e-3, ghost_penalty_fill: 1}\n", "model.yaml");
  EXPECT_EQ(ghost.numerics.ghost_penalty, 3.0e-3);
  EXPECT_EQ(ghost.numerics.ghost_penalty_fill, 1.0);
  // An explicit 0 switches the penalty off and keeps the limit (a fill alone is refused below).
  const spec::Model off = read_model_from_string(
      kLoadingModel + "numerics: {ghost_penalty: 0, ghost_penalty_fill: 1}\n", "model.yaml");
  EXPECT_EQ(off.numerics.ghost_penalty, 0.0);
  EXPECT_EQ(off.numerics.ghost_penalty_fill, 1.0);
}

TEST(ModelReaderLoading, ReadsLayersK0NodeSetsAndGridMotions) {
  const spec::Model model = read_model_from_string(kLoadingModel, "model.yaml");
  const spec::Body& ground = model.bodies.at(0);
  EXPECT_TRUE(ground.material.empty());
  ASSERT_EQ(ground.layers.size(), 3u);
  EXPECT_EQ(ground.layers[0].material, "sand");
  EXPECT_EQ(ground.layers[0].bottom, 3.0);
  EXPECT_EQ(ground.layers[1].bottom, 1.0);
  EXPECT_FALSE(ground.layers[2].bottom.has_value());
  EXPECT_EQ(ground.layers[2].source.key_path, "bodies.ground.layers[2]");

  ASSERT_EQ(model.node_sets.size(), 1u);
  EXPECT_EQ(model.node_sets[0].name, "footing_base");
  EXPECT_EQ(model.node_sets[0].min, Vec3(0, 5, 0));
  EXPECT_EQ(model.node_sets[0].max, Vec3(0.5, 5, 0));

  ASSERT_TRUE(model.phases[0].k0_procedure.has_value());
  const spec::K0Procedure& k0 = *model.phases[0].k0_procedure;
  EXPECT_EQ(k0.k0.size(), 2u);  // sand takes its default, 1 - sin(phi)
  EXPECT_EQ(k0.k0.at("clay"), 0.7);
  EXPECT_EQ(k0.bodies, std::vector<std::string>{"ground"});
  EXPECT_FALSE(model.phases[1].k0_procedure.has_value());

  const auto& motions = model.phases[1].grid_motions;
  ASSERT_EQ(motions.size(), 2u);
  EXPECT_EQ(motions[0].boundary, "footing_base");
  EXPECT_FALSE(motions[0].velocity);
  EXPECT_EQ(motions[0].components[0], "");
  EXPECT_EQ(motions[0].components[1], "-0.05*t");
  EXPECT_EQ(motions[1].plane_axis, 0);
  EXPECT_EQ(motions[1].plane_value, 4.0);
  EXPECT_TRUE(motions[1].velocity);
  EXPECT_EQ(model.output.histories[0].boundary, "footing_base");
}

TEST(ModelReaderLoading, OneK0ForEveryMaterialAndAnEmptyProcedure) {
  const spec::Model one = read_model_from_string(
      apply(kLoadingModel, {{"K0: {clay: 0.7, rock: 0.4}", "K0: 0.6"}}), "model.yaml");
  EXPECT_EQ(one.phases[0].k0_procedure->k0.at("sand"), 0.6);
  EXPECT_EQ(one.phases[0].k0_procedure->k0.at("rock"), 0.6);
  // Every material with a default: the procedure may be given with nothing under it.
  const std::string sand_only =
      apply(kLoadingModel, {{"    layers:\n      - {material: sand, bottom: 3}\n      - {material: "
                             "clay, bottom: 1}\n      - {material: rock}\n",
                             "    material: sand\n"},
                            {"    k0_procedure:\n      K0: {clay: 0.7, rock: 0.4}\n      bodies: "
                             "[ground]\n",
                             "    k0_procedure:\n"}});
  const spec::Model empty = read_model_from_string(sand_only, "model.yaml");
  ASSERT_TRUE(empty.phases[0].k0_procedure.has_value());
  EXPECT_TRUE(empty.phases[0].k0_procedure->k0.empty());
  EXPECT_TRUE(empty.phases[0].k0_procedure->bodies.empty());
}

struct LoadingCase {
  std::string name;
  std::vector<Edit> edits;
  std::string line_marker;
  std::string key_path;
  std::string explanation;
};
void PrintTo(const LoadingCase& c, std::ostream* os) { *os << c.name; }

class ModelReaderLoadingMalformed : public ::testing::TestWithParam<LoadingCase> {};

TEST_P(ModelReaderLoadingMalformed, NamesFileLineKeyPathAndProblem) {
  const LoadingCase& c = GetParam();
  const std::string text = apply(kLoadingModel, c.edits);
  std::string message;
  try {
    read_model_from_string(text, "model.yaml");
    ADD_FAILURE() << "the model was accepted";
  } catch (const InputError& e) {
    message = e.what();
  }
  const std::string where =
      fmt::format("model.yaml:{}: {}: ", line_of(text, c.line_marker), c.key_path);
  EXPECT_EQ(message.rfind(where, 0), 0u) << "expected '" << where << "' first in\n  " << message;
  EXPECT_NE(message.find(c.explanation), std::string::npos)
      << "expected '" << c.explanation << "' in\n  " << message;
}

const std::vector<LoadingCase> kLoadingCases = {
    // bodies.*.layers
    {"layers_and_material",
     {{"    layers:\n", "    material: sand\n    layers:\n"}},
     "layers:",
     "bodies.ground.layers",
     "give only one of material, layers"},
    {"layers_not_a_list",
     {{"    layers:\n      - {material: sand, bottom: 3}\n      - {material: clay, bottom: 1}\n"
       "      - {material: rock}\n",
       "    layers: sand\n"}},
     "layers: sand",
     "bodies.ground.layers",
     "expected a list of layers"},
    {"one_layer",
     {{"      - {material: sand, bottom: 3}\n      - {material: clay, bottom: 1}\n", ""}},
     "layers:",
     "bodies.ground.layers",
     "at least 2 layers"},
    {"layer_of_an_unknown_material",
     {{"{material: clay, bottom: 1}", "{material: silt, bottom: 1}"}},
     "material: silt",
     "bodies.ground.layers[1].material",
     "no material named 'silt'"},
    {"layer_without_bottom",
     {{"{material: clay, bottom: 1}", "{material: clay}"}},
     "{material: clay}",
     "bodies.ground.layers[1].bottom",
     "missing required key 'bottom'"},
    {"last_layer_with_bottom",
     {{"{material: rock}", "{material: rock, bottom: 0}"}},
     "bottom: 0",
     "bodies.ground.layers[2].bottom",
     "remove its 'bottom'"},
    {"layers_not_top_down",
     {{"{material: clay, bottom: 1}", "{material: clay, bottom: 3.5}"}},
     "bottom: 3.5",
     "bodies.ground.layers[1].bottom",
     "must lie below that of the layer above (y = 3)"},
    {"layer_bottom_as_text",
     {{"{material: sand, bottom: 3}", "{material: sand, bottom: deep}"}},
     "bottom: deep",
     "bodies.ground.layers[0].bottom",
     "expected a number"},
    {"unknown_layer_key",
     {{"{material: sand, bottom: 3}", "{material: sand, base: 3}"}},
     "base: 3",
     "bodies.ground.layers[0].base",
     "allowed keys: material, bottom"},

    // phases[0].k0_procedure
    {"k0_in_a_later_phase",
     {{"    grid_motion:\n", "    k0_procedure: {K0: 0.5}\n    grid_motion:\n"}},
     "k0_procedure: {K0: 0.5}",
     "phases[1].k0_procedure",
     "allowed only in the first phase"},
    {"k0_without_gravity",
     {{"    time_step: 1\n    gravity: {acceleration: [0, -10]}\n", "    time_step: 1\n"}},
     "k0_procedure:",
     "phases[0].k0_procedure",
     "needs the phase's gravity"},
    {"k0_with_ramped_gravity",
     {{"    time_step: 1\n    gravity: {acceleration: [0, -10]}",
       "    time_step: 1\n    gravity: {acceleration: [0, -10], ramp: true}"}},
     "ramp: true",
     "phases[0].gravity.ramp",
     "remove 'ramp'"},
    {"k0_with_inclined_gravity",
     {{"    time_step: 1\n    gravity: {acceleration: [0, -10]}",
       "    time_step: 1\n    gravity: {acceleration: [1, -10]}"}},
     "acceleration: [1, -10]",
     "phases[0].gravity.acceleration",
     "must point straight down (-y)"},
    {"k0_of_an_unknown_material",
     {{"K0: {clay: 0.7, rock: 0.4}", "K0: {clay: 0.7, rock: 0.4, silt: 0.5}"}},
     "K0: {clay",
     "phases[0].k0_procedure.K0.silt",
     "no material named 'silt'"},
    {"k0_not_positive",
     {{"K0: {clay: 0.7, rock: 0.4}", "K0: {clay: -0.7, rock: 0.4}"}},
     "K0: {clay",
     "phases[0].k0_procedure.K0.clay",
     "expected a number > 0"},
    {"k0_as_a_list",
     {{"K0: {clay: 0.7, rock: 0.4}", "K0: [0.7, 0.4]"}},
     "K0: [",
     "phases[0].k0_procedure.K0",
     "a map of materials to numbers"},
    {"k0_missing_for_an_elastic_material",
     {{"K0: {clay: 0.7, rock: 0.4}", "K0: {clay: 0.7}"}},
     "K0: {clay",
     "phases[0].k0_procedure.K0",
     "no K0 for the material 'rock' (of body 'ground')"},
    {"k0_missing_altogether",
     {{"      K0: {clay: 0.7, rock: 0.4}\n", ""}},
     "k0_procedure:",
     "phases[0].k0_procedure.K0",
     "only mohr_coulomb has a default"},
    {"k0_of_an_unknown_body",
     {{"bodies: [ground]", "bodies: [soil]"}},
     "bodies: [soil]",
     "phases[0].k0_procedure.bodies[0]",
     "no body named 'soil'"},
    {"k0_misspelt_key",
     {{"      K0: {clay", "      k0: {clay"}},
     "k0: {clay",
     "phases[0].k0_procedure.k0",
     "(did you mean 'K0'?)"},

    // node_sets
    {"node_set_box_inside_out",
     {{"{min: [0, 5], max: [0.5, 5]}", "{min: [0.5, 5], max: [0, 5]}"}},
     "{min: [0.5, 5]",
     "node_sets.footing_base.box.max",
     "min <= max"},
    {"node_set_named_like_a_boundary",
     {{"  footing_base: {box:", "  top: {box:"}},
     "top: {box:",
     "node_sets.top",
     "is a boundary of the generated mesh already"},
    {"node_set_without_box",
     {{"  footing_base: {box: {min: [0, 5], max: [0.5, 5]}}", "  footing_base: {}"}},
     "footing_base: {}",
     "node_sets.footing_base.box",
     "missing required key 'box'"},

    // phases[*].grid_motion
    {"grid_motion_of_an_unknown_boundary",
     {{"{boundary: footing_base, displacement", "{boundary: footing, displacement"}},
     "boundary: footing,",
     "phases[1].grid_motion[0].boundary",
     "the node sets: footing_base"},
    {"grid_motion_without_nodes",
     {{"{boundary: footing_base, displacement", "{displacement"}},
     "{displacement",
     "phases[1].grid_motion[0]",
     "expected one of the keys boundary, plane"},
    {"grid_motion_with_displacement_and_velocity",
     {{"displacement: [~, \"-0.05*t\"]}", "displacement: [~, \"-0.05*t\"], velocity: [~, 1]}"}},
     "velocity: [~, 1]",
     "phases[1].grid_motion[0].velocity",
     "give only one of displacement, velocity"},
    {"grid_motion_all_free",
     {{"displacement: [~, \"-0.05*t\"]}", "displacement: [~, ~]}"}},
     "displacement: [~, ~]",
     "phases[1].grid_motion[0].displacement",
     "every component is free"},
    {"grid_motion_of_position",
     {{"\"-0.05*t\"", "\"-0.05*x\""}},
     "-0.05*x",
     "phases[1].grid_motion[0].displacement[1]",
     "uses 'x'"},
    {"grid_motion_twice_on_a_boundary",
     {{"      - {plane: {axis: x, value: 4}, velocity: [0, ~]}",
       "      - {boundary: footing_base, velocity: [0, ~]}"}},
     "{boundary: footing_base, velocity",
     "phases[1].grid_motion[1]",
     "already driven in this phase"},

    // Histories of a boundary.
    {"velocity_of_a_boundary",
     {{"{quantity: displacement, boundary: footing_base",
       "{quantity: velocity, boundary: footing_base"}},
     "boundary: footing_base, component: y, name: settlement",
     "output.history[0].boundary",
     "only for reaction and displacement"},

    // Newton's backtracking and the volume change of mixed points.
    {"line_search_negative",
     {{"    time_step: 0.1\n", "    time_step: 0.1\n    newton: {line_search: -1}\n"}},
     "newton: {line_search: -1}",
     "phases[1].newton.line_search",
     "expected a whole number from 0 to 20"},
    {"energy_line_search_of_one",
     {{"    time_step: 0.1\n", "    time_step: 0.1\n    newton: {energy_line_search: 1}\n"}},
     "newton: {energy_line_search: 1}",
     "phases[1].newton.energy_line_search",
     "expected a tolerance from 0 (off) up to, not including, 1"},
    {"predictor_unknown",
     {{"    time_step: 0.1\n", "    time_step: 0.1\n    newton: {predictor: linear}\n"}},
     "newton: {predictor: linear}",
     "phases[1].newton.predictor",
     "expected one of: zero, extrapolated"},
    {"extrapolated_patience_without_the_extrapolated_start",
     {{"    time_step: 0.1\n", "    time_step: 0.1\n    newton: {extrapolated_patience: 5}\n"}},
     "newton: {extrapolated_patience: 5}",
     "phases[1].newton.extrapolated_patience",
     "applies to the extrapolated start only"},
    {"extrapolated_patience_zero",
     {{"    time_step: 0.1\n",
       "    time_step: 0.1\n    newton: {predictor: extrapolated, extrapolated_patience: 0}\n"}},
     "extrapolated_patience: 0",
     "phases[1].newton.extrapolated_patience",
     "expected a whole number >= 1"},
    {"mixed_volume_unknown",
     {{"    - {quantity: reaction, boundary: footing_base, component: y, name: footing_force}\n",
       "    - {quantity: reaction, boundary: footing_base, component: y, name: footing_force}\n"
       "numerics: {mixed_volume: averaged}\n"}},
     "mixed_volume: averaged",
     "numerics.mixed_volume",
     "cell_average"},
    {"mixed_material_pressure_unknown",
     {{"    - {quantity: reaction, boundary: footing_base, component: y, name: footing_force}\n",
       "    - {quantity: reaction, boundary: footing_base, component: y, name: footing_force}\n"
       "numerics: {mixed_material_pressure: projected}\n"}},
     "mixed_material_pressure: projected",
     "numerics.mixed_material_pressure",
     "field"},
    {"mixed_pressure_equation_unknown",
     {{"    - {quantity: reaction, boundary: footing_base, component: y, name: footing_force}\n",
       "    - {quantity: reaction, boundary: footing_base, component: y, name: footing_force}\n"
       "numerics: {mixed_pressure_equation: rate}\n"}},
     "mixed_pressure_equation: rate",
     "numerics.mixed_pressure_equation",
     "expected one of: total, incremental"},
    {"mixed_pressure_equation_with_field_pressure",
     {{"    - {quantity: reaction, boundary: footing_base, component: y, name: footing_force}\n",
       "    - {quantity: reaction, boundary: footing_base, component: y, name: footing_force}\n"
       "numerics: {mixed_material_pressure: field, mixed_pressure_equation: incremental}\n"}},
     "mixed_pressure_equation: incremental",
     "numerics.mixed_pressure_equation",
     "applies to mixed_material_pressure: own"},
    {"mixed_pressure_start_unknown",
     {{"    - {quantity: reaction, boundary: footing_base, component: y, name: footing_force}\n",
       "    - {quantity: reaction, boundary: footing_base, component: y, name: footing_force}\n"
       "numerics: {mixed_pressure_start: last}\n"}},
     "mixed_pressure_start: last",
     "numerics.mixed_pressure_start",
     "expected one of: points, fitted"},
    {"pressure_stabilisation_floor_negative",
     {{"    - {quantity: reaction, boundary: footing_base, component: y, name: footing_force}\n",
       "    - {quantity: reaction, boundary: footing_base, component: y, name: footing_force}\n"
       "numerics: {pressure_stabilisation_floor: -0.1}\n"}},
     "pressure_stabilisation_floor: -0.1",
     "numerics.pressure_stabilisation_floor",
     ">= 0"},
    {"sparse_node_fill_of_zero",
     {{"    - {quantity: reaction, boundary: footing_base, component: y, name: footing_force}\n",
       "    - {quantity: reaction, boundary: footing_base, component: y, name: footing_force}\n"
       "numerics: {sparse_node_fill: 0}\n"}},
     "sparse_node_fill: 0",
     "numerics.sparse_node_fill",
     "expected a fraction of a node's support, 0 < fill <= 1, found 0"},
    {"sparse_node_stiffness_negative",
     {{"    - {quantity: reaction, boundary: footing_base, component: y, name: footing_force}\n",
       "    - {quantity: reaction, boundary: footing_base, component: y, name: footing_force}\n"
       "numerics: {sparse_node_stiffness: -1}\n"}},
     "sparse_node_stiffness: -1",
     "numerics.sparse_node_stiffness",
     ">= 0"},
    {"ghost_penalty_negative",
     {{"    - {quantity: reaction, boundary: footing_base, component: y, name: footing_force}\n",
       "    - {quantity: reaction, boundary: footing_base, component: y, name: footing_force}\n"
       "numerics: {ghost_penalty: -0.01}\n"}},
     "ghost_penalty: -0.01",
     "numerics.ghost_penalty",
     ">= 0"},
    {"ghost_penalty_fill_above_one",
     {{"    - {quantity: reaction, boundary: footing_base, component: y, name: footing_force}\n",
       "    - {quantity: reaction, boundary: footing_base, component: y, name: footing_force}\n"
       "numerics: {ghost_penalty: 0.01, ghost_penalty_fill: 1.5}\n"}},
     "ghost_penalty_fill: 1.5",
     "numerics.ghost_penalty_fill",
     "expected a fraction of an edge cell, 0 < fill <= 1, found 1.5"},
    // A fill limit without the stiffness it limits would otherwise be ignored silently.
    {"ghost_penalty_fill_without_penalty",
     {{"    - {quantity: reaction, boundary: footing_base, component: y, name: footing_force}\n",
       "    - {quantity: reaction, boundary: footing_base, component: y, name: footing_force}\n"
       "numerics: {ghost_penalty_fill: 0.3}\n"}},
     "ghost_penalty_fill: 0.3",
     "numerics.ghost_penalty_fill",
     "has no effect without numerics.ghost_penalty"},
    {"sparse_node_fill_without_stiffness",
     {{"    - {quantity: reaction, boundary: footing_base, component: y, name: footing_force}\n",
       "    - {quantity: reaction, boundary: footing_base, component: y, name: footing_force}\n"
       "numerics: {empty_cell_stiffness: 1.0e-4, sparse_node_fill: 0.1}\n"}},
     "sparse_node_fill: 0.1",
     "numerics.sparse_node_fill",
     "has no effect without numerics.sparse_node_stiffness"},
};

INSTANTIATE_TEST_SUITE_P(ModelReaderLoading, ModelReaderLoadingMalformed,
                         ::testing::ValuesIn(kLoadingCases),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace geompm

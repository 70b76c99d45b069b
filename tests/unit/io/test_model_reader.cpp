// The model reader on valid models: every key lands in the right spec field, defaults are those
// of model_spec.hpp, JSON works as well as YAML, paths resolve against the model's directory,
// and every part records where it came from.
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>

#include "geompm/io/model_reader.hpp"
#include "model_reader_support.hpp"

namespace geompm {
namespace {

using namespace geompm::testing;

// The valid model of model_reader_support.hpp with settings away from the defaults and the other
// ways to write some values: a numeric history component, unquoted load expressions, a fixity on
// the boundary "right", a plot of two columns.
const std::string& column_model() {
  static const std::string text = apply(
      kValidModel,
      {{"growth: 1.5, cutback: 0.5, target_iterations: 4",
        "growth: 1.25, cutback: 0.25, target_iterations: 3"},
       {"newton: {max_iterations: 15, residual_tolerance: 1.0e-8, displacement_tolerance: 1.0e-8}",
        "newton: {max_iterations: 12, residual_tolerance: 1.0e-9, displacement_tolerance: 1.0e-7, "
        "tangent_check: 1.0e-6}"},
       {"      - {boundary: bottom, fix: [x, y]}\n",
        "      - {boundary: bottom, fix: [x, y]}\n      - {boundary: right, fix: x}\n"},
       {"force: [\"0\", \"-10*t\"]", "force: [0, -10*t]"},
       {"{quantity: reaction, boundary: bottom, component: y}",
        "{quantity: reaction, boundary: bottom, component: 1}"},
       {"y: [reaction_bottom_y],", "y: [reaction_bottom_y, time],"}});
  return text;
}

TEST(ModelReader, ReadsEveryKeyOfACompleteModel) {
  const std::string& text = column_model();
  const spec::Model m = read_model_from_string(text, "column.yaml");

  EXPECT_EQ(m.file, "column.yaml");
  EXPECT_EQ(m.directory, std::filesystem::current_path().lexically_normal().string());
  EXPECT_EQ(m.title, "Column under self-weight");
  EXPECT_EQ(m.kinematics, Kinematics::PlaneStrain);

  ASSERT_TRUE(m.mesh.generate.has_value());
  EXPECT_TRUE(m.mesh.file.empty());
  const StructuredMeshSpec& g = *m.mesh.generate;
  EXPECT_EQ(g.cell_type, CellType::Quad4);
  EXPECT_EQ(g.origin, Vec3(0, 0, 0));
  ASSERT_EQ(g.axes[0].size(), 1u);
  EXPECT_DOUBLE_EQ(g.axes[0][0].length, 1.0);
  EXPECT_EQ(g.axes[0][0].cells, 1);
  EXPECT_DOUBLE_EQ(g.axes[0][0].ratio, 1.0);
  ASSERT_EQ(g.axes[1].size(), 2u);
  EXPECT_DOUBLE_EQ(g.axes[1][0].length, 40.0);
  EXPECT_EQ(g.axes[1][0].cells, 16);
  EXPECT_DOUBLE_EQ(g.axes[1][1].length, 20.0);
  EXPECT_EQ(g.axes[1][1].cells, 8);
  EXPECT_DOUBLE_EQ(g.axes[1][1].ratio, 2.0);
  EXPECT_TRUE(g.axes[2].empty());
  EXPECT_EQ(m.mesh.source.key_path, "mesh");
  EXPECT_EQ(m.mesh.source.line, line_of(text, "mesh:"));

  ASSERT_EQ(m.materials.size(), 1u);
  const spec::Material& soil = m.materials[0];
  EXPECT_EQ(soil.name, "soil");
  EXPECT_EQ(soil.model, "linear_elastic");
  EXPECT_EQ(soil.parameters,
            (std::map<std::string, double>{{"E", 1000}, {"nu", 0.0}, {"density", 0.08}}));
  EXPECT_EQ(soil.source.file, "column.yaml");
  EXPECT_EQ(soil.source.key_path, "materials.soil");
  EXPECT_EQ(soil.source.line, line_of(text, "  soil:"));

  ASSERT_EQ(m.bodies.size(), 2u);
  const spec::Body& column = m.bodies[0];
  EXPECT_EQ(column.name, "column");
  EXPECT_EQ(column.material, "soil");
  EXPECT_EQ(column.region.kind, spec::Region::Kind::Box);
  EXPECT_EQ(column.region.min, Vec3(0, 0, 0));
  EXPECT_EQ(column.region.max, Vec3(1, 50, 0));
  EXPECT_EQ(column.region.source.key_path, "bodies.column.region");
  EXPECT_EQ(column.region.source.line, line_of(text, "region: {box: {min: [0, 0]"));
  EXPECT_EQ(column.points_per_cell, 4);
  EXPECT_EQ(column.initial_velocity, (std::array<std::string, 3>{"0.1*sin(pi*y/50)", "0", "0"}));
  EXPECT_EQ(column.source.line, line_of(text, "  column:"));
  const spec::Body& block = m.bodies[1];
  EXPECT_EQ(block.region.kind, spec::Region::Kind::Polygon);
  ASSERT_EQ(block.region.polygon.size(), 3u);
  EXPECT_EQ(block.region.polygon[2], Vec3(0.5, 55, 0));
  EXPECT_EQ(block.points_per_cell, 9);
  EXPECT_EQ(block.initial_velocity, (std::array<std::string, 3>{"0", "0", "0"}));

  ASSERT_EQ(m.point_sets.size(), 2u);
  EXPECT_EQ(m.point_sets[0].name, "top");
  EXPECT_EQ(m.point_sets[0].body, "column");
  EXPECT_EQ(m.point_sets[0].region.min, Vec3(0, 49, 0));
  EXPECT_EQ(m.point_sets[1].name, "side");
  EXPECT_EQ(m.point_sets[1].body, "");  // all bodies
  EXPECT_EQ(m.point_sets[1].region.kind, spec::Region::Kind::Circle);
  EXPECT_EQ(m.point_sets[1].region.center, Vec3(0.5, 25, 0));
  EXPECT_DOUBLE_EQ(m.point_sets[1].region.radius, 0.5);
  EXPECT_EQ(m.point_sets[1].source.key_path, "point_sets.side");
  EXPECT_EQ(m.point_sets[1].source.line, line_of(text, "  side:"));

  ASSERT_EQ(m.phases.size(), 2u);
  const spec::Phase& gravity = m.phases[0];
  EXPECT_EQ(gravity.name, "gravity");
  EXPECT_EQ(gravity.source.key_path, "phases[0]");
  EXPECT_EQ(gravity.source.line, line_of(text, "- name: gravity"));
  EXPECT_DOUBLE_EQ(gravity.duration, 1.0);
  EXPECT_DOUBLE_EQ(gravity.time_step.initial, 0.1);
  EXPECT_DOUBLE_EQ(gravity.time_step.min, 1e-4);
  EXPECT_DOUBLE_EQ(gravity.time_step.max, 0.2);
  EXPECT_DOUBLE_EQ(gravity.time_step.growth, 1.25);
  EXPECT_DOUBLE_EQ(gravity.time_step.cutback, 0.25);
  EXPECT_EQ(gravity.time_step.target_iterations, 3);
  EXPECT_TRUE(gravity.dynamics.quasi_static);
  EXPECT_EQ(gravity.newton.max_iterations, 12);
  EXPECT_DOUBLE_EQ(gravity.newton.residual_tolerance, 1e-9);
  EXPECT_DOUBLE_EQ(gravity.newton.displacement_tolerance, 1e-7);
  EXPECT_DOUBLE_EQ(gravity.newton.tangent_check, 1e-6);
  ASSERT_TRUE(gravity.gravity.has_value());
  EXPECT_EQ(gravity.gravity->acceleration, Vec3(0, -10, 0));
  EXPECT_TRUE(gravity.gravity->ramp);
  ASSERT_EQ(gravity.fixities.size(), 3u);
  EXPECT_EQ(gravity.fixities[0].boundary, "left");
  EXPECT_TRUE(gravity.fixities[0].normal_only);
  EXPECT_EQ(gravity.fixities[0].plane_axis, -1);
  EXPECT_EQ(gravity.fixities[1].boundary, "");
  EXPECT_EQ(gravity.fixities[1].plane_axis, 0);
  EXPECT_DOUBLE_EQ(gravity.fixities[1].plane_value, 1.0);
  EXPECT_TRUE(gravity.fixities[1].normal_only);
  EXPECT_EQ(gravity.fixities[2].boundary, "bottom");
  EXPECT_FALSE(gravity.fixities[2].normal_only);
  EXPECT_EQ(gravity.fixities[2].components, (std::array<bool, 3>{true, true, false}));
  EXPECT_TRUE(gravity.motions.empty());
  EXPECT_TRUE(gravity.loads.empty());

  const spec::Phase& loading = m.phases[1];
  EXPECT_DOUBLE_EQ(loading.duration, 2.0);
  EXPECT_DOUBLE_EQ(loading.time_step.initial, 0.05);  // short form: a fixed step ...
  EXPECT_DOUBLE_EQ(loading.time_step.max, 0.05);
  EXPECT_DOUBLE_EQ(loading.time_step.min, 0.05e-3);  // ... that may be cut back 1000 times
  EXPECT_FALSE(loading.dynamics.quasi_static);
  EXPECT_DOUBLE_EQ(loading.dynamics.beta, 0.3);
  EXPECT_DOUBLE_EQ(loading.dynamics.gamma, 0.6);
  ASSERT_TRUE(loading.gravity.has_value());
  EXPECT_FALSE(loading.gravity->ramp);
  ASSERT_EQ(loading.fixities.size(), 2u);
  EXPECT_EQ(loading.fixities[0].components, (std::array<bool, 3>{true, true, false}));
  EXPECT_EQ(loading.fixities[0].source.key_path, "phases[1].fixities[0]");
  EXPECT_EQ(loading.fixities[0].source.line, line_of(text, "{boundary: bottom, fix: [x, y]}"));
  EXPECT_EQ(loading.fixities[1].components, (std::array<bool, 3>{true, false, false}));
  ASSERT_EQ(loading.motions.size(), 1u);
  EXPECT_EQ(loading.motions[0].point_set, "top");
  EXPECT_FALSE(loading.motions[0].velocity);
  EXPECT_EQ(loading.motions[0].components, (std::array<std::string, 3>{"", "-0.1*t", ""}));
  EXPECT_EQ(loading.motions[0].source.key_path, "phases[1].prescribed_motion[0]");
  EXPECT_EQ(loading.motions[0].source.line, line_of(text, "{point_set: top, displacement"));
  ASSERT_EQ(loading.loads.size(), 1u);
  EXPECT_EQ(loading.loads[0].point_set, "side");
  EXPECT_EQ(loading.loads[0].components, (std::array<std::string, 3>{"0", "-10*t", "0"}));
  EXPECT_EQ(loading.loads[0].source.key_path, "phases[1].loads[0]");

  EXPECT_EQ(m.output.vtk_every, 2);
  EXPECT_FALSE(m.output.vtk_grid);
  ASSERT_EQ(m.output.histories.size(), 3u);
  const auto& h = m.output.histories;
  EXPECT_EQ(h[0].name, "top_uy");
  EXPECT_EQ(h[0].quantity, "displacement");
  EXPECT_EQ(h[0].point_set, "top");
  EXPECT_EQ(h[0].component, 1);
  EXPECT_EQ(h[1].name, "reaction_bottom_y");  // default name: quantity_target_component
  EXPECT_EQ(h[1].boundary, "bottom");
  EXPECT_EQ(h[1].component, 1);
  EXPECT_EQ(h[1].source.key_path, "output.history[1]");
  EXPECT_EQ(h[1].source.line, line_of(text, "{quantity: reaction"));
  EXPECT_EQ(h[2].name, "kinetic_energy");
  EXPECT_EQ(h[2].component, -1);
  ASSERT_EQ(m.output.plots.size(), 1u);
  const spec::Plot& plot = m.output.plots[0];
  EXPECT_EQ(plot.file, "settlement.png");
  EXPECT_EQ(plot.x, "top_uy");
  EXPECT_EQ(plot.y, (std::vector<std::string>{"reaction_bottom_y", "time"}));
  EXPECT_DOUBLE_EQ(plot.x_scale, 1.0);
  EXPECT_DOUBLE_EQ(plot.y_scale, -1.0);
  EXPECT_EQ(plot.title, "Settlement");
  EXPECT_EQ(plot.source.key_path, "output.plots[0]");

  EXPECT_DOUBLE_EQ(m.numerics.empty_cell_stiffness, 1e-5);
  EXPECT_EQ(m.numerics.buffer_layers, 2);
  EXPECT_EQ(m.numerics.lost_points, spec::LostPointPolicy::Remove);
  EXPECT_EQ(m.numerics.linear_solver, "sparse_lu");
  EXPECT_FALSE(m.numerics.formulation.has_value());  // each material the one that suits it
  EXPECT_FALSE(m.materials[0].formulation.has_value());
}

TEST(ModelReader, ReadsPlotLabelsAndReferenceLinesAndBands) {
  const std::string text = testing::apply(
      testing::kValidModel,
      {{"title: Settlement, y_scale: -1}",
        "title: Settlement, y_scale: -1, x_label: \"settlement (m)\",\n"
        "       y_label: load (kN/m), reference: {y: 5.14, label: Prandtl}}\n"
        "    - {file: band.png, y: top_uy, reference: [{y: [1, 2]}, {y: 3, label: three}]}"}});
  const spec::Model m = read_model_from_string(text, "column.yaml");
  ASSERT_EQ(m.output.plots.size(), 2u);
  const spec::Plot& plot = m.output.plots[0];
  EXPECT_EQ(plot.x_label, "settlement (m)");
  EXPECT_EQ(plot.y_label, "load (kN/m)");
  ASSERT_EQ(plot.references.size(), 1u);
  EXPECT_DOUBLE_EQ(plot.references[0].lo, 5.14);
  EXPECT_DOUBLE_EQ(plot.references[0].hi, 5.14);
  EXPECT_EQ(plot.references[0].label, "Prandtl");
  const spec::Plot& band = m.output.plots[1];
  EXPECT_EQ(band.x_label, "");  // drawn as the column name with its scale
  ASSERT_EQ(band.references.size(), 2u);
  EXPECT_DOUBLE_EQ(band.references[0].lo, 1.0);
  EXPECT_DOUBLE_EQ(band.references[0].hi, 2.0);
  EXPECT_EQ(band.references[0].label, "");
  EXPECT_DOUBLE_EQ(band.references[1].lo, 3.0);
  EXPECT_EQ(band.references[1].label, "three");
}

TEST(ModelReader, ReadsTheMixedFormulationGloballyAndPerMaterial) {
  const std::string text = testing::apply(
      testing::kValidModel,
      {{"buffer_layers: 2,", "buffer_layers: 2, formulation: mixed,"},
       {"    density: 0.08\n", "    density: 0.08\n    formulation: displacement\n"}});
  const spec::Model m = read_model_from_string(text, "model.yaml");
  EXPECT_EQ(m.numerics.formulation, spec::Formulation::Mixed);
  EXPECT_EQ(m.materials[0].formulation, spec::Formulation::Displacement);
  EXPECT_EQ(m.materials[0].parameters.count("formulation"), 0u);
}

TEST(ModelReader, ReadsTheFBarFormulationAndNamesTheChoices) {
  const std::string text =
      testing::apply(testing::kValidModel,
                     {{"    density: 0.08\n", "    density: 0.08\n    formulation: f_bar\n"}});
  EXPECT_EQ(read_model_from_string(text, "model.yaml").materials[0].formulation,
            spec::Formulation::FBar);
  const std::string wrong =
      testing::apply(testing::kValidModel,
                     {{"    density: 0.08\n", "    density: 0.08\n    formulation: fbar\n"}});
  try {
    read_model_from_string(wrong, "model.yaml");
    ADD_FAILURE() << "an unknown formulation was accepted";
  } catch (const std::exception& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("model.yaml"), std::string::npos) << message;
    EXPECT_NE(message.find("f_bar"), std::string::npos) << message;
    EXPECT_NE(message.find("fbar"), std::string::npos) << message;
  }
}

TEST(ModelReader, FillsDefaultsOfAMinimalModel) {
  const spec::Model m = read_model_from_string(R"m(
analysis: {kinematics: plane_strain}
mesh:
  generate: {x: {length: 2, cells: 2}, y: {length: 1, cells: 1}}
materials:
  clay: {model: neo_hookean, E: 100, nu: 0.3}
bodies:
  soil: {material: clay, region: all}
phases:
  - {name: only, time_step: {initial: 0.1}}
)m",
                                               "minimal.yaml");
  const spec::Model defaults;
  EXPECT_EQ(m.title, "");
  EXPECT_EQ(m.mesh.generate->cell_type, CellType::Quad4);
  EXPECT_EQ(m.mesh.generate->origin, Vec3::Zero());
  EXPECT_EQ(m.bodies[0].region.kind, spec::Region::Kind::All);
  EXPECT_EQ(m.bodies[0].points_per_cell, spec::Body{}.points_per_cell);
  EXPECT_EQ(m.bodies[0].initial_velocity, spec::Body{}.initial_velocity);
  EXPECT_TRUE(m.point_sets.empty());

  const spec::Phase& phase = m.phases[0];
  const spec::Phase default_phase;
  EXPECT_DOUBLE_EQ(phase.duration, default_phase.duration);
  EXPECT_DOUBLE_EQ(phase.time_step.initial, 0.1);
  EXPECT_DOUBLE_EQ(phase.time_step.max, 0.1);   // max defaults to initial
  EXPECT_DOUBLE_EQ(phase.time_step.min, 1e-4);  // min to initial / 1000
  EXPECT_DOUBLE_EQ(phase.time_step.growth, default_phase.time_step.growth);
  EXPECT_DOUBLE_EQ(phase.time_step.cutback, default_phase.time_step.cutback);
  EXPECT_EQ(phase.time_step.target_iterations, default_phase.time_step.target_iterations);
  EXPECT_TRUE(phase.dynamics.quasi_static);
  EXPECT_EQ(phase.newton.max_iterations, default_phase.newton.max_iterations);
  EXPECT_DOUBLE_EQ(phase.newton.residual_tolerance, default_phase.newton.residual_tolerance);
  EXPECT_DOUBLE_EQ(phase.newton.displacement_tolerance,
                   default_phase.newton.displacement_tolerance);
  EXPECT_FALSE(phase.gravity.has_value());
  EXPECT_TRUE(phase.fixities.empty());

  EXPECT_EQ(m.output.vtk_every, defaults.output.vtk_every);
  EXPECT_EQ(m.output.vtk_grid, defaults.output.vtk_grid);
  EXPECT_TRUE(m.output.histories.empty());
  EXPECT_TRUE(m.output.plots.empty());
  EXPECT_DOUBLE_EQ(m.numerics.empty_cell_stiffness, defaults.numerics.empty_cell_stiffness);
  EXPECT_EQ(m.numerics.buffer_layers, defaults.numerics.buffer_layers);
  EXPECT_EQ(m.numerics.lost_points, defaults.numerics.lost_points);
  EXPECT_EQ(m.numerics.linear_solver, defaults.numerics.linear_solver);
}

TEST(ModelReader, ReadsTheCheckpointSchedule) {
  const std::string vtk = "  vtk: {every: 2, grid: false}\n";
  const spec::Model given = read_model_from_string(
      apply(kValidModel, {{vtk, vtk + "  checkpoint: {every_steps: 25, every_minutes: 2.5}\n"}}),
      "model.yaml");
  EXPECT_EQ(given.output.checkpoint.every_steps, 25);
  EXPECT_DOUBLE_EQ(given.output.checkpoint.every_minutes, 2.5);
  const spec::Model off = read_model_from_string(
      apply(kValidModel, {{vtk, vtk + "  checkpoint: {every_steps: 0, every_minutes: 0}\n"}}),
      "model.yaml");
  EXPECT_EQ(off.output.checkpoint.every_steps, 0);
  EXPECT_EQ(off.output.checkpoint.every_minutes, 0.0);
  // Defaults (docs/user-guide.md): every 100 steps and every 10 minutes; one key alone keeps the
  // other's default.
  const spec::Model defaults = read_model_from_string(kValidModel, "model.yaml");
  EXPECT_EQ(defaults.output.checkpoint.every_steps, 100);
  EXPECT_DOUBLE_EQ(defaults.output.checkpoint.every_minutes, 10.0);
  const spec::Model steps_only = read_model_from_string(
      apply(kValidModel, {{vtk, vtk + "  checkpoint: {every_steps: 7}\n"}}), "model.yaml");
  EXPECT_EQ(steps_only.output.checkpoint.every_steps, 7);
  EXPECT_DOUBLE_EQ(steps_only.output.checkpoint.every_minutes, 10.0);
}

TEST(ModelReader, TreatsOptionalListsLeftEmptyAsAbsent) {
  // What remains when every entry of an optional list has been commented out.
  const spec::Model m = read_model_from_string(R"m(
title:
analysis: {kinematics: plane_strain}
mesh: {generate: {x: {length: 1, cells: 1}, y: {length: 1, cells: 1}}}
materials: {soil: {model: linear_elastic, E: 1, nu: 0}}
bodies: {soil: {material: soil, region: all}}
point_sets:
#  top: {region: {box: {min: [0, 0.9], max: [1, 1]}}}
phases:
  - name: only
    time_step: 0.1
    fixities:
    prescribed_motion:
    loads:
output:
  history:
  plots:
numerics:
)m",
                                               "empty.yaml");
  EXPECT_EQ(m.title, "");
  EXPECT_TRUE(m.point_sets.empty());
  EXPECT_TRUE(m.phases[0].fixities.empty());
  EXPECT_TRUE(m.phases[0].motions.empty());
  EXPECT_TRUE(m.phases[0].loads.empty());
  EXPECT_TRUE(m.output.histories.empty());
  EXPECT_EQ(m.numerics.linear_solver, "umfpack");
}

TEST(ModelReader, NewmarkAloneTakesTheTrapezoidalDefaults) {
  const spec::Model m = read_model_from_string(R"m(
analysis: {kinematics: plane_strain}
mesh: {generate: {x: {length: 25, cells: 13}, y: {length: 1, cells: 1}}}
materials: {bar: {model: linear_elastic, E: 100, nu: 0, density: 1}}
bodies:
  bar: {material: bar, region: all, points_per_cell: 1, initial_velocity: ["0.1*sin(pi*x/50)", 0]}
phases:
  - {name: vibrate, duration: 50, time_step: 0.1, dynamics: newmark}
  - name: again
    time_step: 0.1
    dynamics:
      newmark:
)m",
                                               "bar.yaml");
  for (const spec::Phase& phase : m.phases) {
    EXPECT_FALSE(phase.dynamics.quasi_static);
    EXPECT_DOUBLE_EQ(phase.dynamics.beta, 0.25);
    EXPECT_DOUBLE_EQ(phase.dynamics.gamma, 0.5);
  }
  EXPECT_EQ(m.bodies[0].points_per_cell, 1);
}

TEST(ModelReader, DampedIsBossaksSchemeWithItsSecondOrderParameters) {
  const spec::Model m = read_model_from_string(R"m(
analysis: {kinematics: plane_strain}
mesh: {generate: {x: {length: 25, cells: 13}, y: {length: 1, cells: 1}}}
materials: {bar: {model: linear_elastic, E: 100, nu: 0, density: 1}}
bodies:
  bar: {material: bar, region: all, points_per_cell: 1}
phases:
  - {name: damped, duration: 50, time_step: 0.1, dynamics: damped}
  - {name: bossak, time_step: 0.1, dynamics: {bossak: }}
  - {name: strong, time_step: 0.1, dynamics: {bossak: {alpha_m: -0.3}}}
)m",
                                               "bar.yaml");
  for (int k = 0; k < 3; ++k) {
    const spec::Dynamics& d = m.phases[k].dynamics;
    const double alpha = k < 2 ? -0.1 : -0.3;
    EXPECT_FALSE(d.quasi_static);
    EXPECT_DOUBLE_EQ(d.alpha_m, alpha);
    EXPECT_DOUBLE_EQ(d.gamma, 0.5 - alpha);
    EXPECT_DOUBLE_EQ(d.beta, 0.25 * (1 - alpha) * (1 - alpha));
  }
}

TEST(ModelReader, ReadsAThreeDimensionalModelWrittenInJson) {
  const std::string text = R"m({
  "title": "Spudcan",
  "analysis": {"kinematics": "3d"},
  "mesh": {"generate": {"cell": "hex8", "origin": [-5, -5, -10],
                        "x": {"length": 10, "cells": 4},
                        "y": {"length": 10, "cells": 4},
                        "z": [{"length": 8, "cells": 4}, {"length": 2, "cells": 2, "ratio": 0.5}]}},
  "materials": {"clay": {"model": "linear_elastic", "E": 5000, "nu": 0.495}},
  "bodies": {"seabed": {"material": "clay", "region": {"box": {"min": [-5, -5, -10], "max": [5, 5, -2]}}}},
  "point_sets": {"tip": {"region": {"sphere": {"center": [0, 0, -2], "radius": 0.5}}}},
  "phases": [
    {"name": "push", "time_step": {"initial": 0.01, "max": 0.02},
     "fixities": [{"boundary": "back", "fix": ["y"]}, {"boundary": "bottom", "fix": "all"}],
     "prescribed_motion": [{"point_set": "tip", "velocity": [null, null, "-1"]}]}
  ],
  "output": {"history": [{"quantity": "reaction", "point_set": "tip", "component": "z"}]}
})m";
  const spec::Model m = read_model_from_string(text, "spudcan.json");
  EXPECT_EQ(m.kinematics, Kinematics::ThreeD);
  EXPECT_EQ(m.mesh.generate->cell_type, CellType::Hex8);
  EXPECT_EQ(m.mesh.generate->origin, Vec3(-5, -5, -10));
  ASSERT_EQ(m.mesh.generate->axes[2].size(), 2u);
  EXPECT_DOUBLE_EQ(m.mesh.generate->axes[2][1].ratio, 0.5);
  EXPECT_DOUBLE_EQ(m.materials[0].parameters.at("nu"), 0.495);
  EXPECT_EQ(m.bodies[0].region.max, Vec3(5, 5, -2));
  EXPECT_EQ(m.bodies[0].points_per_cell, 8);  // hexahedra have no 4-point rule
  EXPECT_EQ(m.point_sets[0].region.kind, spec::Region::Kind::Circle);
  EXPECT_DOUBLE_EQ(m.point_sets[0].region.radius, 0.5);
  const spec::Phase& push = m.phases[0];
  EXPECT_DOUBLE_EQ(push.time_step.max, 0.02);
  EXPECT_DOUBLE_EQ(push.time_step.min, 1e-5);
  EXPECT_EQ(push.fixities[0].components, (std::array<bool, 3>{false, true, false}));
  EXPECT_EQ(push.fixities[1].components, (std::array<bool, 3>{true, true, true}));
  EXPECT_TRUE(push.motions[0].velocity);
  EXPECT_EQ(push.motions[0].components, (std::array<std::string, 3>{"", "", "-1"}));
  EXPECT_EQ(m.output.histories[0].name, "reaction_tip_z");
  EXPECT_EQ(m.output.histories[0].component, 2);
  EXPECT_EQ(push.fixities[1].source.line, line_of(text, "{\"boundary\": \"bottom\""));
}

TEST(ModelReader, AxisymmetricModelsTakeGravityAlongTheAxis) {
  const spec::Model m = read_model_from_string(R"m(
analysis: {kinematics: axisymmetric}
mesh: {generate: {cell: tri3, x: {length: 5, cells: 10}, y: {length: 5, cells: 10}}}
materials: {soil: {model: hencky, E: 1000, nu: 0.3, density: 1.6}}
bodies: {soil: {material: soil, region: {group: all}, points_per_cell: 3}}
phases: [{name: geostatic, time_step: 1, gravity: {acceleration: [0, -9.81]}}]
)m",
                                               "cpt.yaml");
  EXPECT_EQ(m.kinematics, Kinematics::Axisymmetric);
  EXPECT_EQ(m.mesh.generate->cell_type, CellType::Tri3);
  EXPECT_EQ(m.mesh.generate->diagonals, Diagonals::Alternating);
  EXPECT_EQ(m.bodies[0].region.kind, spec::Region::Kind::Group);
  EXPECT_EQ(m.bodies[0].region.group, "all");
  EXPECT_EQ(m.bodies[0].points_per_cell, 3);
  EXPECT_EQ(m.phases[0].gravity->acceleration, Vec3(0, -9.81, 0));
}

TEST(ModelReader, Tri3MeshesCanCrossTheirDiagonals) {
  const spec::Model m = read_model_from_string(R"m(
analysis: {kinematics: plane_strain}
mesh: {generate: {cell: tri3, diagonals: crossed, x: {length: 2, cells: 2}, y: {length: 1, cells: 1}}}
materials: {soil: {model: hencky, E: 1000, nu: 0.3, density: 0}}
bodies: {soil: {material: soil, region: all, points_per_cell: 3}}
phases: [{name: rest, time_step: 1}]
)m",
                                               "crossed.yaml");
  EXPECT_EQ(m.mesh.generate->diagonals, Diagonals::Crossed);
}

TEST(ModelReader, PhasesShareSettingsThroughYamlMergeKeys) {
  const std::string text = R"m(
analysis: {kinematics: plane_strain}
mesh: {generate: {x: {length: 1, cells: 1}, y: {length: 1, cells: 1}}}
materials: {soil: {model: linear_elastic, E: 1, nu: 0}}
bodies: {soil: {material: soil, region: all}}
phases:
  - &common
    name: first
    time_step: {initial: 0.2, max: 0.4}
    newton: {max_iterations: 7}
  - <<: *common
    name: second
    duration: 3
)m";
  const spec::Model m = read_model_from_string(text, "merge.yaml");
  ASSERT_EQ(m.phases.size(), 2u);
  EXPECT_EQ(m.phases[1].name, "second");
  EXPECT_DOUBLE_EQ(m.phases[1].duration, 3.0);
  EXPECT_DOUBLE_EQ(m.phases[1].time_step.max, 0.4);
  EXPECT_EQ(m.phases[1].newton.max_iterations, 7);
}

// The annotated example of docs/user-guide.md stays a valid model.
TEST(ModelReader, ReadsTheExampleOfTheUserGuide) {
  std::ifstream guide(std::string(GEOMPM_SOURCE_DIR) + "/docs/user-guide.md");
  ASSERT_TRUE(guide) << "docs/user-guide.md not found";
  const std::string text((std::istreambuf_iterator<char>(guide)), std::istreambuf_iterator<char>());
  const std::size_t heading = text.find("## A complete annotated example");
  ASSERT_NE(heading, std::string::npos);
  const std::size_t begin = text.find("```yaml\n", heading) + 8;
  const std::size_t end = text.find("```", begin);
  ASSERT_NE(end, std::string::npos);
  const spec::Model m = read_model_from_string(text.substr(begin, end - begin), "guide.yaml");
  EXPECT_EQ(m.phases.size(), 2u);
  EXPECT_EQ(m.output.histories[1].name, "reaction_bottom_y");
}

// A model on disk with an imported mesh: the mesh path is resolved against the model's
// directory, not the working directory.
class ModelReaderFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = std::filesystem::temp_directory_path() /
                 ("geompm_model_reader_" + std::to_string(::getpid()));
    std::filesystem::create_directories(directory_ / "meshes");
    std::ofstream(directory_ / "meshes" / "pile.msh") << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }

  std::filesystem::path write_model(const std::string& mesh_file) {
    const std::filesystem::path path = directory_ / "pile.yaml";
    std::ofstream(path) << "analysis: {kinematics: plane_strain}\n"
                        << "mesh: {file: " << mesh_file << "}\n"
                        << "materials: {soil: {model: linear_elastic, E: 100, nu: 0.33}}\n"
                        << "bodies: {soil: {material: soil, region: {group: soil}, "
                           "points_per_cell: 3}}\n"
                        << "phases:\n"
                        << "  - name: install\n"
                        << "    time_step: 0.01\n"
                        << "    fixities: [{boundary: seabed_base, fix: all}]\n";
    return path;
  }

  std::filesystem::path directory_;
};

TEST_F(ModelReaderFiles, ResolvesTheMeshFileAgainstTheModelDirectory) {
  const std::filesystem::path model_path = write_model("meshes/pile.msh");
  const spec::Model m = read_model(model_path.string());
  EXPECT_EQ(m.file, model_path.string());
  EXPECT_EQ(m.directory, directory_.lexically_normal().string());
  EXPECT_FALSE(m.mesh.generate.has_value());
  EXPECT_EQ(m.mesh.file, (directory_ / "meshes" / "pile.msh").lexically_normal().string());
  EXPECT_TRUE(std::filesystem::path(m.mesh.file).is_absolute());
  // An imported mesh's boundary names are checked after import.
  EXPECT_EQ(m.phases[0].fixities[0].boundary, "seabed_base");
}

TEST_F(ModelReaderFiles, ReportsAMissingMeshFileWithItsLine) {
  const std::filesystem::path model_path = write_model("meshes/pile2.msh");
  try {
    read_model(model_path.string());
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(model_path.string() + ":2: mesh.file: "),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("not found"), std::string::npos) << e.what();
  }
}

TEST_F(ModelReaderFiles, ReportsAMissingModelFile) {
  const std::string path = (directory_ / "nothing.yaml").string();
  try {
    read_model(path);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path + ": the model file does not exist");
  }
}

}  // namespace
}  // namespace geompm

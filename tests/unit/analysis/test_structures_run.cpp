// Structures in a whole run (docs/theory.md §17): a rigid pipe above a soil block, driven by its
// prescribed motion in every component with gravity on, so that nothing but its drive acts on it.
// The histories give back the prescribed motion, the drive's reaction holds its weight and the
// weight's moment about the reference point, a second phase measures from its own start, the
// ParaView series has one file per output, and a resumed run reads the structure's state back.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "geompm/io/model_reader.hpp"
#include "geompm/structures/rigid_structure.hpp"
#include "run_model.hpp"

namespace geompm {
namespace {

const char* kModel = R"m(
analysis: {kinematics: plane_strain}
mesh:
  generate: {cell: quad4, origin: [0, 0], x: {length: 4, cells: 4}, y: {length: 4, cells: 4}}
materials:
  soil: {model: linear_elastic, E: 1000, nu: 0.3, density: 0}
bodies:
  ground: {material: soil, region: {box: {min: [0, 0], max: [4, 2]}}, points_per_cell: 4}
structures:
  - name: pipe
    shape: {type: pipe, diameter: 0.8, position: [2, 3], cell_size: 0.2}
    mass: 5
    reference_point: [2.3, 3]
phases:
  - name: push
    duration: 1
    time_step: 0.25
    gravity: {acceleration: [0, -10]}
    fixities: [{boundary: bottom, fix: all}, {boundary: left, fix: normal},
               {boundary: right, fix: normal}]
    structures:
      pipe: {displacement: ["0.1*t", "-0.2*t"], rotation: "0.4*t"}
  - name: hold
    duration: 0.5
    time_step: 0.25
    gravity: {acceleration: [0, -10]}
    fixities: [{boundary: bottom, fix: all}, {boundary: left, fix: normal},
               {boundary: right, fix: normal}]
    structures:
      pipe: {velocity: [0, "-0.2"], angular_velocity: 0}
output:
  history:
    - {quantity: reaction, structure: pipe, component: x}
    - {quantity: reaction, structure: pipe, component: y}
    - {quantity: moment, structure: pipe, component: z}
    - {quantity: displacement, structure: pipe, component: y}
    - {quantity: phase_displacement, structure: pipe, component: y}
    - {quantity: rotation, structure: pipe, component: z}
    - {quantity: position, structure: pipe, component: x}
)m";

TEST(StructuresRun, FollowTheirDriveAndReportItsReaction) {
  const spec::Model spec = read_model_from_string(kModel, "structures.yaml");
  testing::ModelRun run = testing::run_spec(spec, "structures_run");
  const auto t = run.column("time");
  const auto fx = run.column("reaction_pipe_x"), fy = run.column("reaction_pipe_y");
  const auto mz = run.column("moment_pipe_z"), uy = run.column("displacement_pipe_y");
  const auto phase_uy = run.column("phase_displacement_pipe_y");
  const auto rz = run.column("rotation_pipe_z"), x = run.column("position_pipe_x");
  ASSERT_EQ(t.size(), 7u);  // the initial row and 4 + 2 steps
  const double m = 5.0, g = 10.0;
  for (std::size_t k = 1; k < t.size(); ++k) {
    const double tp = std::min(t[k], 1.0);  // the first phase's time
    EXPECT_NEAR(uy[k], -0.2 * t[k], 1e-9);  // both phases move it down at 0.2
    EXPECT_NEAR(rz[k], 0.4 * tp, 1e-9);
    EXPECT_NEAR(x[k], 2.3 + 0.1 * tp, 1e-9);
    EXPECT_NEAR(phase_uy[k], t[k] <= 1.0 ? uy[k] : -0.2 * (t[k] - 1.0), 1e-9);
    // The drive holds the weight: +m g up, nothing along x.
    EXPECT_NEAR(fx[k], 0.0, 1e-9);
    EXPECT_NEAR(fy[k], m * g, 1e-9);
    // and its moment about the reference point, - s x F = m g s_x, with s (from the reference
    // point to the centre, (-0.3, 0) at the start) turned as at the start of the step.
    const double turned = rz[k - 1];
    EXPECT_NEAR(mz[k], m * g * (-0.3 * std::cos(turned)), 1e-8);  // 10 digits in the CSV
  }
  // One structure file per output, in its own series.
  const auto pvd = run.output / "structure_pipe.pvd";
  ASSERT_TRUE(std::filesystem::exists(pvd));
  std::ifstream in(pvd);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::size_t files = 0;
  for (std::size_t at = text.find(".vtu"); at != std::string::npos; at = text.find(".vtu", at + 1))
    ++files;
  EXPECT_EQ(files, 7u);

  // The checkpoint at the end holds the structure where the run left it.
  const auto* moved = dynamic_cast<const RigidStructure*>(run.model->structures[0].get());
  std::unique_ptr<Model> fresh = build_model(spec);
  RunOptions options;
  options.output_dir = run.output;
  options.progress = false;
  options.resume = true;
  run_analysis(*fresh, options);
  const auto* loaded = dynamic_cast<const RigidStructure*>(fresh->structures[0].get());
  EXPECT_EQ(loaded->displacement(), moved->displacement());
  EXPECT_EQ(loaded->rotation(), moved->rotation());
  EXPECT_EQ(loaded->mesh().nodes(), moved->mesh().nodes());
}

TEST(StructuresRun, TakeTheirMassFromAWeightAndTheGravity) {
  std::string text = kModel;
  text.replace(text.find("mass: 5"), 7, "weight: 6");
  const std::unique_ptr<Model> model = build_model(read_model_from_string(text, "s.yaml"));
  const auto* pipe = dynamic_cast<const RigidStructure*>(model->structures[0].get());
  EXPECT_DOUBLE_EQ(pipe->mass(), 0.6);  // W / g, per unit thickness
  // A weight and no gravity in any phase: no mass to take.
  const std::string gravity = "gravity: {acceleration: [0, -10]}";
  while (text.find(gravity) != std::string::npos)
    text.replace(text.find(gravity), gravity.size(), "");
  try {
    build_model(read_model_from_string(text, "s.yaml"));
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("structures[0].weight: a weight is turned into a mass"),
              std::string::npos)
        << e.what();
  }
}

// Axisymmetry: a spudcan on the axis, pushed down; its weight per radian is held by the drive,
// its radial motion and rotation by axisymmetry.
TEST(StructuresRun, AxisymmetricSpudcanHoldsItsWeightPerRadian) {
  std::string text = kModel;
  text.replace(text.find("plane_strain"), 12, "axisymmetric");
  const std::string pipe = "shape: {type: pipe, diameter: 0.8, position: [2, 3], cell_size: 0.2}";
  text.replace(text.find(pipe), pipe.size(),
               "shape: {type: spudcan, diameter: 2, tip_angle: 150, shoulder: 0.2, position: [0, "
               "2.5]}");
  text.replace(text.find("reference_point: [2.3, 3]"), 25, "reference_point: [0, 2.6]");
  const auto replace = [&text](const std::string& from, const std::string& to) {
    ASSERT_NE(text.find(from), std::string::npos) << from;
    text.replace(text.find(from), from.size(), to);
  };
  replace("pipe: {displacement: [\"0.1*t\", \"-0.2*t\"], rotation: \"0.4*t\"}",
          "pipe: {displacement: [~, \"-0.2*t\"]}");
  replace("pipe: {velocity: [0, \"-0.2\"], angular_velocity: 0}",
          "pipe: {velocity: [0, \"-0.2\"]}");
  testing::ModelRun run =
      testing::run_spec(read_model_from_string(text, "axi.yaml"), "structures_axi");
  const auto fy = run.column("reaction_pipe_y"), uy = run.column("displacement_pipe_y");
  const auto rz = run.column("rotation_pipe_z"), x = run.column("position_pipe_x");
  const auto fx = run.column("reaction_pipe_x"), mz = run.column("moment_pipe_z");
  for (std::size_t k = 1; k < fy.size(); ++k) {
    EXPECT_NEAR(fy[k], 5.0 * 10.0, 1e-9);  // the mass is per radian, as every mass
    EXPECT_EQ(fx[k], 0.0);                 // held by symmetry, not by the drive
    EXPECT_EQ(mz[k], 0.0);
    EXPECT_NEAR(uy[k], -0.2 * run.column("time")[k], 1e-9);
    EXPECT_EQ(rz[k], 0.0);
    EXPECT_EQ(x[k], 0.0);
  }
}

TEST(StructuresRun, AreDescribedByCheck) {
  const std::unique_ptr<Model> model =
      build_model(read_model_from_string(kModel, "structures.yaml"));
  const std::string text = describe_model(*model);
  EXPECT_NE(text.find("structure  pipe:"), std::string::npos) << text;
}

}  // namespace
}  // namespace geompm

namespace geompm {
namespace {

TEST(StructuresRun, AFreeStructureTouchingNothingStopsTheRunWithAHint) {
  // Free vertically under its weight, above the ground: nothing holds it in a quasi-static phase.
  std::string text = kModel;
  const std::string drive = R"(pipe: {displacement: ["0.1*t", "-0.2*t"], rotation: "0.4*t"})";
  text.replace(text.find(drive), drive.size(), R"(pipe: {displacement: [0, ~], rotation: 0})");
  std::string message;
  try {
    testing::run_spec(read_model_from_string(text, "free.yaml"), "structures_free");
  } catch (const std::exception& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("'structure:pipe'"), std::string::npos) << message;
  EXPECT_NE(message.find("touches nothing"), std::string::npos) << message;
}

}  // namespace
}  // namespace geompm

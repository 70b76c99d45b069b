// End-to-end: input that reads well but cannot run — expressions without a finite value,
// magnitudes no physical quantity has, models and meshes too big for the machine, a structure
// beside the mesh — is refused by `geompm check` (exit 2) with the file, the place and what was
// expected; and files named in a model that are not what they should be are reported as what
// they are (a directory, a device), not as "not found".
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "example_text.hpp"

namespace {

namespace fs = std::filesystem;

using namespace geompm::testing;

/// A block of 2 x 1 cells, its top layer of points driven (`motion`) or loaded, with the phase's
/// `extra` lines and the model's `tail` sections.
struct Parts {
  std::string mesh =
      "mesh:\n  generate: {cell: quad4, x: {length: 2, cells: 2}, y: {length: 1, cells: 1}}\n";
  std::string material = "{model: linear_elastic, E: 1000, nu: 0.3, density: 1}";
  std::string body_extra;
  std::string motion = "[~, \"-0.01*t\"]";
  std::string phase_extra;
  std::string tail;
};

std::string model_text(const Parts& p) {
  return "analysis: {kinematics: plane_strain}\n" + p.mesh +
         "materials:\n"
         "  soil: " +
         p.material +
         "\n"
         "bodies:\n"
         "  soil:\n"
         "    material: soil\n"
         "    region: {box: {min: [0, 0], max: [2, 1]}}\n" +
         p.body_extra +
         "point_sets:\n"
         "  top: {body: soil, region: {box: {min: [0, 0.5], max: [2, 1]}}}\n"
         "phases:\n"
         "  - name: push\n"
         "    time_step: 0.1\n"
         "    prescribed_motion:\n"
         "      - {point_set: top, displacement: " +
         p.motion +
         "}\n"
         "    fixities:\n"
         "      - {boundary: bottom, fix: all}\n" +
         p.phase_extra + p.tail;
}

/// 1-based line of the first `marker` in `text`.
int line_of(const std::string& text, const std::string& marker) {
  const std::size_t at = text.find(marker);
  EXPECT_NE(at, std::string::npos) << marker;
  return at == std::string::npos ? 0 : 1 + int(std::count(text.begin(), text.begin() + at, '\n'));
}

class InputBounds : public GeompmRunTest<> {
 protected:
  /// `geompm check model.yaml` refuses the model (exit 2, no crash, nothing on stdout) and
  /// names the model file; returns the message.
  std::string refused(const std::string& model) {
    write("model.yaml", model);
    const auto r = geompm({"check", "model.yaml"});
    EXPECT_TRUE(r.exited && r.exit_code == 2) << describe(r);
    EXPECT_TRUE(Contains(r.err, "model.yaml"));
    EXPECT_FALSE(Contains(r.err, "internal error"));
    return r.err;
  }
};

TEST_F(InputBounds, BaselineIsValid) {
  write("model.yaml", model_text({}));
  const auto r = geompm({"check", "model.yaml"});
  EXPECT_TRUE(r.exited && r.exit_code == 0) << describe(r);
}

// Constant expressions are evaluated where they are read.
TEST_F(InputBounds, NonFiniteConstantExpressions) {
  for (const std::string text : {"0/0", "1/0", "log(0)"}) {
    SCOPED_TRACE(text);
    Parts parts;
    parts.motion = "[~, \"" + text + "\"]";
    const std::string model = model_text(parts);
    const std::string err = refused(model);
    EXPECT_TRUE(Contains(err, "model.yaml:" + std::to_string(line_of(model, "displacement:")) +
                                  ": phases[0].prescribed_motion[0].displacement[1]: the "
                                  "expression '" +
                                  text + "' is"));
    EXPECT_TRUE(Contains(err, "expected a finite number"));
  }
}

// An expression of t is evaluated at its phase's start and end by check.
TEST_F(InputBounds, NonFiniteAtThePhaseStartOrEnd) {
  Parts parts;
  parts.motion = "[~, \"0.01*log(t)\"]";
  std::string err = refused(model_text(parts));
  EXPECT_TRUE(Contains(err,
                       "phases[0].prescribed_motion[0] (its y component): the expression "
                       "'0.01*log(t)' is -inf at t = 0"));
  parts.motion = "[~, \"0.01/(1-t)\"]";
  err = refused(model_text(parts));
  EXPECT_TRUE(Contains(err, "'0.01/(1-t)' is"));
  EXPECT_TRUE(Contains(err, "at t = 1"));
}

// Between the phase's start and end only the run meets it: it stops (exit 3) naming it.
TEST_F(InputBounds, NonFiniteMidPhaseStopsTheRun) {
  Parts parts;
  parts.motion = "[~, \"t > 0.45 && t < 0.75 ? 0/0 : -0.01*t\"]";
  write("model.yaml", model_text(parts));
  const auto check = geompm({"check", "model.yaml"});
  EXPECT_TRUE(check.exited && check.exit_code == 0) << describe(check);
  const auto r = geompm({"run", "-q", "-t", "1", "-o", "out", "model.yaml"});
  ASSERT_TRUE(r.exited) << describe(r);
  EXPECT_EQ(r.exit_code, 3) << describe(r);
  EXPECT_TRUE(Contains(r.err, "phases[0].prescribed_motion[0] (its y component)"));
  EXPECT_TRUE(Contains(r.err, "is nan at t = 0.5"));
  const Csv history = read_csv(work() / "out" / "history.csv");
  EXPECT_TRUE(history.problem.empty()) << history.problem;
  EXPECT_EQ(history.rows.size(), 5u) << "steps up to t = 0.4 and the initial row";
  EXPECT_TRUE(Contains(read_text(work() / "out" / "summary.json"), "\"status\": \"stopped\""));
}

TEST_F(InputBounds, NonFiniteInitialVelocity) {
  Parts parts;
  parts.body_extra = "    initial_velocity: [\"1/0\", 0]\n";
  std::string err = refused(model_text(parts));
  EXPECT_TRUE(Contains(err, "bodies.soil.initial_velocity[0]: the expression '1/0' is inf"));
  parts.body_extra = "    initial_velocity: [\"log(x - 1)\", 0]\n";
  err = refused(model_text(parts));
  EXPECT_TRUE(Contains(err, "bodies.soil.initial_velocity[0]: the expression 'log(x - 1)' is"));
  EXPECT_TRUE(Contains(err, "at x = 0.25"));
  parts.body_extra = "    initial_velocity: [\"1e300\", 0]\n";
  err = refused(model_text(parts));
  EXPECT_TRUE(Contains(err, "expected 0 or a magnitude between 1e-20 and 1e+20"));
}

TEST_F(InputBounds, MeaninglessMagnitudes) {
  Parts parts;
  parts.material = "{model: linear_elastic, E: 1e300, nu: 0.3, density: 1}";
  std::string err = refused(model_text(parts));
  EXPECT_TRUE(Contains(err,
                       "materials.soil.E: expected a number of magnitude between 1e-20 and "
                       "1e+20 (or 0), found '1e300'"));
  parts = {};
  parts.material = "{model: linear_elastic, E: 1000, nu: 0.3, density: 1e300}";
  err = refused(model_text(parts));
  EXPECT_TRUE(Contains(err, "materials.soil.density: expected a number of magnitude"));
  parts = {};
  parts.phase_extra = "    dynamics: {newmark: {beta: 1e-300}}\n";
  err = refused(model_text(parts));
  EXPECT_TRUE(Contains(err, "phases[0].dynamics.newmark.beta: expected a number of magnitude"));
}

TEST_F(InputBounds, OutOfRangeWholeNumbersSayTheRange) {
  Parts parts;
  parts.body_extra = "    points_per_cell: 1e10\n";
  const std::string err = refused(model_text(parts));
  EXPECT_TRUE(Contains(err,
                       "bodies.soil.points_per_cell: expected a whole number between "
                       "-2147483648 and 2147483647, found '1e10'"));
}

// 10^10 cells: refused with the estimate before anything is allocated (it used to end in
// std::bad_alloc after 40 s).
TEST_F(InputBounds, ModelTooBigForTheMachine) {
  Parts parts;
  parts.mesh =
      "mesh:\n  generate: {cell: quad4, x: {length: 2, cells: 100000}, y: {length: 1, cells: "
      "100000}}\n";
  const std::string err = refused(model_text(parts));
  EXPECT_TRUE(Contains(err, "mesh: the generated mesh has 1e+10 cells"));
  EXPECT_TRUE(Contains(err, "GB of memory"));
}

TEST_F(InputBounds, BoundsOnCountsThatWouldHang) {
  Parts parts;
  parts.tail = "numerics: {buffer_layers: 1e9}\n";
  std::string err = refused(model_text(parts));
  EXPECT_TRUE(Contains(err, "numerics.buffer_layers: expected a whole number from 0 to 100"));

  parts = {};
  parts.phase_extra = "    duration: 1e18\n";
  err = refused(model_text(parts));
  EXPECT_TRUE(Contains(err, "phases[0].time_step: the phase's duration 1e+18 takes at least"));

  parts = {};
  parts.phase_extra = "    duration: 1e10\n";
  parts.motion = "[~, 0]";
  parts.tail = "";
  std::string model = model_text(parts);
  model = replace_once(model, "time_step: 0.1", "time_step: {initial: 1e-3, max: 1000}");
  err = refused(model);
  EXPECT_TRUE(Contains(err, "below 1e-12 of the phase's duration"));

  parts = {};
  std::string history = "output:\n  history:\n";
  for (int k = 0; k < 10001; ++k)
    history += "    - {quantity: kinetic_energy, name: e" + std::to_string(k) + "}\n";
  parts.tail = history;
  err = refused(model_text(parts));
  EXPECT_TRUE(Contains(err, "output.history: 10001 history columns; at most 10000"));
}

TEST_F(InputBounds, MeshCommandRefusesAMeshTooBig) {
  const auto r = geompm({"mesh", "--size", "1", "1", "--h", "1e-5", "-o", "m.msh"});
  ASSERT_TRUE(r.exited) << describe(r);
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  EXPECT_TRUE(Contains(r.err, "gives about 2e+10 cells"));
  EXPECT_FALSE(fs::exists(work() / "m.msh"));
}

TEST_F(InputBounds, StructureBesideTheMesh) {
  // Contact acts only inside the mesh: a structure in contact wholly beside it, or above it,
  // touches nothing.
  Parts parts;
  const auto footing_at = [](const char* position) {
    return std::string(
               "structures:\n  - name: f\n    shape: {type: footing, width: 1, height: 0.2, "
               "position: ") +
           position + "}\n    density: 1\n";
  };
  parts.tail = footing_at("[5.5, 1]");
  EXPECT_TRUE(Contains(refused(model_text(parts)),
                       "structures[0]: the structure 'f' lies outside the mesh (which spans [0, "
                       "2] x [0, 1]): contact acts only inside it"));
  parts.tail = footing_at("[1, 7]");
  EXPECT_TRUE(Contains(refused(model_text(parts)), "the structure 'f' lies outside the mesh"));
  // On the block's top it is inside; beside it without contact it is a structure on its own.
  for (const std::string& tail :
       {footing_at("[1, 1]"), footing_at("[5.5, 1]") + "    contact: none\n"}) {
    parts.tail = tail;
    write("model.yaml", model_text(parts));
    EXPECT_EQ(geompm({"check", "model.yaml"}).exit_code, 0) << tail;
  }
}

// A mesh file that is a directory or a device is reported as such.
TEST_F(InputBounds, MeshFileOfTheWrongKind) {
  fs::create_directories(work() / "meshes");
  Parts parts;
  parts.mesh = "mesh: {file: meshes}\n";
  std::string err = refused(model_text(parts));
  EXPECT_TRUE(Contains(err, "mesh file 'meshes' is a directory, not a file"));
  EXPECT_FALSE(Contains(err, "not found"));
  parts.mesh = "mesh: {file: /dev/zero}\n";
  err = refused(model_text(parts));
  EXPECT_TRUE(Contains(err, "mesh file '/dev/zero' is not a regular file"));
  EXPECT_FALSE(Contains(err, "not found"));
}

}  // namespace

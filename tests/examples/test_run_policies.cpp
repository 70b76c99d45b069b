// End-to-end: what `geompm run` does when a run cannot simply go on (points leaving the mesh,
// steps that do not converge), adaptive time stepping, results independent of the thread count,
// and the --version / --help texts.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "example_text.hpp"

namespace {

namespace fs = std::filesystem;

using namespace geompm::testing;

// ---------------------------------------------------------------------------------------------
// Reading what a run wrote (history.csv: cli_support.hpp).

/// The history of a run that wrote every converged step: rows for steps 0, 1, 2, ... in order.
void expect_consecutive_steps(const Csv& history) {
  ASSERT_TRUE(history.problem.empty()) << history.problem;
  const auto steps = history.column("step");
  const auto times = history.column("time");
  for (std::size_t k = 0; k < steps.size(); ++k) {
    EXPECT_EQ(steps[k], static_cast<double>(k));
    if (k > 0) {
      EXPECT_GT(times[k], times[k - 1]);
    }
  }
}

/// Every .vtu file the series names exists.
void expect_series_files_exist(const fs::path& pvd) {
  ASSERT_TRUE(fs::is_regular_file(pvd)) << pvd;
  const std::string text = read_text(pvd);
  static const std::regex file(R"re(file="([^"]+)")re");
  int count = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), file); it != std::sregex_iterator();
       ++it, ++count)
    EXPECT_TRUE(fs::is_regular_file(pvd.parent_path() / (*it)[1].str())) << (*it)[1].str();
  EXPECT_GE(count, 1) << text;
}

bool is_png(const fs::path& file) {
  return read_text(file).substr(0, 8) == std::string("\x89PNG\r\n\x1a\n", 8);
}

// ---------------------------------------------------------------------------------------------
// Models.

/// A 6 x 1 strip of unit cells. The body "flyer" (cell [3, 4]) slides to the right at 10 m/s on a
/// frictionless base (rollers), and leaves the mesh after 0.25 s: its points pass x = 6 during
/// the 5th step of 0.05 s. The body "rest" (cell [0, 1]) stays put.
std::string flying_block_model(const std::string& numerics) {
  return R"(title: Block sliding off the mesh
analysis: {kinematics: plane_strain}
mesh:
  generate:
    cell: quad4
    x: {length: 6, cells: 6}
    y: {length: 1, cells: 1}
materials:
  rock: {model: linear_elastic, E: 1000, nu: 0.2, density: 1}
bodies:
  flyer:
    material: rock
    region: {box: {min: [3, 0], max: [4, 1]}}
    initial_velocity: ["10", "0"]
  rest:
    material: rock
    region: {box: {min: [0, 0], max: [1, 1]}}
point_sets:
  flyer: {body: flyer, region: all}
phases:
  - name: flight
    duration: 0.5
    time_step: 0.05
    dynamics: newmark
    gravity: {acceleration: [0, -10]}
    fixities:
      - {boundary: bottom, fix: normal}
output:
  vtk: {every: 1}
  history:
    - {quantity: position, point_set: flyer, component: x, name: flyer_x}
    - {quantity: kinetic_energy}
  plots:
    - {file: flight.png, x: time, y: [flyer_x]}
)" + numerics;
}

class RunPolicies : public GeompmRunTest<> {};

// (a) A point leaves the mesh under the default policy (stop): exit 3, the message names the
// points and where they would go, and the steps finished before are all kept.
TEST_F(RunPolicies, LostPointsStopTheRun) {
  write("model.yaml", flying_block_model(""));
  const auto r = geompm({"run", "-q", "-t", "1", "-o", "out", "model.yaml"});
  ASSERT_TRUE(r.exited && r.exit_code == 3) << describe(r);
  EXPECT_TRUE(Contains(r.err, "run stopped: phase 'flight'"));
  EXPECT_TRUE(Contains(r.err, "left the mesh (policy numerics.lost_points = stop)"));
  EXPECT_TRUE(Contains(r.err, "lost_points: remove"));

  // "point 1 would move to (6.25, 0.25, 0)": a point id and a position outside the mesh.
  static const std::regex point(
      R"re(point (\d+) would move to \(([-+.0-9eE]+), ([-+.0-9eE]+), ([-+.0-9eE]+)\))re");
  std::smatch match;
  ASSERT_TRUE(std::regex_search(r.err, match, point)) << describe(r);
  EXPECT_LT(std::stoi(match[1].str()), 4) << "the flyer's points are 0..3 (the first body)";
  EXPECT_GT(std::stod(match[2].str()), 6.0) << "the position should be past the mesh's end";

  // Stopped at t = 0.25 (during the 5th step), with the results up to t = 0.2 kept.
  static const std::regex times(
      R"re(time ([.0-9eE+-]+): \d+ material point\(s\).*Results up to time ([.0-9eE+-]+) are in out)re");
  std::string flat = r.err;
  std::replace(flat.begin(), flat.end(), '\n', ' ');
  ASSERT_TRUE(std::regex_search(flat, match, times)) << describe(r);
  const double stopped = std::stod(match[1].str()), kept = std::stod(match[2].str());
  EXPECT_NEAR(stopped, 0.25, 1e-9);

  const Csv history = read_csv(work() / "out" / "history.csv");
  expect_consecutive_steps(history);
  ASSERT_EQ(history.rows.size(), 5u) << "the initial state and the 4 steps before the loss";
  EXPECT_NEAR(history.column("time").back(), kept, 1e-9);
  EXPECT_NEAR(history.column("time").back(), 0.2, 1e-9);
  EXPECT_NEAR(history.column("flyer_x").back(), 3.5 + 10 * 0.2, 1e-3);
  expect_series_files_exist(work() / "out" / "points.pvd");
  EXPECT_TRUE(is_png(work() / "out" / "flight.png")) << "plots of the finished steps are drawn";
}

// (b) The same with lost_points: remove: the run finishes, without the flyer's points and mass.
TEST_F(RunPolicies, LostPointsRemoved) {
  write("model.yaml", flying_block_model("numerics: {lost_points: remove}\n"));
  const auto r = geompm({"run", "-t", "1", "-o", "out", "model.yaml"});
  ASSERT_TRUE(r.exited && r.exit_code == 0) << describe(r);
  static const std::regex summary(
      R"re(finished: \d+ steps, .*, (\d+) points left the mesh \(mass ([.0-9eE+-]+) removed\))re");
  std::smatch match;
  ASSERT_TRUE(std::regex_search(r.err, match, summary)) << describe(r);
  EXPECT_EQ(match[1].str(), "4") << "the flyer's 4 points";
  EXPECT_NEAR(std::stod(match[2].str()), 1.0, 1e-9) << "the flyer's mass (1 m2 at density 1)";

  const Csv history = read_csv(work() / "out" / "history.csv");
  expect_consecutive_steps(history);
  EXPECT_NEAR(history.column("time").back(), 0.5, 1e-9);
  EXPECT_EQ(history.rows.size(), 11u);
  const auto energy = history.column("kinetic_energy");
  EXPECT_NEAR(energy.front(), 50.0, 1e-9) << "1/2 m v^2 of the flyer";
  EXPECT_LT(energy.back(), 1e-2) << "the flyer's kinetic energy left with it";

  // Which points went, and where: on the log and in summary.json (two at t = 0.25, the other two
  // a step later).
  EXPECT_TRUE(Contains(r.err, "time 0.25: 2 material point(s) left the mesh and were removed"));
  static const std::regex point(R"re(point (\d+) would move to \(([-+.0-9eE]+), )re");
  ASSERT_TRUE(std::regex_search(r.err, match, point)) << describe(r);
  EXPECT_LT(std::stoi(match[1].str()), 4) << "the flyer's points are 0..3 (the first body)";
  EXPECT_GT(std::stod(match[2].str()), 6.0);
  const std::string json = read_text(work() / "out" / "summary.json");
  static const std::regex listed(
      R"re(\{\s*"id": (\d+),\s*"time": ([-+.0-9eE]+),\s*"position": \[\s*([-+.0-9eE]+),)re");
  int count = 0;
  for (auto it = std::sregex_iterator(json.begin(), json.end(), listed);
       it != std::sregex_iterator(); ++it, ++count) {
    EXPECT_LT(std::stoi((*it)[1].str()), 4);
    EXPECT_NEAR(std::stod((*it)[2].str()), 0.275, 0.025 + 1e-9);
    EXPECT_GT(std::stod((*it)[3].str()), 6.0);
  }
  EXPECT_EQ(count, 4) << json;
}

// A run that stops between two ParaView steps still writes the last converged state: the flyer
// leaves during step 5, so the points of step 4 (t = 0.2) are the series' last entry.
TEST_F(RunPolicies, AStoppedRunWritesItsLastConvergedState) {
  write("model.yaml", geompm::testing::replace_once(flying_block_model(""), "vtk: {every: 1}",
                                                    "vtk: {every: 1000}"));
  const auto r = geompm({"run", "-q", "-t", "1", "-o", "out", "model.yaml"});
  ASSERT_TRUE(r.exited && r.exit_code == 3) << describe(r);
  const std::string pvd = read_text(work() / "out" / "points.pvd");
  EXPECT_TRUE(
      Contains(pvd, "timestep=\"0.2\" group=\"\" part=\"0\" file=\"vtk/points_000004.vtu\""));
  expect_series_files_exist(work() / "out" / "points.pvd");
}

// A prescribed displacement the body cannot follow (the oedometer's block of height 1 squeezed by
// 2) used to end "finished" with the points about half-way; the run now stops and says so.
TEST_F(RunPolicies, APrescribedMotionTheBodyCannotFollowStopsTheRun) {
  write("model.yaml", geompm::testing::replace_once(
                          geompm::testing::example_text("oedometer/oedometer.yaml"),
                          "displacement: [~, \"-0.1*t\"]", "displacement: [~, \"-2*t\"]"));
  const auto r = geompm({"run", "-q", "-t", "1", "-o", "out", "model.yaml"});
  ASSERT_TRUE(r.exited) << describe(r);
  EXPECT_EQ(r.exit_code, 3) << describe(r);
  EXPECT_TRUE(Contains(r.err,
                       "phase 'compression': the points did not follow the displacement "
                       "prescribed to them"));
  EXPECT_TRUE(Contains(r.err, "phases[0].prescribed_motion[0] (top): the point set moved"));
  EXPECT_TRUE(Contains(r.err, "of the -2 prescribed"));
  EXPECT_TRUE(Contains(read_text(work() / "out" / "summary.json"), "\"status\": \"stopped\""));
}

TEST_F(RunPolicies, AllPointsRemoved) {
  // Only the flyer: it leaves the mesh at t = 0.25 and the phase goes on to t = 0.5.
  std::string model = flying_block_model("numerics: {lost_points: remove}\n");
  model = geompm::testing::replace_once(
      model, "  rest:\n    material: rock\n    region: {box: {min: [0, 0], max: [1, 1]}}\n", "");
  write("model.yaml", model);
  const auto r = geompm({"run", "-t", "1", "-o", "out", "model.yaml"});
  ASSERT_TRUE(r.exited) << describe(r);
  EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 3) << describe(r);
  EXPECT_TRUE(Contains(r.err, "left the mesh"));
  EXPECT_FALSE(Contains(r.err, "internal error"));
  const Csv history = read_csv(work() / "out" / "history.csv");
  expect_consecutive_steps(history);
  EXPECT_GE(history.rows.size(), 6u) << "the steps up to the loss of the last point are kept";
}

// A lone block sliding at constant velocity with no load at all (no gravity) is the simplest
// dynamic problem there is: every step should converge at once.
TEST_F(RunPolicies, UniformMotionWithoutLoads) {
  std::string model = flying_block_model("");
  model = geompm::testing::replace_once(model, "    gravity: {acceleration: [0, -10]}\n", "");
  model = geompm::testing::replace_once(model, "duration: 0.5", "duration: 0.1");
  model = geompm::testing::replace_once(
      model, "  rest:\n    material: rock\n    region: {box: {min: [0, 0], max: [1, 1]}}\n", "");
  write("model.yaml", model);
  const auto r = geompm({"run", "-q", "-t", "1", "-o", "out", "model.yaml"});
  ASSERT_TRUE(r.exited && r.exit_code == 0) << describe(r);
  const Csv history = read_csv(work() / "out" / "history.csv");
  expect_consecutive_steps(history);
  EXPECT_NEAR(history.column("flyer_x").back(), 3.5 + 10 * 0.1, 1e-6);
}

// (c) A very soft column under gravity asked to take its whole load in one step with at most 5
// Newton iterations a step (with the default 15 the step converges in 10, its first correction
// halved where it inverted points): Newton fails, the step is cut back until it converges, and
// the run still reaches the right settlement.
TEST_F(RunPolicies, AdaptiveTimeSteppingCutsBack) {
  std::string model = geompm::testing::example_text("column/column_large_deformation.yaml");
  model = geompm::testing::replace_once(model, "time_step: {initial: 0.05, min: 0.001, max: 0.05}",
                                        "time_step: {initial: 1.0, min: 0.001, max: 1.0}\n"
                                        "    newton: {max_iterations: 5}");
  write("column.yaml", model);
  const auto r = geompm({"run", "-t", "1", "-o", "out", "column.yaml"});
  ASSERT_TRUE(r.exited && r.exit_code == 0) << describe(r);
  static const std::regex summary(R"re(finished: (\d+) steps, .*, (\d+) cut-backs)re");
  std::smatch match;
  ASSERT_TRUE(std::regex_search(r.err, match, summary)) << describe(r);
  EXPECT_GT(std::stoi(match[2].str()), 0) << "the single step of 1.0 cannot converge";
  EXPECT_GT(std::stoi(match[1].str()), 1);

  const Csv history = read_csv(work() / "out" / "history.csv");
  expect_consecutive_steps(history);
  const auto time = history.column("time");
  ASSERT_GE(time.size(), 3u);
  EXPECT_LT(time[1], 1.0) << "the first converged step is a cut-back one";
  EXPECT_NEAR(time.back(), 1.0, 1e-9);
  // Closed form (Hencky law, see the example): top settlement -25.940 m, base reaction 40 kN/m.
  EXPECT_NEAR(history.column("top_settlement").back(), -25.940, 0.05 * 25.940);
  EXPECT_NEAR(history.column("base_reaction").back(), 40.0, 1e-6 * 40.0);
}

// (d) A step that cannot converge even at the smallest step: exit 3 with the reason, and the
// history of the phase before is kept.
TEST_F(RunPolicies, NoConvergenceAtTheSmallestTimeStep) {
  const std::string stubborn = R"(  - name: stubborn
    duration: 1.0
    time_step: {initial: 0.1, min: 0.1, max: 0.1}
    newton: {max_iterations: 1, residual_tolerance: 1.0e-14, displacement_tolerance: 1.0e-14}
    prescribed_motion:
      - {point_set: top, displacement: [~, "-0.1*t"]}
    fixities:
      - {boundary: left, fix: normal}
      - {boundary: right, fix: normal}
      - {boundary: bottom, fix: all}
output:
)";
  write("oedometer.yaml",
        geompm::testing::replace_once(geompm::testing::example_text("oedometer/oedometer.yaml"),
                                      "output:\n", stubborn));
  const auto r = geompm({"run", "-q", "-t", "1", "-o", "out", "oedometer.yaml"});
  ASSERT_TRUE(r.exited && r.exit_code == 3) << describe(r);
  EXPECT_TRUE(Contains(r.err, "run stopped: phase 'stubborn'"));
  EXPECT_TRUE(Contains(r.err, "did not converge with the smallest allowed time step (0.1)"));
  EXPECT_TRUE(Contains(r.err, "no convergence in 1 iterations"));
  // ... and where the model is most out of balance: the unknown, its node and position.
  EXPECT_TRUE(Contains(r.err, "; largest out-of-balance force ")) << r.err;
  EXPECT_TRUE(Contains(r.err, " in y at node ")) << r.err;
  EXPECT_TRUE(Contains(r.err, "Results up to time 1 are in out"));
  // newton.csv names the same node for the last iterate of the failed step (unknown 1: y).
  std::smatch node;
  ASSERT_TRUE(std::regex_search(r.err, node, std::regex(R"re( in y at node (\d+) )re"))) << r.err;
  const Csv newton = read_csv(work() / "out" / "newton.csv");
  ASSERT_FALSE(newton.rows.empty());
  EXPECT_EQ(newton.column("converged").back(), 0.0);
  EXPECT_EQ(newton.column("largest_residual_node").back(), std::stod(node[1].str()));
  EXPECT_EQ(newton.column("largest_residual_unknown").back(), 1.0);
  for (const double unknown : newton.column("largest_residual_unknown"))
    EXPECT_TRUE(unknown == 0.0 || unknown == 1.0) << "a displacement model: x or y";
  // Where each correction moved the model most: none before an attempt's first correction (its
  // step_length 0; a step tries whole corrections, then halved ones, before it is cut back), a
  // mesh node's x or y after it.
  const auto moved_node = newton.column("largest_correction_node"),
             moved_unknown = newton.column("largest_correction_unknown"),
             iteration = newton.column("iteration"), kept = newton.column("step_length");
  for (std::size_t k = 0; k < iteration.size(); ++k) {
    if (iteration[k] == 0.0) EXPECT_EQ(kept[k], 0.0) << "row " << k;
    if (kept[k] == 0.0) {
      EXPECT_EQ(moved_node[k], -1.0) << "row " << k;
    } else {
      EXPECT_GE(moved_node[k], 0.0) << "row " << k;
      EXPECT_TRUE(moved_unknown[k] == 0.0 || moved_unknown[k] == 1.0) << "row " << k;
    }
  }

  const Csv history = read_csv(work() / "out" / "history.csv");
  expect_consecutive_steps(history);
  ASSERT_EQ(history.rows.size(), 11u) << "the initial state and the 10 steps of the first phase";
  EXPECT_NEAR(history.column("time").back(), 1.0, 1e-9);
  EXPECT_NEAR(history.column("top_uy").back(), -0.1, 1e-3);
  expect_series_files_exist(work() / "out" / "points.pvd");
  EXPECT_TRUE(is_png(work() / "out" / "load_displacement.png"));
}

// (e) The thread count does not change a single digit of the results.
TEST_F(RunPolicies, ThreadCountDoesNotChangeResults) {
  const std::string model =
      (fs::path(GEOMPM_SOURCE_DIR) / "examples/oedometer/oedometer.yaml").string();
  const auto one = geompm({"run", "-q", "--threads", "1", "-o", "one", model});
  ASSERT_TRUE(one.exited && one.exit_code == 0) << describe(one);
  const auto two = geompm({"run", "-q", "--threads", "2", "-o", "two", model});
  ASSERT_TRUE(two.exited && two.exit_code == 0) << describe(two);
  const std::string history = read_text(work() / "one" / "history.csv");
  ASSERT_GT(std::count(history.begin(), history.end(), '\n'), 2);
  EXPECT_EQ(history, read_text(work() / "two" / "history.csv"));
  int compared = 0;
  for (const auto& entry : fs::directory_iterator(work() / "one" / "vtk")) {
    const fs::path other = work() / "two" / "vtk" / entry.path().filename();
    ASSERT_TRUE(fs::exists(other)) << other;
    EXPECT_TRUE(read_text(entry.path()) == read_text(other)) << entry.path().filename();
    ++compared;
  }
  EXPECT_GE(compared, 2);
}

// newton.csv logs Newton's active set: the points returned plastically at every iterate, and how
// many changed between elastic and plastic since the iterate before (-1 where an attempt
// starts). The thick Tresca cylinder of examples/thick_cylinder (r = 1 to 2 m, 20 x 2 cells of
// 2 x 2 points: 160 points) is expanded monotonically, so its plastic zone (r < c in Hill's
// solution) only grows from step to step, and once c reaches the outer radius every point flows
// (the limit pressure 2 s_u ln 2).
TEST_F(RunPolicies, NewtonLogsThePlasticPoints) {
  const std::string model =
      (fs::path(GEOMPM_SOURCE_DIR) / "examples/thick_cylinder/thick_cylinder.yaml").string();
  const auto r = geompm({"run", "-q", "-t", "1", "-o", "out", model});
  ASSERT_TRUE(r.exited && r.exit_code == 0) << describe(r);
  const Csv newton = read_csv(work() / "out" / "newton.csv");
  ASSERT_TRUE(newton.problem.empty()) << newton.problem;
  const auto step = newton.column("step"), iteration = newton.column("iteration");
  const auto plastic = newton.column("plastic_points"), changes = newton.column("plastic_changes");
  const auto converged = newton.column("converged");
  ASSERT_EQ(plastic.size(), step.size());
  constexpr double kPoints = 160.0;
  std::vector<double> zone;  // per step: the plastic points at the converged iterate
  for (std::size_t k = 0; k < step.size(); ++k) {
    EXPECT_GE(plastic[k], 0.0);
    EXPECT_LE(plastic[k], kPoints);
    const bool first_of_step = k == 0 || step[k - 1] != step[k];
    if (first_of_step) {
      EXPECT_EQ(iteration[k], 0.0);
      EXPECT_EQ(changes[k], -1.0) << "nothing to compare an attempt's first iterate with";
    } else if (changes[k] >= 0.0) {
      EXPECT_LE(changes[k], kPoints);
    }
    const bool last_of_step = k + 1 == step.size() || step[k + 1] != step[k];
    if (last_of_step && converged[k] == 1.0) zone.push_back(plastic[k]);
  }
  ASSERT_GE(zone.size(), 10u);
  for (std::size_t s = 1; s < zone.size(); ++s)
    EXPECT_GE(zone[s], zone[s - 1]) << "step " << s + 1 << ": the zone shrank";
  EXPECT_GT(zone.front(), 0.0) << "the first step yields the inner ring";
  EXPECT_LT(zone.front(), kPoints) << "... not the whole tube";
  EXPECT_EQ(zone.back(), kPoints) << "at the limit pressure every point flows";
}

// (f)
TEST(CommandLine, Version) {
  const fs::path here = fs::temp_directory_path();
  const fs::path capture = here / ("geompm_e2e_version_" + std::to_string(getpid()));
  fs::create_directories(capture);
  const auto r = run_geompm({"--version"}, here, capture);
  fs::remove_all(capture);
  ASSERT_TRUE(r.exited && r.exit_code == 0) << describe(r);
  EXPECT_TRUE(std::regex_match(r.out, std::regex("geompm [0-9]+\\.[0-9]+\\.[0-9]+\n"))) << r.out;
  EXPECT_EQ(r.out, std::string("geompm ") + GEOMPM_VERSION + "\n");
}

TEST(CommandLine, HelpListsTheCommands) {
  const fs::path here = fs::temp_directory_path();
  const fs::path capture = here / ("geompm_e2e_help_" + std::to_string(getpid()));
  fs::create_directories(capture);
  const auto r = run_geompm({"--help"}, here, capture);
  const auto run_help = run_geompm({"run", "--help"}, here, capture);
  fs::remove_all(capture);
  ASSERT_TRUE(r.exited && r.exit_code == 0) << describe(r);
  for (const std::string command : {"run", "check", "plot"})
    EXPECT_TRUE(std::regex_search(r.out, std::regex("\\n\\s+" + command + "\\s+\\S")))
        << "no line for '" << command << "' in:\n"
        << r.out;
  ASSERT_TRUE(run_help.exited && run_help.exit_code == 0) << describe(run_help);
  for (const std::string option : {"--output", "--threads", "--quiet"})
    EXPECT_TRUE(Contains(run_help.out, option));
}

}  // namespace

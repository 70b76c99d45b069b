// End-to-end: checkpoints and --resume (docs/user-guide.md, "Checkpoints and resuming"). A run
// killed with SIGKILL at a random moment and resumed ends exactly as one that never stopped
// (history.csv and newton.csv byte for byte, the final points to 1e-12), for a dynamic example
// and a plastic quasi-static one, also when it is killed half-way through writing a checkpoint;
// writing checkpoints does not change the results; and a checkpoint that cannot be used
// (missing, truncated, damaged, of another model or format version) stops --resume with exit 2,
// a message naming the file and the problem, and the output left as it was.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <random>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include "cli_support.hpp"
#include "example_text.hpp"
#include "geompm/io/checkpoint_file.hpp"
#include "process_support.hpp"
#include "read_vtu.hpp"

namespace {

namespace fs = std::filesystem;
using namespace geompm::testing;
using Clock = std::chrono::steady_clock;

nlohmann::json read_json(const fs::path& file) { return nlohmann::json::parse(read_text(file)); }

/// `model` with the checkpoint schedule `schedule` in its output section.
std::string with_checkpoints(const std::string& model, const std::string& schedule) {
  return replace_once(model, "output:\n", "output:\n  checkpoint: " + schedule + "\n");
}

/// The points file of a run's last step: the last entry of points.pvd.
fs::path last_points_file(const fs::path& dir) {
  const std::string pvd = read_text(dir / "points.pvd");
  static const std::regex file(R"re(file="([^"]+)")re");
  std::string last;
  for (auto it = std::sregex_iterator(pvd.begin(), pvd.end(), file); it != std::sregex_iterator();
       ++it)
    last = (*it)[1].str();
  EXPECT_FALSE(last.empty()) << dir / "points.pvd";
  return dir / last;
}

/// Every point array of the two files agrees to 1e-12 of its largest value.
void expect_same_points(const fs::path& expected_file, const fs::path& actual_file) {
  const ReadVtu expected = read_with_meshio(expected_file), actual = read_with_meshio(actual_file);
  ASSERT_EQ(actual.points.size(), expected.points.size());
  auto compare = [](const std::string& name, const std::vector<std::vector<double>>& a,
                    const std::vector<std::vector<double>>& b) {
    ASSERT_EQ(a.size(), b.size()) << name;
    double scale = 0.0;
    for (const auto& row : a)
      for (double v : row) scale = std::max(scale, std::abs(v));
    int differing = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      ASSERT_EQ(a[i].size(), b[i].size()) << name;
      for (std::size_t c = 0; c < a[i].size(); ++c)
        if (!(std::abs(a[i][c] - b[i][c]) <= 1e-12 * scale) && differing++ < 3)
          ADD_FAILURE() << name << " of point " << i << "[" << c << "]: " << b[i][c]
                        << ", expected " << a[i][c];
    }
    EXPECT_EQ(differing, 0) << name;
  };
  compare("position", expected.points, actual.points);
  ASSERT_EQ(actual.point_data.size(), expected.point_data.size());
  for (const auto& [name, array] : expected.point_data) {
    ASSERT_TRUE(actual.point_data.count(name)) << name;
    compare(name, array.rows, actual.point_data.at(name).rows);
  }
}

class Checkpoints : public GeompmRunTest<> {
 protected:
  /// Runs `model` with checkpoints off into "reference", timing it.
  double run_reference(const std::string& model) {
    write("reference.yaml", with_checkpoints(model, "{every_steps: 0, every_minutes: 0}"));
    const auto start = Clock::now();
    const auto r = geompm({"run", "-q", "-t", "1", "-o", "reference", "reference.yaml"});
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    EXPECT_TRUE(r.exited && r.exit_code == 0) << describe(r);
    EXPECT_FALSE(fs::exists(work() / "reference" / "checkpoint.bin")) << "checkpoints are off";
    return seconds;
  }

  /// Starts `run.yaml` into "killed" (with `environment`) and kills it with SIGKILL after
  /// `delay` seconds; true if it was killed while still running.
  bool kill_after(double delay, const std::vector<std::pair<std::string, std::string>>& env = {}) {
    fs::remove_all(work() / "killed");
    GeompmProcess run({"run", "-q", "-t", "1", "-o", "killed", "run.yaml"}, work(),
                      root_ / "capture", env);
    EXPECT_TRUE(run.started());
    const auto until = Clock::now() + std::chrono::duration<double>(delay);
    while (Clock::now() < until && run.running())
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    const bool was_running = run.running();
    run.kill();
    const CommandResult r = run.wait();
    if (was_running) {
      EXPECT_TRUE(!r.exited && r.signal == SIGKILL) << describe(r);
    }
    return was_running;
  }

  /// Runs `run.yaml` into "killed" with `args`, killed half-way through writing its n-th
  /// checkpoint (GEOMPM_TEST_KILL_IN_CHECKPOINT).
  CommandResult kill_in_checkpoint(int n, const std::vector<std::string>& args) {
    fs::remove_all(work() / "killed");
    std::vector<std::string> all = {"run", "-q", "-t", "1", "-o", "killed"};
    all.insert(all.end(), args.begin(), args.end());
    all.push_back("run.yaml");
    GeompmProcess run(all, work(), root_ / "capture",
                      {{"GEOMPM_TEST_KILL_IN_CHECKPOINT", std::to_string(n)}});
    return run.wait();
  }

  /// Resumes "killed" and checks that it ends as "reference" did, after `resumes` resumes.
  /// Returns what the resumed run printed.
  std::string resume_and_compare(std::size_t resumes = 1) {
    const auto r = geompm({"run", "-q", "-t", "1", "-o", "killed", "--resume", "run.yaml"});
    EXPECT_TRUE(r.exited && r.exit_code == 0) << describe(r);
    if (!r.exited || r.exit_code != 0) return r.err;
    EXPECT_TRUE(Contains(r.err, "resuming from killed/checkpoint.bin"));
    const fs::path reference = work() / "reference", resumed = work() / "killed";
    EXPECT_EQ(read_text(resumed / "history.csv"), read_text(reference / "history.csv"))
        << "history.csv differs from the uninterrupted run's";
    EXPECT_EQ(read_text(resumed / "newton.csv"), read_text(reference / "newton.csv"))
        << "newton.csv differs from the uninterrupted run's";
    EXPECT_EQ(read_text(resumed / "points.pvd"), read_text(reference / "points.pvd"));
    EXPECT_EQ(last_points_file(resumed).filename(), last_points_file(reference).filename());
    expect_same_points(last_points_file(reference), last_points_file(resumed));
    EXPECT_FALSE(fs::exists(resumed / "checkpoint.bin.tmp"));
    const auto expected = read_json(reference / "summary.json");
    const auto actual = read_json(resumed / "summary.json");
    EXPECT_EQ(actual.at("status"), "finished");
    for (const char* key : {"steps", "cutbacks", "newton_iterations", "time", "history"})
      EXPECT_EQ(actual.at(key), expected.at(key)) << key;
    EXPECT_EQ(actual.at("resumed_at_steps").size(), resumes);
    for (const auto& step : actual.at("resumed_at_steps"))
      EXPECT_LE(step.get<int>(), actual.at("steps").get<int>());
    return r.err;
  }

  /// Runs `model` uninterrupted, then with a checkpoint every 2 steps killed in its second (step
  /// 4): it resumes from step 2 and must end alike.
  void kill_in_second_checkpoint_and_resume(const std::string& model) {
    run_reference(model);
    write("run.yaml", model);
    const CommandResult r = kill_in_checkpoint(2, {"--checkpoint-every", "2"});
    ASSERT_TRUE(!r.exited && r.signal == SIGKILL) << describe(r);
    EXPECT_TRUE(Contains(resume_and_compare(), "step 2,"));
  }

  /// Runs `model` uninterrupted, then with checkpoints every `every` steps killed at a random
  /// moment of its run and resumed: both must end alike.
  void kill_at_random_and_resume(const std::string& model, int every) {
    const double duration = run_reference(model);
    write("run.yaml", with_checkpoints(model, "{every_steps: " + std::to_string(every) + "}"));
    const unsigned seed = std::random_device{}();
    std::mt19937 random(seed);
    // Late enough for a checkpoint to exist, early enough to be inside the run; a run that was
    // quicker this time (a less loaded machine) is killed earlier on the next try, one killed
    // before its first checkpoint later.
    double delay = std::uniform_real_distribution<double>(0.4, 0.8)(random) * duration;
    bool killed = false, saved = false;
    for (int attempt = 0; attempt < 5 && !(killed && saved); ++attempt) {
      std::cerr << "[ kill     ] after " << delay << " s of a " << duration << " s run (seed "
                << seed << ")\n";
      killed = kill_after(delay);
      saved = fs::exists(work() / "killed" / "checkpoint.bin");
      delay = killed ? 0.5 * (delay + duration) : 0.5 * delay;
    }
    ASSERT_TRUE(killed && saved) << "could not kill the run between its first checkpoint and "
                                    "its end";
    resume_and_compare();
  }
};

// Dynamic: the vibrating bar (Newmark, examples/vibrating_bar), 2500 steps of 0.1 s.
TEST_F(Checkpoints, AVibratingBarKilledAtRandomResumesExactly) {
  const std::string model = replace_once(example_text("vibrating_bar/vibrating_bar.yaml"),
                                         "duration: 50", "duration: 250");
  kill_at_random_and_resume(model, 20);
}

// Plastic, quasi-static: the rough strip footing on Tresca clay (mixed p-u, fitted pressure
// start, extrapolated Newton start), pushed to a settlement of 0.02 B.
TEST_F(Checkpoints, AStripFootingKilledAtRandomResumesExactly) {
  const std::string model = replace_once(example_text("strip_footing/strip_footing.yaml"),
                                         "duration: 1.0", "duration: 0.2");
  kill_at_random_and_resume(model, 1);
}

// Killed while it writes its third checkpoint (--checkpoint-every 10: steps 10, 20, 30): the
// temporary file is half written, checkpoint.bin is still the one of step 20, and the resumed run
// goes on from there (with the model's schedule: checkpoints never change the results).
TEST_F(Checkpoints, AKillWhileACheckpointIsWrittenResumesFromTheOneBefore) {
  const std::string model = example_text("vibrating_bar/vibrating_bar.yaml");
  run_reference(model);
  write("run.yaml", model);
  const CommandResult r = kill_in_checkpoint(3, {"--checkpoint-every", "10"});
  ASSERT_TRUE(!r.exited && r.signal == SIGKILL) << describe(r);
  const fs::path dir = work() / "killed";
  ASSERT_TRUE(fs::exists(dir / "checkpoint.bin.tmp")) << "the half-written checkpoint";
  EXPECT_LT(fs::file_size(dir / "checkpoint.bin.tmp"), fs::file_size(dir / "checkpoint.bin"));
  EXPECT_EQ(read_csv(dir / "history.csv").rows.size(), 31u) << "steps 0-30 were written";

  const auto resumed = geompm({"run", "-q", "-t", "1", "-o", "killed", "--resume", "run.yaml"});
  EXPECT_TRUE(Contains(resumed.err, "phase 'vibration', step 20,")) << describe(resumed);
  // resume_and_compare() resumes once more: from the run's final checkpoint, with nothing left
  // to do, which must change nothing either.
  resume_and_compare(2);
}

// Checkpoints by wall-clock time only (every 0.002 min = 0.12 s of a run of about two seconds):
// the third is written long before the end, and a kill in it resumes from the second.
TEST_F(Checkpoints, CheckpointsByWallClockTime) {
  const std::string model = replace_once(example_text("vibrating_bar/vibrating_bar.yaml"),
                                         "duration: 50", "duration: 250");
  run_reference(model);
  write("run.yaml", with_checkpoints(model, "{every_steps: 0, every_minutes: 0.002}"));
  const CommandResult r = kill_in_checkpoint(3, {});
  ASSERT_TRUE(!r.exited && r.signal == SIGKILL) << describe(r);
  const std::size_t rows = read_csv(work() / "killed" / "history.csv").rows.size();
  EXPECT_LT(rows, 2501u) << "killed before the end of the run";
  resume_and_compare();
}

// Checkpoints only at the ends of phases (--checkpoint-every 0; every 10 minutes is never
// reached), killed in the second: the run resumes at the start of the second phase of the
// Rankine wall (K0 geostatic phase, then the wall pushed; examples/earth_pressure).
TEST_F(Checkpoints, AKillInTheSecondPhaseResumesAtItsStart) {
  const std::string model = example_text("earth_pressure/rankine_active.yaml");
  run_reference(model);
  write("run.yaml", model);
  const CommandResult r = kill_in_checkpoint(2, {"--checkpoint-every", "0"});
  ASSERT_TRUE(!r.exited && r.signal == SIGKILL) << describe(r);
  const auto resumed = geompm({"run", "-q", "-t", "1", "-o", "killed", "--resume", "run.yaml"});
  EXPECT_TRUE(Contains(resumed.err, "resuming from killed/checkpoint.bin: phase 'geostatic'"))
      << describe(resumed);
  resume_and_compare(2);
  const auto phases = read_json(work() / "killed" / "summary.json").at("phases");
  ASSERT_EQ(phases.size(), 2u);
  for (const auto& phase : phases) EXPECT_EQ(phase.at("status"), "finished");
}

// A rough rigid structure in level-set contact (docs/theory.md §18) carries state from step to
// step: its pose and the contact's multipliers, penetrations and states. Killed in its second
// checkpoint (step 4), it resumes from step 2 with them.
TEST_F(Checkpoints, ARoughRigidFootingResumesWithItsContactState) {
  const std::string model = replace_once(example_text("structures/strip_footing_rough.yaml"),
                                         "duration: 1.0", "duration: 0.15");
  run_reference(model);
  write("run.yaml", model);
  const CommandResult r = kill_in_checkpoint(2, {"--checkpoint-every", "2"});
  ASSERT_TRUE(!r.exited && r.signal == SIGKILL) << describe(r);
  EXPECT_TRUE(Contains(resume_and_compare(), "phase 'push', step 2,"));
}

// A coupled model (examples/coupling: MPM near the footing, FEM beyond, docs/theory.md §19)
// carries the FEM region's Gauss points and the moved mesh from step to step. Killed in its
// second checkpoint (step 4), it resumes from step 2 with both and ends as the uninterrupted run.
TEST_F(Checkpoints, ACoupledModelResumesWithItsFemRegionAndMovedMesh) {
  kill_in_second_checkpoint_and_resume(replace_once(
      example_text("coupling/strip_footing_coupled.yaml"), "duration: 1.0", "duration: 0.2"));
}

// The same on a mesh of two cell types (strip_footing_coupled_mixed.yaml: quad4 MPM cells over
// tri3 FEM cells, docs/theory.md §19.5): the checkpoint carries the mixed mesh's moved nodes and
// the Gauss points of both kinds of cell. Killed in its second checkpoint (step 4), it resumes
// from step 2 and ends as the uninterrupted run.
TEST_F(Checkpoints, AMixedMeshResumesExactly) {
  kill_in_second_checkpoint_and_resume(
      replace_once(example_text("coupling/strip_footing_coupled_mixed.yaml"), "duration: 1.0",
                   "duration: 0.15"));
}

// A surface load (docs/theory.md §16) writes the boundary series (boundary.pvd), which its
// checkpoint carries: killed in its second checkpoint (step 4), it resumes from step 2 and ends
// with the same boundary files as a run that never stopped.
TEST_F(Checkpoints, ASurfaceLoadResumesWithItsBoundarySeries) {
  const std::string model = example_text("surface_load/strip_surcharge.yaml");
  run_reference(model);
  write("run.yaml", model);
  const CommandResult r = kill_in_checkpoint(2, {"--checkpoint-every", "2"});
  ASSERT_TRUE(!r.exited && r.signal == SIGKILL) << describe(r);
  EXPECT_TRUE(Contains(resume_and_compare(), "phase 'surcharge', step 2,"));
  const fs::path reference = work() / "reference", resumed = work() / "killed";
  EXPECT_EQ(read_text(resumed / "boundary.pvd"), read_text(reference / "boundary.pvd"));
  EXPECT_EQ(read_text(resumed / "vtk" / "boundary_000005.vtp"),
            read_text(reference / "vtk" / "boundary_000005.vtp"));
}

// A structure carries its pose, its pose at the phase start and the velocity and acceleration of
// its unknowns from step to step (docs/theory.md §17.6), and the step solver the rate of its
// unknowns for Newton's extrapolated start: a plate free in every component beside the vibrating
// bar, pushed and turned by its drive's loads under Newmark, killed in its third checkpoint,
// resumes from step 20 and ends as a run that never stopped (its histories too).
TEST_F(Checkpoints, AStructureResumesWithItsPoseAndMotion) {
  std::string model = example_text("vibrating_bar/vibrating_bar.yaml");
  model = replace_once(model, "phases:\n",
                       "structures:\n"
                       "  - name: plate\n"
                       "    shape: {type: footing, width: 1, height: 0.5, position: [5, 3], "
                       "cell_size: 0.25}\n"
                       "    density: 2\n"
                       "    reference_point: [4.5, 3]\n"
                       "    contact: none\n"
                       "phases:\n");
  model = replace_once(model, "      - {boundary: top, fix: [y]}\n",
                       "      - {boundary: top, fix: [y]}\n"
                       "    structures:\n"
                       "      plate: {force: [\"0.01*sin(t)\", -0.02], moment: 0.005}\n");
  // Newton's extrapolated start: the plate's unknowns' last rate is state too.
  model = replace_once(model, "    dynamics: {newmark: {beta: 0.25, gamma: 0.5}}\n",
                       "    dynamics: {newmark: {beta: 0.25, gamma: 0.5}}\n"
                       "    newton: {predictor: extrapolated}\n");
  model = replace_once(model, "    - {quantity: kinetic_energy}\n",
                       "    - {quantity: kinetic_energy}\n"
                       "    - {quantity: displacement, structure: plate, component: x}\n"
                       "    - {quantity: displacement, structure: plate, component: y}\n"
                       "    - {quantity: rotation, structure: plate, component: z}\n");
  run_reference(model);
  write("run.yaml", model);
  const CommandResult r = kill_in_checkpoint(3, {"--checkpoint-every", "10"});
  ASSERT_TRUE(!r.exited && r.signal == SIGKILL) << describe(r);
  EXPECT_TRUE(Contains(resume_and_compare(), "phase 'vibration', step 20,"));
  EXPECT_EQ(read_text(work() / "killed" / "structure_plate.pvd"),
            read_text(work() / "reference" / "structure_plate.pvd"));
  // It moved: pushed down and turned.
  const Csv history = read_csv(work() / "reference" / "history.csv");
  ASSERT_TRUE(history.problem.empty()) << history.problem;
  EXPECT_LT(history.column("displacement_plate_y").back(), -1.0);
  EXPECT_GT(history.column("rotation_plate_z").back(), 0.1);
}

// A deformable structure carries its nodes, its Gauss points' states (F, b_e, the material's
// variables, the stress) and its nodes' velocities and accelerations from step to step
// (docs/theory.md §17.7): a plate held at its base and shaken at its top beside the vibrating bar
// under Newmark, killed in its third checkpoint, resumes from step 20 and ends as a run that never
// stopped (its section stress too).
TEST_F(Checkpoints, ADeformableStructureResumesWithItsGaussPointsAndRates) {
  std::string model = example_text("vibrating_bar/vibrating_bar.yaml");
  model = replace_once(model, "phases:\n",
                       "structures:\n"
                       "  - name: plate\n"
                       "    shape: {type: footing, width: 1, height: 0.5, position: [5, 3], "
                       "cell: quad4, cell_size: 0.25}\n"
                       "    deformable: {material: bar}\n"
                       "    contact: none\n"
                       "phases:\n");
  model = replace_once(model, "      - {boundary: top, fix: [y]}\n",
                       "      - {boundary: top, fix: [y]}\n"
                       "    structures:\n"
                       "      plate: [{nodes: bottom, displacement: [0, 0]},\n"
                       "              {nodes: top, force: [\"0.5*sin(t)\", -0.2]}]\n");
  model = replace_once(model, "    - {quantity: kinetic_energy}\n",
                       "    - {quantity: kinetic_energy}\n"
                       "    - {quantity: displacement, structure: plate, nodes: top, component: x,"
                       " name: plate_top_x}\n"
                       "    - {quantity: section_stress, structure: plate, section: {point: [5, "
                       "3.1], normal: [0, 1]}, name: plate_stress}\n");
  run_reference(model);
  write("run.yaml", model);
  const CommandResult r = kill_in_checkpoint(3, {"--checkpoint-every", "10"});
  ASSERT_TRUE(!r.exited && r.signal == SIGKILL) << describe(r);
  EXPECT_TRUE(Contains(resume_and_compare(), "phase 'vibration', step 20,"));
  EXPECT_EQ(read_text(work() / "killed" / "structure_plate.pvd"),
            read_text(work() / "reference" / "structure_plate.pvd"));
  // It moved and is stressed.
  const Csv history = read_csv(work() / "reference" / "history.csv");
  ASSERT_TRUE(history.problem.empty()) << history.problem;
  double largest = 0.0;
  for (double x : history.column("plate_top_x")) largest = std::max(largest, std::abs(x));
  EXPECT_GT(largest, 1e-3);
  EXPECT_LT(history.column("plate_stress").back(), 0.0);
}

// A checkpoint that cannot be used: exit 2, a message naming the file and the problem, and
// nothing changed in the output directory.
class BadCheckpoints : public GeompmRunTest<> {
 protected:
  void SetUp() override {
    GeompmRunTest<>::SetUp();
    write("model.yaml", example_text("oedometer/oedometer.yaml"));
    const auto r = geompm({"run", "-q", "-t", "1", "-o", "good", "model.yaml"});
    ASSERT_TRUE(r.exited && r.exit_code == 0) << describe(r);
    ASSERT_TRUE(fs::exists(work() / "good" / "checkpoint.bin")) << "the end of the phase";
  }

  /// Copies "good" to `name`, lets `damage` change its checkpoint's bytes, and resumes it with
  /// `model`: exit 2 with `message` after the checkpoint's name, history.csv unchanged.
  void expect_refused(const std::string& name, const std::function<void(std::string&)>& damage,
                      const std::string& message, const std::string& model = "model.yaml") {
    fs::copy(work() / "good", work() / name, fs::copy_options::recursive);
    const fs::path checkpoint = work() / name / "checkpoint.bin";
    std::string bytes = read_text(checkpoint);
    damage(bytes);
    std::ofstream(checkpoint, std::ios::binary | std::ios::trunc) << bytes;
    const std::string history = read_text(work() / name / "history.csv");
    const auto r = geompm({"run", "-q", "-t", "1", "-o", name, "--resume", model});
    ASSERT_TRUE(r.exited && r.exit_code == 2) << describe(r);
    EXPECT_TRUE(Contains(r.err, "error: " + name + "/checkpoint.bin: " + message));
    EXPECT_EQ(read_text(work() / name / "history.csv"), history);
    EXPECT_EQ(read_text(checkpoint), bytes) << "the checkpoint is left as it was";
  }
};

TEST_F(BadCheckpoints, Truncated) {
  expect_refused(
      "truncated", [](std::string& b) { b.resize(b.size() / 2); }, "truncated checkpoint");
}

TEST_F(BadCheckpoints, AByteChanged) {
  expect_refused(
      "flipped", [](std::string& b) { b[b.size() / 2] ^= 0x01; },
      "damaged checkpoint: the checksum of its contents");
}

TEST_F(BadCheckpoints, AnotherModel) {
  write("other.yaml", example_text("oedometer/oedometer.yaml") + "# changed\n");
  expect_refused(
      "other_model", [](std::string&) {}, "the checkpoint was written for another model",
      "other.yaml");
}

TEST_F(BadCheckpoints, AnotherFormatVersion) {
  expect_refused(
      "other_version",
      [](std::string& b) {
        const std::uint32_t version = 99;
        std::memcpy(b.data() + 8, &version, sizeof version);
      },
      "checkpoint format version 99; this geompm (" GEOMPM_VERSION ") reads format version " +
          std::to_string(geompm::checkpoint_format_version));
}

TEST_F(BadCheckpoints, NoCheckpoint) {
  const auto r = geompm({"run", "-q", "-t", "1", "-o", "nowhere", "--resume", "model.yaml"});
  ASSERT_TRUE(r.exited && r.exit_code == 2) << describe(r);
  EXPECT_TRUE(Contains(r.err, "error: nowhere/checkpoint.bin: no checkpoint to resume from"));
  EXPECT_FALSE(fs::exists(work() / "nowhere")) << "nothing is written";
}

// The files a resumed run appends to must still hold what they held at the checkpoint; both are
// checked before either is cut back.
TEST_F(BadCheckpoints, OutputFilesCutShorterThanTheCheckpoint) {
  fs::copy(work() / "good", work() / "short", fs::copy_options::recursive);
  const std::string history = read_text(work() / "short" / "history.csv");
  std::ofstream(work() / "short" / "history.csv", std::ios::binary | std::ios::trunc)
      << history.substr(0, history.size() / 2);
  const auto cut = geompm({"run", "-q", "-t", "1", "-o", "short", "--resume", "model.yaml"});
  ASSERT_TRUE(cut.exited && cut.exit_code == 2) << describe(cut);
  EXPECT_TRUE(Contains(cut.err, "error: short/history.csv: " + std::to_string(history.size() / 2) +
                                    " bytes, but at the "
                                    "checkpoint it had " +
                                    std::to_string(history.size()) + " bytes"));

  fs::copy(work() / "good", work() / "lost", fs::copy_options::recursive);
  fs::remove(work() / "lost" / "newton.csv");
  const auto lost = geompm({"run", "-q", "-t", "1", "-o", "lost", "--resume", "model.yaml"});
  ASSERT_TRUE(lost.exited && lost.exit_code == 2) << describe(lost);
  EXPECT_TRUE(Contains(lost.err, "error: lost/newton.csv: missing;"));
  EXPECT_EQ(read_text(work() / "lost" / "history.csv"), history) << "history.csv was cut back";
}

TEST_F(BadCheckpoints, BadCheckpointIntervalOnTheCommandLine) {
  for (const std::string value : {"-1", "ten", "2.5"}) {
    const auto r = geompm({"run", "-q", "-o", "bad", "--checkpoint-every", value, "model.yaml"});
    EXPECT_TRUE(r.exited && r.exit_code == 1) << value << ": " << describe(r);
    EXPECT_TRUE(Contains(r.err, "--checkpoint-every")) << value;
  }
  EXPECT_FALSE(fs::exists(work() / "bad"));
  const auto help = geompm({"run", "--help"});
  ASSERT_TRUE(help.exited && help.exit_code == 0) << describe(help);
  EXPECT_TRUE(Contains(help.out, "--resume"));
  EXPECT_TRUE(Contains(help.out, "--checkpoint-every STEPS"));
}

// Checkpoints are part of the run's output: a new run in the same directory removes the old
// one's (a later --resume must not go back to another run), as it overwrites the rest.
TEST_F(BadCheckpoints, ANewRunForgetsTheOldCheckpoint) {
  write("stop.yaml", replace_once(example_text("oedometer/oedometer.yaml"),
                                  "time_step: {initial: 0.1, min: 0.001, max: 0.1}",
                                  "time_step: {initial: 0.1, min: 0.1, max: 0.1}\n"
                                  "    newton: {max_iterations: 1, residual_tolerance: 1.0e-14, "
                                  "displacement_tolerance: 1.0e-14}"));
  const auto r = geompm({"run", "-q", "-t", "1", "-o", "good", "stop.yaml"});
  ASSERT_TRUE(r.exited && r.exit_code == 3) << describe(r);
  EXPECT_FALSE(fs::exists(work() / "good" / "checkpoint.bin"));
  EXPECT_EQ(read_json(work() / "good" / "summary.json").at("status"), "stopped");
}

}  // namespace

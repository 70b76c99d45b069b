// The saved state of a run (docs/checkpoint-format.md): one section per owner of persistent
// state, each written and read by that owner, in this order. A section's reader checks that it
// read every byte, so a layout that drifts from its writer is caught, not misread.
#include <fmt/format.h>

#include <exception>
#include <functional>
#include <optional>

#include "geompm/analysis/distribution.hpp"
#include "geompm/analysis/simulation.hpp"
#include "geompm/core/agreement.hpp"
#include "geompm/core/error.hpp"
#include "geompm/io/checkpoint_file.hpp"
#include "geompm/points/saved_points.hpp"
#include "geompm/points/streamed_points.hpp"

namespace geompm {

namespace {

// Process 0's checkpoint file while every process takes part in writing it: an error of process
// 0's writing (a full disk) is kept, not thrown, until the collective steps are over, then every
// process learns it and throws it (together), as a serial run throws it at once.
class ProcessZeroFile {
 public:
  explicit ProcessZeroFile(const Communicator& processes) : processes_(processes) {}

  /// Runs `write` with the file on process 0, unless an earlier write failed.
  void write(const std::function<void(CheckpointWriter&)>& write) {
    if (processes_.rank() != 0 || failure_) return;
    try {
      write(*file_);
    } catch (...) {
      failure_ = std::current_exception();
    }
  }
  void open(const std::filesystem::path& file, std::uint64_t model_hash, std::uint32_t sections,
            CheckpointWriteOptions options) {
    if (processes_.rank() != 0) return;
    try {
      file_.emplace(file, model_hash, sections, options);
    } catch (...) {
      failure_ = std::current_exception();
    }
  }
  /// A whole section, made by `fill` on process 0.
  void section(const char* name, const std::function<void(ByteWriter&)>& fill) {
    write([&](CheckpointWriter& file) {
      ByteWriter out;
      fill(out);
      file.section(name, out.bytes());
    });
  }
  /// The bytes of process 0's sink of stream_saved_points.
  ByteSink sink() {
    return [this](std::string_view bytes) { write([&](CheckpointWriter& f) { f.add(bytes); }); };
  }
  /// Commits the file; every process throws the error process 0 met, if it met one.
  /// Collective.
  void commit() {
    write([](CheckpointWriter& file) { file.commit(); });
    together(processes_, [&] {
      if (failure_) std::rethrow_exception(failure_);
    });
  }

 private:
  const Communicator& processes_;
  std::optional<CheckpointWriter> file_;
  std::exception_ptr failure_;
};

constexpr std::uint32_t checkpoint_sections = 8;

}  // namespace

// Collective. Process 0 writes the file; the points (and the FEM region's Gauss points) of every
// process reach it a slice at a time, in id order (points/streamed_points.hpp): in the serial
// run's layout, and no process holds a copy of every point.
void Simulation::save(const std::filesystem::path& file) const {
  CheckpointWriteOptions write_options;
  write_options.kill_half_way = kill_in_checkpoint_ > 0 && checkpoints_ + 1 == kill_in_checkpoint_;
  ProcessZeroFile out(processes_);
  out.open(file, options_.model_hash, checkpoint_sections, write_options);
  out.section("run", [&](ByteWriter& out) {
    out.put(static_cast<std::uint64_t>(phase_index_));
    out.put(model_.spec.phases[phase_index_].name);
    out.put(time_);
    out.put(step_number_);
    out.put(done_duration_);
    out.put(control_->state().time);
    out.put(control_->state().dt);
  });
  const Index points = processes_.sum(model_.points.size());
  out.write([&](CheckpointWriter& f) { f.begin_section("points", saved_points_bytes(points)); });
  stream_saved_points(model_.points, processes_, out.sink());
  // Model::save_state's bytes: the Gauss points, last, streamed as the points are.
  ByteWriter model_state;
  if (writes_files()) model_.save_state_before_gauss_points(model_state);
  const std::vector<Index> own_gauss =
      model_.fem ? model_.fem->own_gauss_points() : std::vector<Index>();
  const Index gauss_points = model_.fem ? processes_.sum(static_cast<Index>(own_gauss.size())) : 0;
  out.write([&](CheckpointWriter& f) {
    f.begin_section(
        "model", model_state.bytes().size() + (model_.fem ? saved_points_bytes(gauss_points) : 0));
    f.add(model_state.bytes());
  });
  if (model_.fem)
    stream_saved_points(model_.fem->gauss_points(), own_gauss, processes_, out.sink());
  out.section("phase", [&](ByteWriter& out) { phase_->save(out); });
  out.section("step_solver", [&](ByteWriter& out) {
    out.put(stepper_.last_rate());
    out.put(stepper_.pressure().last());
    out.put(stepper_.field_rate());
  });
  out.section("summary", [&](ByteWriter& out) {
    // The wall times so far, this process's included.
    RunSummary counted = summary_;
    const auto now = Clock::now();
    counted.wall_seconds = wall_before_ + std::chrono::duration<double>(now - started_).count();
    counted.phases[phase_index_].wall_seconds =
        phase_wall_before_ + std::chrono::duration<double>(now - phase_started_).count();
    counted.save(out);
  });
  out.section("output", [&](ByteWriter& out) { output_->save(out); });
  out.section("structures", [&](ByteWriter& out) {
    out.put(static_cast<std::uint64_t>(model_.structures.size()));
    for (std::size_t k = 0; k < model_.structures.size(); ++k) {
      out.put(model_.structures[k]->name());
      model_.structures[k]->save(out);
      model_.contacts[k].save(out);  // its contact with the soil
    }
  });
  out.commit();
  ++checkpoints_;
}

void Simulation::load(const std::filesystem::path& file) {
  // The points are left in the file: each process reads those of its own cells only.
  const CheckpointContents contents = read_checkpoint_file(file, options_.model_hash, {"points"});
  if (contents.geompm_version != GEOMPM_VERSION && options_.log)
    *options_.log << fmt::format("note: {} was written by geompm {}; this is geompm {}\n",
                                 file.string(), contents.geompm_version, GEOMPM_VERSION);

  ByteReader run = contents.section("run");
  const auto phase = run.get<std::uint64_t>();
  const auto phase_name = run.get<std::string>();
  if (phase >= model_.spec.phases.size() || model_.spec.phases[phase].name != phase_name)
    throw InputError(fmt::format("{}: written in phase {} '{}', which the model does not have",
                                 run.context(), phase + 1, phase_name));
  phase_index_ = static_cast<std::size_t>(phase);
  const spec::Phase& spec = model_.spec.phases[phase_index_];
  StepController::State control;
  run.get(time_);
  run.get(step_number_);
  run.get(done_duration_);
  run.get(control.time);
  run.get(control.dt);
  run.expect_end();

  ByteReader model = contents.section("model");
  model_.load_state(model);
  // Whatever process count wrote it, the cut is made anew by the points in each cell (and the FEM
  // region's Gauss points, just read), and this process reads its own cells' points.
  const CheckpointContents::Place place = contents.place("points");
  const SavedPoints saved(file, place.offset, place.length,
                          fmt::format("{}: section 'points'", file.string()));
  resumed_cell_part_.clear();
  if (processes_.distributed())
    resumed_cell_part_ =
        partition_by_work(model_, saved.points_in_cell(model_.mesh.num_cells()), processes_.size());
  model_.points = saved.load(resumed_cell_part_, processes_.rank());
  // The phase is rebuilt from the model, then given the state its steps had reached.
  phase_ = std::make_unique<PhaseContext>(model_, spec);
  ByteReader phase_state = contents.section("phase");
  phase_->load(phase_state);
  control_ = std::make_unique<StepController>(step_control_settings(spec.time_step), spec.duration);
  control_->restore(control);

  ByteReader step_solver = contents.section("step_solver");
  stepper_.set_last_rate(step_solver.get<std::vector<double>>());
  stepper_.pressure().set_last(step_solver.get<std::vector<double>>());
  stepper_.set_field_rate(step_solver.get<std::map<std::string, std::vector<double>>>());
  step_solver.expect_end();

  ByteReader summary = contents.section("summary");
  summary_.load(summary);
  if (summary_.phases.size() != model_.spec.phases.size())
    throw InputError(fmt::format("{}: {} phases counted, the model has {}", summary.context(),
                                 summary_.phases.size(), model_.spec.phases.size()));
  wall_before_ = summary_.wall_seconds;
  phase_wall_before_ = summary_.phases[phase_index_].wall_seconds;
  done_duration_before_ = done_duration_;

  ByteReader structures = contents.section("structures");
  if (const auto saved = structures.get<std::uint64_t>(); saved != model_.structures.size())
    throw InputError(fmt::format("{}: {} structures saved, the model has {}", structures.context(),
                                 saved, model_.structures.size()));
  for (std::size_t k = 0; k < model_.structures.size(); ++k) {
    auto& structure = model_.structures[k];
    if (const auto name = structures.get<std::string>(); name != structure->name())
      throw InputError(fmt::format("{}: the structure '{}' saved, the model has '{}' there",
                                   structures.context(), name, structure->name()));
    structure->load(structures);
    model_.contacts[k].load(structures);
  }
  structures.expect_end();

  ByteReader output = contents.section("output");
  if (writes_files()) output_ = std::make_unique<OutputWriter>(model_, options_.output_dir, output);
}

}  // namespace geompm

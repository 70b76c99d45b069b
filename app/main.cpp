// The geompm command line: run a model, check it, or plot a history.
//
// Exit codes: 0 success, 1 bad command line, 2 bad input (model or mesh file, a model too big for
// the machine, an output directory that cannot be used, a checkpoint that is missing or cannot be
// used by --resume), 3 the run stopped (no convergence at the smallest time step, a point left the
// mesh, a non-finite value, a file that cannot be written, a prescribed motion not followed), 4 an
// internal error.
#include <fmt/format.h>
#include <omp.h>
#include <CLI/CLI.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geompm/analysis/model.hpp"
#include "geompm/analysis/run.hpp"
#include "geompm/core/agreement.hpp"
#include "geompm/core/error.hpp"
#include "geompm/core/fnv1a.hpp"
#include "geompm/core/interrupt.hpp"
#include "geompm/io/model_reader.hpp"
#include "geompm/io/output_directory.hpp"
#include "geompm/io/plot.hpp"
#include "geompm/mesh/cell_type.hpp"
#include "geompm/mesh/gmsh_generate.hpp"
#include "geompm/solver/linear_solver.hpp"
#include "geompm/solver/petsc_communicator.hpp"

namespace {

struct RunCommand {
  std::string model_file, output;
  int threads = 0;
  bool quiet = false;
  bool resume = false;
  std::optional<int> checkpoint_every;
  std::string linear_solver, petsc_options;
};

// --linear-solver and --petsc-options over the model's numerics (docs/user-guide.md, "Linear
// solvers").
void override_linear_solver(const RunCommand& command, geompm::spec::Numerics& numerics) {
  if (!command.linear_solver.empty()) numerics.linear_solver = command.linear_solver;
  if (!command.petsc_options.empty()) {
    if (const std::string error = geompm::petsc_options_error(command.petsc_options);
        !error.empty())
      throw geompm::InputError("--petsc-options: " + error);
    if (!geompm::uses_petsc(numerics.linear_solver))
      throw geompm::InputError("--petsc-options: no effect with linear solver '" +
                               numerics.linear_solver +
                               "' (expected auto, petsc_gamg, petsc_hypre or petsc_mumps)");
    numerics.petsc_options = command.petsc_options;
  }
}

int run_command(const RunCommand& command) {
  if (command.threads > 0) omp_set_num_threads(command.threads);
  geompm::install_interrupt_handler();  // Ctrl-C: the run stops cleanly between steps (exit 3)
  // Read and build everything before anything is written, so bad input leaves no output.
  std::optional<geompm::spec::Model> spec;
  std::exception_ptr unread;
  try {
    spec = geompm::read_model(command.model_file);
    override_linear_solver(command, spec->numerics);
  } catch (...) {
    unread = std::current_exception();
  }
  // Under mpirun/srun with several processes: a distributed run (docs/user-guide.md, "Running on
  // several processes"); MPI is started only then, with the model's PETSc options. Every process
  // has read the model, then built it, each seeding only its own cells' points: if one could not,
  // they stop together (core/agreement.hpp), process 0 saying why before any process ends (mpirun
  // would stop it with the first to end).
  std::unique_ptr<geompm::Communicator> processes;
  if (geompm::launched_with_several_processes())
    processes = geompm::mpi_world_communicator(spec ? spec->numerics.petsc_options : "");
  const auto stop_if_unread = [&] {
    if (processes)
      geompm::together(*processes, [&] {
        if (unread) std::rethrow_exception(unread);
      });
    else if (unread)
      std::rethrow_exception(unread);
  };
  stop_if_unread();
  std::unique_ptr<geompm::Model> model;
  try {
    model = geompm::build_model(*spec, processes ? *processes : geompm::serial_communicator());
  } catch (...) {
    unread = std::current_exception();
  }
  stop_if_unread();
  const bool first = !processes || processes->rank() == 0;
  std::string output = command.output;
  if (output.empty())
    output = std::filesystem::path(command.model_file).stem().string() + "_results";
  if (!command.quiet) {
    const std::string description =
        geompm::describe_model(*model, processes ? *processes : geompm::serial_communicator());
    if (first) std::cerr << description;
  }
  if (!command.quiet && first && processes)
    std::cerr << fmt::format("distributed run on {} processes\n", processes->size());
  geompm::RunOptions options;
  options.communicator = processes.get();
  options.output_dir = output;
  options.progress = !command.quiet;
  options.log = first ? &std::cerr : nullptr;
  options.resume = command.resume;
  options.checkpoint_every = command.checkpoint_every;
  // The text read_model has just read: a checkpoint is only resumed with the same model.
  std::ifstream in(command.model_file, std::ios::binary);
  options.model_hash = geompm::fnv1a_64(
      std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()));
  geompm::run_analysis(*model, options);
  return 0;
}

int check_command(const std::string& model_file) {
  const auto spec = geompm::read_model(model_file);
  auto model = geompm::build_model(spec);
  std::cout << geompm::describe_model(*model) << "model is valid\n";
  return 0;
}

struct MeshCommand {
  std::vector<double> origin = {0, 0, 0}, size, refine;
  double h = 0, h_refined = 0;
  std::string cell = "tri3", output = "mesh.msh";
};

geompm::Vec3 vec3(const std::vector<double>& v) {
  geompm::Vec3 x = geompm::Vec3::Zero();
  for (std::size_t i = 0; i < v.size() && i < 3; ++i) x(i) = v[i];
  return x;
}

int mesh_command(const MeshCommand& command) {
  const auto type = geompm::parse_cell_type(command.cell);
  if (!type)
    throw geompm::InputError("--cell: expected tri3, tri6, quad4 or tet4, got '" + command.cell +
                             "'");
  const bool box = command.size.size() == 3;
  std::optional<geompm::RefineBox> region;
  if (!command.refine.empty()) {
    const std::size_t half = command.refine.size() / 2;
    if (command.refine.size() % 2 || (half != command.size.size()))
      throw geompm::InputError("--refine: expected " + std::to_string(2 * command.size.size()) +
                               " numbers (lower and upper corner)");
    geompm::Vec3 lo = geompm::Vec3::Zero(), hi = geompm::Vec3::Zero();
    for (std::size_t i = 0; i < half; ++i) {
      lo(i) = command.refine[i];
      hi(i) = command.refine[half + i];
    }
    region = std::make_pair(lo, hi);
    if (!(command.h_refined > 0))
      throw geompm::InputError("--h-refined: expected a size > 0 with --refine");
  }
  // Where the mesh goes is checked before Gmsh meshes (which would fail only when it writes).
  const std::filesystem::path file(command.output);
  if (std::filesystem::is_directory(file))
    throw geompm::InputError(command.output + ": -o names a directory; expected a .msh file");
  geompm::prepare_output_directory(file.has_parent_path() ? file.parent_path() : ".");
  try {
    if (box)
      geompm::write_gmsh_box(command.output, vec3(command.origin), vec3(command.size), command.h,
                             *type, region, command.h_refined);
    else
      geompm::write_gmsh_rectangle(command.output, vec3(command.origin), vec3(command.size),
                                   command.h, *type, region, command.h_refined);
  } catch (const std::invalid_argument& e) {
    throw geompm::InputError(std::string("geompm mesh: ") + e.what());
  }
  std::cout << "wrote " << command.output << "\n";
  return 0;
}

CLI::App* add_run_command(CLI::App& app, RunCommand& options) {
  auto* run = app.add_subcommand("run", "run an analysis");
  run->add_option("model", options.model_file, "model file (YAML or JSON)")->required();
  run->add_option("-o,--output", options.output,
                  "output directory (default: <model name>_results)");
  run->add_option("-t,--threads", options.threads, "number of threads (default: all cores)")
      ->check(CLI::Range(1, 4096).description("a whole number >= 1"));
  run->add_flag("-q,--quiet", options.quiet,
                "no model description or progress line (the closing summary is still printed)");
  run->add_flag("--resume", options.resume,
                "continue the run in the output directory from its last checkpoint "
                "(checkpoint.bin), with the same model file");
  run->add_option("--checkpoint-every", options.checkpoint_every,
                  "write a checkpoint every STEPS converged steps (0: not by steps; default: "
                  "output.checkpoint.every_steps of the model, 100)")
      ->type_name("STEPS")
      ->check(CLI::Range(0, 1000000000).description("a whole number >= 0"));
  run->add_option("--linear-solver", options.linear_solver,
                  "linear solver, over the model's numerics.linear_solver")
      ->check(CLI::IsMember(geompm::linear_solver_names()));
  run->add_option("--petsc-options", options.petsc_options,
                  "PETSc options for the PETSc solvers, over the model's numerics.petsc_options "
                  "(e.g. \"-ksp_type fgmres -pc_gamg_threshold 0.02\")");
  return run;
}

struct PlotCommand {
  geompm::PlotRequest request;
  std::string png = "plot.png";
  std::vector<std::string> references, reference_labels;
};

/// "5.14" is a line, "5.14:5.40" a band; the labels go with the references in order.
std::vector<geompm::PlotReference> plot_references(const PlotCommand& command) {
  std::vector<geompm::PlotReference> references;
  for (std::size_t i = 0; i < command.references.size(); ++i) {
    const std::string& text = command.references[i];
    geompm::PlotReference reference;
    try {
      const std::size_t colon = text.find(':');
      reference.lo = std::stod(text.substr(0, colon));
      reference.hi = colon == std::string::npos ? reference.lo : std::stod(text.substr(colon + 1));
    } catch (const std::exception&) {
      throw geompm::InputError("--reference: expected a value (5.14) or a band (5.14:5.40), got '" +
                               text + "'");
    }
    if (reference.hi < reference.lo)
      throw geompm::InputError("--reference: a band is lower:upper, got '" + text + "'");
    if (i < command.reference_labels.size()) reference.label = command.reference_labels[i];
    references.push_back(reference);
  }
  return references;
}

int plot_command(PlotCommand& command) {
  command.request.references = plot_references(command);
  geompm::plot_history(command.request, command.png);
  std::cout << "wrote " << command.png << "\n";
  return 0;
}

CLI::App* add_plot_command(CLI::App& app, PlotCommand& command) {
  geompm::PlotRequest& request = command.request;
  auto* plot = app.add_subcommand("plot", "plot columns of a history CSV into a PNG");
  plot->add_option("csv", request.csv, "history CSV file")->required();
  plot->add_option("--x", request.x, "column for the horizontal axis")->default_val("time");
  plot->add_option("--y", request.y, "column(s) for the vertical axis")->required();
  plot->add_option("--x-scale", request.x_scale, "factor applied to x (e.g. -1)");
  plot->add_option("--y-scale", request.y_scale, "factor applied to y (e.g. -1)");
  plot->add_option("--title", request.title, "plot title");
  plot->add_option("--x-label", request.x_label, "x axis label: quantity and unit");
  plot->add_option("--y-label", request.y_label, "y axis label: quantity and unit");
  plot->add_option("--reference", command.references,
                   "reference line at a (scaled) y value, or band lower:upper; repeatable")
      ->type_name("Y[:Y]");
  plot->add_option("--reference-label", command.reference_labels,
                   "legend label of each --reference, in order");
  plot->add_option("-o,--output", command.png, "PNG file to write")->default_val("plot.png");
  return plot;
}

// Unstructured meshes through Gmsh, written as .msh for `mesh: {file: ...}` in a model.
CLI::App* add_mesh_command(CLI::App& app, MeshCommand& options) {
  auto* mesh = app.add_subcommand("mesh", "write an unstructured Gmsh mesh of a rectangle or box");
  mesh->add_option("--origin", options.origin, "lower corner (2 or 3 numbers)")->expected(2, 3);
  mesh->add_option("--size", options.size, "extent (2 numbers: rectangle, 3: box)")
      ->required()
      ->expected(2, 3);
  mesh->add_option("--h", options.h, "cell size")->required()->check(CLI::PositiveNumber);
  mesh->add_option("--refine", options.refine,
                   "refinement box: lower and upper corner (4 or 6 numbers)")
      ->expected(4, 6);
  mesh->add_option("--h-refined", options.h_refined, "cell size inside the refinement box");
  mesh->add_option("--cell", options.cell, "tri3, tri6, quad4 (2D) or tet4 (3D)")
      ->default_val("tri3");
  mesh->add_option("-o,--output", options.output, "the .msh file to write")
      ->default_val("mesh.msh");
  return mesh;
}

/// An unknown first word is named before CLI11 would complain about something else.
bool known_command(const CLI::App& app, int argc, char** argv) {
  if (argc <= 1 || argv[1][0] == '-') return true;
  for (const auto* sub : app.get_subcommands({}))
    if (sub->get_name() == argv[1]) return true;
  std::cerr << "error: unknown command '" << argv[1]
            << "'; the commands are: run, check, plot, mesh (see --help)\n";
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"geompm — implicit material point method for large-deformation geotechnics"};
  app.set_version_flag("--version", std::string("geompm ") + GEOMPM_VERSION);
  app.require_subcommand(1);

  RunCommand run_options;
  auto* run = add_run_command(app, run_options);
  std::string model_file;
  auto* check =
      app.add_subcommand("check", "validate a model and print a summary, without running");
  check->add_option("model", model_file, "model file")->required();
  PlotCommand plot_options;
  auto* plot = add_plot_command(app, plot_options);
  MeshCommand mesh_options;
  auto* mesh = add_mesh_command(app, mesh_options);

  if (!known_command(app, argc, argv)) return 1;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; every bad command line exits 1 (CLI11 prints the reason).
    return app.exit(e) == 0 ? 0 : 1;
  }
  try {
    if (*run) return run_command(run_options);
    if (*check) return check_command(model_file);
    if (*mesh) return mesh_command(mesh_options);
    if (*plot) return plot_command(plot_options);
  } catch (const std::exception& e) {
    // Every process of a distributed run meets the errors that reach here together (the model
    // read by each, core/agreement.hpp for the run's): process 0 says it, once.
    if (!*run || geompm::launched_rank() == 0) {
      if (dynamic_cast<const geompm::RunError*>(&e)) std::cerr << "\n";  // after the progress line
      std::cerr << geompm::describe_error(e) << "\n";
    }
    return geompm::exit_code(e);
  }
  return 0;
}

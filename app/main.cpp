// The geompm command line: run a model, check it, or plot a history.
//
// Exit codes: 0 success, 1 bad command line, 2 bad input (model or mesh file), 3 the run stopped
// (no convergence at the smallest time step, a point left the mesh), 4 an internal error.
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <omp.h>

#include <filesystem>
#include <iostream>

#include "geompm/analysis/model.hpp"
#include "geompm/analysis/run.hpp"
#include "geompm/core/error.hpp"
#include "geompm/io/model_reader.hpp"
#include "geompm/io/plot.hpp"

namespace {

int run_command(const std::string& model_file, std::string output, int threads, bool quiet) {
  if (threads > 0) omp_set_num_threads(threads);
  // Read and build everything before anything is written, so bad input leaves no output.
  const auto spec = geompm::read_model(model_file);
  auto model = geompm::build_model(spec);
  if (output.empty())
    output = std::filesystem::path(model_file).stem().string() + "_results";
  if (!quiet) std::cerr << geompm::describe_model(*model);
  geompm::RunOptions options;
  options.output_dir = output;
  options.progress = !quiet;
  options.log = &std::cerr;
  geompm::run_analysis(*model, options);
  return 0;
}

int check_command(const std::string& model_file) {
  const auto spec = geompm::read_model(model_file);
  auto model = geompm::build_model(spec);
  std::cout << geompm::describe_model(*model) << "model is valid\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"geompm — implicit material point method for large-deformation geotechnics"};
  app.set_version_flag("--version", std::string("geompm ") + GEOMPM_VERSION);
  app.require_subcommand(1);

  std::string model_file, output;
  int threads = 0;
  bool quiet = false;
  auto* run = app.add_subcommand("run", "run an analysis");
  run->add_option("model", model_file, "model file (YAML or JSON)")->required();
  run->add_option("-o,--output", output, "output directory (default: <model name>_results)");
  run->add_option("-t,--threads", threads, "number of threads (default: all cores)")
      ->check(CLI::PositiveNumber);
  run->add_flag("-q,--quiet", quiet, "no progress line or summary");

  auto* check = app.add_subcommand("check", "validate a model and print a summary, without running");
  check->add_option("model", model_file, "model file")->required();

  geompm::PlotRequest plot_request;
  std::string png = "plot.png";
  auto* plot = app.add_subcommand("plot", "plot columns of a history CSV into a PNG");
  plot->add_option("csv", plot_request.csv, "history CSV file")->required();
  plot->add_option("--x", plot_request.x, "column for the horizontal axis")->default_val("time");
  plot->add_option("--y", plot_request.y, "column(s) for the vertical axis")->required();
  plot->add_option("--x-scale", plot_request.x_scale, "factor applied to x (e.g. -1)");
  plot->add_option("--y-scale", plot_request.y_scale, "factor applied to y (e.g. -1)");
  plot->add_option("--title", plot_request.title, "plot title");
  plot->add_option("-o,--output", png, "PNG file to write")->default_val("plot.png");

  CLI11_PARSE(app, argc, argv);
  try {
    if (*run) return run_command(model_file, output, threads, quiet);
    if (*check) return check_command(model_file);
    if (*plot) {
      geompm::plot_history(plot_request, png);
      std::cout << "wrote " << png << "\n";
      return 0;
    }
  } catch (const geompm::InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  } catch (const geompm::RunError& e) {
    std::cerr << "\nrun stopped: " << e.what() << "\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "internal error: " << e.what() << "\n";
    return 4;
  }
  return 0;
}

// Runs a model file of examples/ through the library, as `geompm run` does, into a fresh
// temporary directory, and reads back its history.
#pragma once

#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "geompm/analysis/model.hpp"
#include "geompm/analysis/run.hpp"
#include "geompm/core/error.hpp"
#include "geompm/io/history_writer.hpp"
#include "geompm/io/model_reader.hpp"

namespace geompm::testing {

/// A fresh directory of its own for a run: the process id keeps tests that CTest runs at the same
/// time (separate processes, possibly the same run name) out of each other's files.
/// They are removed when the test process ends.
inline std::filesystem::path fresh_directory(const std::string& name) {
  struct RemovedAtExit {
    std::vector<std::filesystem::path> directories;
    ~RemovedAtExit() {
      std::error_code ignored;
      for (const auto& d : directories) std::filesystem::remove_all(d, ignored);
    }
  };
  static RemovedAtExit created;
  auto dir = std::filesystem::temp_directory_path() /
             ("geompm_test_" + name + "_" + std::to_string(::getpid()));
  created.directories.push_back(dir);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

struct ModelRun {
  std::unique_ptr<Model> model;
  RunSummary summary;
  CsvTable history;
  std::filesystem::path output;

  std::vector<double> column(const std::string& name) const {
    const std::size_t c = history.column(name, "history.csv");
    std::vector<double> v;
    for (const auto& row : history.rows) v.push_back(row[c]);
    return v;
  }
};

/// Runs a built model (possibly edited by the test) and returns it with its summary and history.
inline ModelRun run_built(std::unique_ptr<Model> model, const std::string& name) {
  ModelRun r;
  r.model = std::move(model);
  r.output = fresh_directory(name);
  RunOptions options;
  options.output_dir = r.output;
  options.progress = false;
  r.summary = run_analysis(*r.model, options);
  r.history = read_csv(r.output / "history.csv");
  return r;
}

/// Runs `spec` (possibly edited by the test) and returns the model, summary and history.
inline ModelRun run_spec(const spec::Model& spec, const std::string& name) {
  return run_built(build_model(spec), name);
}

/// What building the model of `text` refuses, or "" (and a test failure) if it is accepted.
inline std::string build_error(const std::string& text, const std::string& file = "model.yaml") {
  try {
    build_model(read_model_from_string(text, file));
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "the model was accepted";
  return "";
}

inline spec::Model read_example(const std::string& relative) {
  return read_model(std::string(GEOMPM_SOURCE_DIR) + "/examples/" + relative);
}

}  // namespace geompm::testing

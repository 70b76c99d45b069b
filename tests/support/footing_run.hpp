// A footing model run once per model text (several tests share runs) and its load-settlement
// curve: settlement / B and q in the reference's units, with the Newton iterations of each step.
// Shared by the verification tier and the extended validation tier.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "example_text.hpp"
#include "run_model.hpp"

namespace geompm::testing {

// The examples' mesh (10 cells under the footing's half-width, h = B/20), without VTK files.
inline std::string no_vtk(const std::string& text) {
  return replace_once(text, "vtk: {every: 10}", "vtk: {every: 0}");
}

struct Footing {
  std::vector<double> settlement, q, iterations;
  RunSummary summary;
  std::filesystem::path output;  // the run's directory (its VTK files, if the model writes any)
  // q at a settlement (linear between steps)
  double q_at(double s) const {
    for (std::size_t k = 1; k < settlement.size(); ++k)
      if (settlement[k] >= s - 1e-5) {
        const double a = (s - settlement[k - 1]) / (settlement[k] - settlement[k - 1]);
        return q[k - 1] + a * (q[k] - q[k - 1]);
      }
    ADD_FAILURE() << "the run did not reach a settlement of " << s;
    return NAN;
  }
  // mean of q over the settlements s0..s1 (smooths the cell-crossing noise)
  double q_mean(double s0, double s1) const {
    double sum = 0.0;
    int count = 0;
    for (std::size_t k = 0; k < settlement.size(); ++k)
      if (settlement[k] >= s0 - 1e-5 && settlement[k] <= s1 + 1e-5) {
        sum += q[k];
        ++count;
      }
    return count > 0 ? sum / count : NAN;
  }
  int max_iterations() const {
    return static_cast<int>(*std::max_element(iterations.begin(), iterations.end()));
  }
};

// Runs a footing model (once per text: several tests share runs); q = scale x force column.
inline const Footing& run_footing(const std::string& text, const std::string& name, double scale) {
  static std::map<std::string, Footing> cache;
  if (auto it = cache.find(text); it != cache.end()) return it->second;
  const auto run = run_spec(read_model_from_string(text, name + ".yaml"), name);
  Footing f;
  f.summary = run.summary;
  f.output = run.output;
  for (double s : run.column("settlement")) f.settlement.push_back(-s);  // B = 1
  for (double force : run.column("force")) f.q.push_back(scale * force);
  f.iterations = run.column("newton_iterations");
  std::printf("[%s] %d steps, Newton max %d, total %d; q at the end %.3f\n", name.c_str(),
              f.summary.steps, f.summary.max_iterations_in_a_step, f.summary.iterations,
              f.q.back());
  return cache.emplace(text, std::move(f)).first->second;
}

// The model with the pressure equation over the step (docs/theory.md eqs. 11.8-11.9).
inline std::string incremental_pressure(const std::string& text) {
  return with_numerics(text, "mixed_pressure_equation", "incremental");
}

}  // namespace geompm::testing

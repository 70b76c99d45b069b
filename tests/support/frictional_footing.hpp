// Shared by the strip-footing tests on cohesionless Mohr-Coulomb soil (docs/validation.md §9):
// the reference values, the examples' models refined for the convergence studies of
// docs/validation.md, and the push phase of a run that may stop early.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "example_text.hpp"
#include "geompm/core/error.hpp"
#include "run_model.hpp"
#include "strip_mesh.hpp"

namespace geompm::testing::frictional_footing {

inline const double kPhi = 30.0 * std::numbers::pi / 180.0;
// Prandtl (1921) / Reissner (1924), exact for associated flow; smooth or rough in weightless soil.
inline const double kNq = std::exp(std::numbers::pi * std::tan(kPhi)) *
                          std::pow(std::tan(std::numbers::pi / 4 + kPhi / 2), 2);  // 18.40
inline const double kNc = (kNq - 1.0) / std::tan(kPhi);                            // 30.14
// Martin (2005), "Exact bearing capacity calculations using the method of characteristics",
// Proc. 11th Int. Conf. IACMAG, Turin: exact N_gamma of a strip, phi = 30 deg, associated flow.
inline constexpr double kNgammaRough = 14.75;
inline constexpr double kNgammaSmooth = 7.65;

// The examples' model without VTK files, on the strip mesh with n cells under the half-width
// (the examples have n = 10, h = B/20).
inline std::string model(const std::string& file, int n, double push_end = 0.03) {
  auto text = replace_once(example_text("frictional_footing/" + file), "vtk: {every: 10}",
                           "vtk: {every: 0}");
  // The examples push only as far as their runs finish; pushed 0.03 B as in the report, the runs
  // stop on the way and the history up to there is used.
  for (const char* push : {"\"-0.01*t\"", "\"-0.007*t\"", "\"-0.004*t\""})
    if (text.find(push) != std::string::npos) text = replace_once(text, push, "\"-0.03*t\"");
  // A test that reads the curve only up to push_end ends the push phase there: the same steps as
  // the report's run up to that settlement, without the costly ones after it.
  if (push_end < 0.03)
    text = replace_once(text, "name: push\n    duration: 1.0\n",
                        "name: push\n    duration: " + std::to_string(push_end / 0.03) + "\n");
  // Pushed beyond 0.015 B the N_q example's top row of points crosses into the empty cells above
  // the surface, where a point alone in a new cell stalls Newton with standard MPM: the report's
  // runs use GIMP (the example's own push to 0.01 B does not need it).
  // And as §9 measured it, when the example still carried it: at most 10 Newton iterations a
  // step in the push, cut back otherwise.
  if (file == "frictional_footing_nq.yaml") {
    text = with_numerics(text, "interpolation", "gimp");
    text = with_newton(text, "max_iterations: 10", "push");
  }
  return strip_mesh(text, n);
}

// The push phase (time >= 1) of a run that may stop early: settlement / B since its start, and q
// in the reference's units (scale x force).
struct Push {
  std::vector<double> s, q;
  int most_newton_iterations = 0;  // in a step of the push
  bool stopped = false;
  double at(double settlement) const {
    for (std::size_t k = 1; k < s.size(); ++k)
      if (s[k] >= settlement - 1e-9) {
        const double a = (settlement - s[k - 1]) / (s[k] - s[k - 1]);
        return q[k - 1] + a * (q[k] - q[k - 1]);
      }
    ADD_FAILURE() << "the run did not reach a settlement of " << settlement << " B";
    return NAN;
  }
  double largest() const { return *std::max_element(q.begin(), q.end()); }
  /// The mean of q over the settlements from..to (the points of the history in between).
  double mean(double from, double to) const {
    double sum = 0.0;
    int count = 0;
    for (std::size_t k = 0; k < s.size(); ++k)
      if (s[k] >= from - 1e-9 && s[k] <= to + 1e-9) sum += q[k], ++count;
    EXPECT_GT(count, 0) << "no point of the history between " << from << " and " << to << " B";
    return sum / count;
  }
};

inline Push run_push(const std::string& text, const std::string& name, double scale) {
  const auto spec = read_model_from_string(text, name + ".yaml");
  auto model = build_model(spec);
  const auto dir = fresh_directory(name);
  RunOptions options;
  options.output_dir = dir;
  options.progress = false;
  Push p;
  try {
    run_analysis(*model, options);
  } catch (const RunError& e) {
    p.stopped = true;  // expected (docs/validation.md §9): keep what finished
    std::printf("[%s] %s\n", name.c_str(), e.what());
  }
  const auto table = read_csv(dir / "history.csv");
  const auto t = table.column("time", "history.csv");
  const auto u = table.column("settlement", "history.csv");
  const auto f = table.column("force", "history.csv");
  const auto iterations = table.column("newton_iterations", "history.csv");
  double s0 = 0.0;
  for (const auto& row : table.rows) {
    if (row[t] <= 1.0 + 1e-9) s0 = -row[u];  // the settlement at the end of the first phase
    if (row[t] < 1.0 - 1e-9) continue;
    p.s.push_back(-row[u] - s0);
    p.q.push_back(scale * row[f]);
    if (row[t] > 1.0 + 1e-9)
      p.most_newton_iterations =
          std::max(p.most_newton_iterations, static_cast<int>(row[iterations]));
  }
  std::printf("[%s] pushed to %.4f B, largest q %.3f\n", name.c_str(), p.s.back(), p.largest());
  return p;
}

// q / q0 = 2 x force / (B q0), less the tiny cohesion's exact share c N_c / q0 (c = 0.01 q0;
// Caquot's corresponding states for weightless soil: q_u = N_q q0 + c N_c).
inline constexpr double kSurchargeScale = -2.0;
inline const double kCohesionShare = 0.01 * kNc;
// N_gamma = q / (gamma B / 2) = 2 x 2 x force / (20 x 1): the steel block's reaction (on the
// soil, downward), or the contact force on a rigid structure (upward).
inline constexpr double kGammaScale = -0.2;
inline constexpr double kContactGammaScale = 0.2;
// The rounded N_gamma examples' token cohesion c = 0.1 kPa adds, by superposition,
// 2 c N_c / (gamma B) = 0.30 to N_gamma (frictional_footing_ngamma_limit*.yaml).
inline const double kGammaCohesionShare = 2.0 * 0.1 * kNc / 20.0;

/// The N_q example in the rigid-plastic limit (docs/validation.md §9
/// and §13): sand E = 1e5 q0 instead of 5000 q0, pushed 0.0015 B so that the mechanism forms
/// before the second row of points under the footing crosses its cell; standard MPM (nothing
/// crosses a cell, so the example's GIMP, for the heave above the surface, is not needed), up
/// to 20 Newton iterations a step (the stiff soil's steps need 13-14 on h = B/40) with
/// backtracking (newton.line_search 6, with which §9 and §13 were measured); n cells under
/// the half-width; no VTK files.
inline std::string nq_rigid_plastic_model(int n) {
  auto text =
      replace_once(replace_once(example_text("frictional_footing/frictional_footing_nq.yaml"),
                                "vtk: {every: 10}", "vtk: {every: 0}"),
                   "E: 5000,", "E: 100000,");
  text = replace_once(
      with_numerics(text, "interpolation", "standard"),
      "    prescribed_motion:\n      - {point_set: footing, displacement: [~, \"-0.01*t\"]}",
      "    newton: {line_search: 6, max_iterations: 20}\n"
      "    prescribed_motion:\n      - {point_set: footing, displacement: [~, \"-0.01*t\"]}");
  return strip_mesh(replace_once(text, "\"-0.01*t\"", "\"-0.0015*t\""), n);
}

// N_q read as docs/validation.md §9 reads it: the surcharge footing on the strip mesh with n cells
// under the half-width, pushed to 0.0105 B, at a settlement of 0.01 B, less the cohesion's share.
struct NqReading {
  double nq;
  int most_newton_iterations;  // in the steps up to 0.0105 B
};
inline NqReading nq_at_one_percent(int n, const std::string& name) {
  const Push push = run_push(model("frictional_footing_nq.yaml", n, 0.0105), name, kSurchargeScale);
  const double q = push.at(0.01) - kCohesionShare;
  std::printf("[N_q, h = B/%d] %.2f at 0.01 B (%+.1f %% of N_q = %.2f)\n", 2 * n, q,
              (q / kNq - 1) * 100, kNq);
  return {q, push.most_newton_iterations};
}

}  // namespace geompm::testing::frictional_footing

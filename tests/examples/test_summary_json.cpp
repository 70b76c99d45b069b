// End-to-end: the summary.json a run writes in its output directory, read back and checked
// against what the run wrote in history.csv and newton.csv, for a run that finishes after
// cut-backs and for one that stops (exit 3).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numeric>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "cli_support.hpp"
#include "example_text.hpp"
#include "geompm/core/fnv1a.hpp"

namespace {

namespace fs = std::filesystem;
using namespace geompm::testing;
using Json = nlohmann::ordered_json;

Json read_json(const fs::path& file) {
  const std::string text = read_text(file);
  EXPECT_FALSE(text.empty()) << "no " << file;
  return text.empty() ? Json() : Json::parse(text);
}

// The failed attempts newton.csv logs: each is a run of rows of one (step, dt) with converged 0
// (a retried step has another dt).
int failed_attempts(const Csv& newton) {
  std::set<std::pair<double, double>> failed;
  const auto step = newton.column("step"), dt = newton.column("dt"),
             converged = newton.column("converged");
  for (std::size_t k = 0; k < step.size(); ++k)
    if (converged[k] == 0.0) failed.insert({step[k], dt[k]});
  return static_cast<int>(failed.size());
}

// summary.json's "history" holds history.csv's columns, in order, with its last row's values.
void expect_last_history_row(const Json& summary, const Csv& history) {
  ASSERT_TRUE(history.problem.empty()) << history.problem;
  ASSERT_FALSE(history.rows.empty());
  const Json& last = summary.at("history");
  ASSERT_EQ(last.size(), history.header.size());
  std::size_t k = 0;
  for (const auto& [name, value] : last.items()) {
    EXPECT_EQ(name, history.header[k]);
    EXPECT_EQ(value.get<double>(), history.rows.back()[k]) << name;
    ++k;
  }
}

class SummaryJson : public GeompmRunTest<> {};

// The soft column of test_run_policies.cpp asked to take its load in one step (at most 5 Newton
// iterations a step): cut back, then
// grown again; summary.json counts what newton.csv and history.csv show.
TEST_F(SummaryJson, CountsWhatAFinishedRunDid) {
  std::string model = example_text("column/column_large_deformation.yaml");
  model = replace_once(model, "time_step: {initial: 0.05, min: 0.001, max: 0.05}",
                       "time_step: {initial: 1.0, min: 0.001, max: 1.0}\n"
                       "    newton: {max_iterations: 5}");
  write("column.yaml", model);
  const auto r = geompm({"run", "-q", "-t", "1", "-o", "out", "column.yaml"});
  ASSERT_TRUE(r.exited && r.exit_code == 0) << describe(r);

  const Json summary = read_json(work() / "out" / "summary.json");
  const Csv history = read_csv(work() / "out" / "history.csv");
  const Csv newton = read_csv(work() / "out" / "newton.csv");
  ASSERT_TRUE(newton.problem.empty()) << newton.problem;
  EXPECT_EQ(summary.at("geompm_version"), GEOMPM_VERSION);
  EXPECT_EQ(summary.at("model_file"), "column.yaml");
  EXPECT_EQ(summary.at("model_hash"), "fnv1a64:" + geompm::fnv1a_hex(geompm::fnv1a_64(model)));
  EXPECT_EQ(summary.at("status"), "finished");
  EXPECT_EQ(summary.at("reason"), "finished");
  EXPECT_EQ(summary.at("time").get<double>(), history.column("time").back());
  EXPECT_EQ(summary.at("resumed_at_steps").size(), 0u);

  const int steps = static_cast<int>(history.rows.size()) - 1;  // the first row is the start
  const auto iterations = history.column("newton_iterations");
  const int total = static_cast<int>(std::accumulate(iterations.begin(), iterations.end(), 0.0));
  const int most = static_cast<int>(*std::max_element(iterations.begin(), iterations.end()));
  EXPECT_EQ(summary.at("steps"), steps);
  EXPECT_GT(summary.at("cutbacks").get<int>(), 0) << "a single step of 1.0 cannot converge";
  EXPECT_EQ(summary.at("cutbacks"), failed_attempts(newton));
  EXPECT_EQ(summary.at("newton_iterations").at("total"), total);
  EXPECT_EQ(summary.at("newton_iterations").at("most_in_a_step"), most);
  EXPECT_GT(summary.at("wall_seconds").get<double>(), 0.0);

  ASSERT_EQ(summary.at("phases").size(), 1u);
  const Json& phase = summary.at("phases")[0];
  EXPECT_EQ(phase.at("name"), "gravity");
  EXPECT_EQ(phase.at("status"), "finished");
  EXPECT_EQ(phase.at("steps"), steps);
  EXPECT_EQ(phase.at("cutbacks"), summary.at("cutbacks"));
  EXPECT_EQ(phase.at("newton_iterations"), summary.at("newton_iterations"));
  EXPECT_GT(phase.at("wall_seconds").get<double>(), 0.0);
  EXPECT_LE(phase.at("wall_seconds").get<double>(), summary.at("wall_seconds").get<double>());
  expect_last_history_row(summary, history);
}

// A phase that cannot converge at its smallest step after one that finished: exit 3, and
// summary.json says why, which phase stopped and what each phase did.
TEST_F(SummaryJson, SaysWhyARunStopped) {
  const std::string stubborn = R"(  - name: stubborn
    duration: 1.0
    time_step: {initial: 0.1, min: 0.05, max: 0.1}
    newton: {max_iterations: 1, residual_tolerance: 1.0e-14, displacement_tolerance: 1.0e-14}
    prescribed_motion:
      - {point_set: top, displacement: [~, "-0.1*t"]}
    fixities:
      - {boundary: left, fix: normal}
      - {boundary: right, fix: normal}
      - {boundary: bottom, fix: all}
  - name: never
    duration: 1.0
    time_step: 0.1
output:
)";
  write("oedometer.yaml",
        replace_once(example_text("oedometer/oedometer.yaml"), "output:\n", stubborn));
  const auto r = geompm({"run", "-q", "-t", "1", "-o", "out", "oedometer.yaml"});
  ASSERT_TRUE(r.exited && r.exit_code == 3) << describe(r);

  const Json summary = read_json(work() / "out" / "summary.json");
  const Csv history = read_csv(work() / "out" / "history.csv");
  EXPECT_EQ(summary.at("status"), "stopped");
  const std::string reason = summary.at("reason");
  EXPECT_TRUE(Contains(reason, "phase 'stubborn'"));
  EXPECT_TRUE(Contains(reason, "did not converge with the smallest allowed time step (0.05)"));
  EXPECT_TRUE(Contains(r.err, reason)) << "the log says the same";
  EXPECT_EQ(summary.at("steps"), 10);
  EXPECT_EQ(summary.at("cutbacks"), 2) << "0.1 and 0.05 both fail; 0.025 is below the minimum";
  EXPECT_EQ(summary.at("time").get<double>(), history.column("time").back());

  const Json& phases = summary.at("phases");
  ASSERT_EQ(phases.size(), 3u);
  EXPECT_EQ(phases[0].at("name"), "compression");
  EXPECT_EQ(phases[0].at("status"), "finished");
  EXPECT_EQ(phases[0].at("steps"), 10);
  EXPECT_EQ(phases[0].at("cutbacks"), 0);
  EXPECT_EQ(phases[1].at("name"), "stubborn");
  EXPECT_EQ(phases[1].at("status"), "stopped");
  EXPECT_EQ(phases[1].at("steps"), 0);
  EXPECT_EQ(phases[1].at("cutbacks"), 2);
  EXPECT_EQ(phases[2].at("status"), "not started");
  EXPECT_EQ(phases[2].at("steps"), 0);
  expect_last_history_row(summary, history);
}

}  // namespace

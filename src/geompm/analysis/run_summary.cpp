#include "geompm/analysis/run_summary.hpp"

#include <nlohmann/json.hpp>

#include "geompm/core/byte_archive.hpp"
#include "geompm/core/fnv1a.hpp"
#include "geompm/io/vtk_writer.hpp"

namespace geompm {

void RunSummary::save(ByteWriter& out) const {
  out.put(wall_seconds);
  out.put(steps);
  out.put(iterations);
  out.put(cutbacks);
  out.put(max_iterations_in_a_step);
  out.put(residual_histories);
  out.put(static_cast<std::uint64_t>(phases.size()));
  for (const PhaseSummary& p : phases) {
    out.put(p.name);
    out.put(p.status);
    out.put(p.steps);
    out.put(p.cutbacks);
    out.put(p.iterations);
    out.put(p.max_iterations_in_a_step);
    out.put(p.wall_seconds);
  }
  out.put(resumed_at_steps);
  std::vector<std::pair<std::int32_t, std::array<double, 4>>> lost_points_saved;
  for (const LostPoint& p : lost)
    lost_points_saved.push_back({p.id, {p.time, p.position[0], p.position[1], p.position[2]}});
  out.put(lost_points_saved);
}

void RunSummary::load(ByteReader& in) {
  in.get(wall_seconds);
  in.get(steps);
  in.get(iterations);
  in.get(cutbacks);
  in.get(max_iterations_in_a_step);
  in.get(residual_histories);
  phases.resize(in.get<std::uint64_t>());
  for (PhaseSummary& p : phases) {
    in.get(p.name);
    in.get(p.status);
    in.get(p.steps);
    in.get(p.cutbacks);
    in.get(p.iterations);
    in.get(p.max_iterations_in_a_step);
    in.get(p.wall_seconds);
  }
  in.get(resumed_at_steps);
  std::vector<std::pair<std::int32_t, std::array<double, 4>>> lost_points_saved;
  in.get(lost_points_saved);
  lost.clear();
  for (const auto& [id, at] : lost_points_saved) lost.push_back({id, at[0], {at[1], at[2], at[3]}});
  in.expect_end();
}

namespace {

nlohmann::ordered_json newton_json(int total, int most) {
  return {{"total", total}, {"most_in_a_step", most}};
}

nlohmann::ordered_json linear_json(std::int64_t iterations, double seconds) {
  return {{"iterations", iterations}, {"seconds", seconds}};
}

}  // namespace

void write_summary_json(const std::filesystem::path& file, const RunSummary& summary) {
  // ordered_json: the keys in the order a reader expects them, not alphabetically.
  nlohmann::ordered_json json;
  json["geompm_version"] = GEOMPM_VERSION;
  json["model_file"] = summary.model_file;
  json["model_hash"] = "fnv1a64:" + fnv1a_hex(summary.model_hash);
  json["status"] = summary.status;
  json["reason"] = summary.reason;
  json["time"] = summary.time;
  json["steps"] = summary.steps;
  json["cutbacks"] = summary.cutbacks;
  json["newton_iterations"] = newton_json(summary.iterations, summary.max_iterations_in_a_step);
  json["linear_solver"] = summary.linear_solver;
  json["linear_solves"] = linear_json(summary.linear_iterations, summary.linear_seconds);
  json["wall_seconds"] = summary.wall_seconds;
  json["lost_points"] = summary.lost_points;
  json["lost_mass"] = summary.lost_mass;
  nlohmann::ordered_json lost = nlohmann::ordered_json::array();
  for (const LostPoint& p : summary.lost)
    lost.push_back({{"id", p.id}, {"time", p.time}, {"position", p.position}});
  json["lost"] = lost;
  json["resumed_at_steps"] = summary.resumed_at_steps;
  nlohmann::ordered_json phases = nlohmann::ordered_json::array();
  for (const PhaseSummary& p : summary.phases)
    phases.push_back({{"name", p.name},
                      {"status", p.status},
                      {"steps", p.steps},
                      {"cutbacks", p.cutbacks},
                      {"newton_iterations", newton_json(p.iterations, p.max_iterations_in_a_step)},
                      {"linear_solves", linear_json(p.linear_iterations, p.linear_seconds)},
                      {"wall_seconds", p.wall_seconds}});
  json["phases"] = phases;
  // The last value of each history column; a non-finite value (never expected) becomes null.
  nlohmann::ordered_json history = nlohmann::ordered_json::object();
  for (std::size_t k = 0; k < summary.history_columns.size(); ++k)
    history[summary.history_columns[k]] = k < summary.history_last.size()
                                              ? nlohmann::ordered_json(summary.history_last[k])
                                              : nlohmann::ordered_json();
  json["history"] = history;
  write_file_atomically(file, json.dump(2) + "\n");
}

}  // namespace geompm

#include "geompm/analysis/distribution.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "geompm/core/error.hpp"
#include "geompm/mesh/partition.hpp"

namespace geompm {

void check_distributable(const Model& model, int processes) {
  const spec::Model& spec = model.spec;
  std::vector<std::string> features;
  const auto any_phase = [&](auto&& has) {
    return std::any_of(spec.phases.begin(), spec.phases.end(), has);
  };
  if (any_phase([](const spec::Phase& p) { return p.newton.tangent_check > 0.0; }))
    features.push_back("the tangent check (newton.tangent_check)");
  if (features.empty()) return;
  std::string list;
  for (const std::string& f : features) list += "\n  - " + f;
  throw InputError(fmt::format(
      "{}: a run on {} processes does not handle yet:{}\nRun it on one process (without "
      "mpirun), or see docs/user-guide.md, \"Running on several processes\"",
      spec.file, processes, list));
}

std::vector<int> partition_by_work(const Model& model, std::vector<double> points_in_cell,
                                   int processes) {
  points_in_cell.resize(model.mesh.num_cells(), 0.0);
  // An FEM cell's work is its Gauss points'.
  if (model.fem)
    for (Index c : model.fem->gauss_points().cell) points_in_cell[c] += 1.0;
  return partition_cells(model.mesh, points_in_cell, processes);
}

std::vector<int> partition_by_points(const Model& model, int processes) {
  std::vector<double> points_in_cell(model.mesh.num_cells(), 0.0);
  for (Index c : model.points.cell) points_in_cell[c] += 1.0;
  return partition_by_work(model, std::move(points_in_cell), processes);
}

}  // namespace geompm

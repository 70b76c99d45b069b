#include "geompm/analysis/motion_check.hpp"

#include <fmt/format.h>

#include <cmath>

namespace geompm {

namespace {

// A typical cell size: the mesh's extent shared among its cells.
double typical_cell_size(const Mesh& mesh) {
  const int dim = mesh.dim();
  Vec3 lo = mesh.nodes.front(), hi = lo;
  for (const Vec3& x : mesh.nodes) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  double volume = 1.0;
  for (int d = 0; d < dim; ++d) volume *= hi(d) - lo(d);
  return std::pow(volume / std::max<Index>(mesh.num_cells(), 1), 1.0 / dim);
}

}  // namespace

std::vector<double> motion_sums(const Model& model, const PhaseContext& phase) {
  const MaterialPoints& points = model.points;
  std::vector<double> sums(motion_sum_values * phase.motions.size(), 0.0);
  for (std::size_t m = 0; m < phase.motions.size(); ++m) {
    double* sum = &sums[motion_sum_values * m];
    // Mass-weighted, as the displacement history of a point set (volume-weighted if weightless).
    for (Index p = 0; p < points.size(); ++p)
      if (points.sets[p] >> phase.motions[m].set & 1u) {
        const double w = points.mass[p] > 0 ? points.mass[p] : points.volume[p];
        sum[0] += w;
        for (int i = 0; i < 3; ++i) sum[1 + i] += w * points.phase_displacement[p](i);
      }
  }
  return sums;
}

std::string unfollowed_motions(const Model& model, const PhaseContext& phase,
                               const std::vector<double>& sums) {
  const int dim = model.mesh.dim();
  const double floor = motion_shortfall_floor * typical_cell_size(model.mesh);
  std::string found;
  for (std::size_t m = 0; m < phase.motions.size(); ++m) {
    const PhaseContext::Motion& motion = phase.motions[m];
    const double* sum = &sums.at(motion_sum_values * m);
    const double weight = sum[0];
    if (!(weight > 0)) continue;  // every driven point left the mesh: reported as lost points
    const Vec3 moved = Vec3(sum[1], sum[2], sum[3]) / weight;
    for (int i = 0; i < dim; ++i) {
      if (!motion.components[i]) continue;
      const double prescribed = motion.done(i), shortfall = std::abs(moved(i) - prescribed);
      if (shortfall > motion_shortfall_tolerance * std::abs(prescribed) && shortfall > floor)
        found += fmt::format(
            "\n  {} ({}): the point set moved {:.6g} in {}, {:.3g} % of the {:.6g} prescribed",
            phase.spec->motions[m].source.describe(), phase.spec->motions[m].point_set, moved(i),
            "xyz"[i], prescribed != 0 ? 100 * moved(i) / prescribed : 0.0, prescribed);
    }
  }
  return found;
}

}  // namespace geompm

#include "geompm/boundary/fixities.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace geompm {

std::pair<Vec3, Vec3> node_bounds(const Mesh& mesh) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max()), hi = -lo;
  for (const auto& x : mesh.nodes) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  return {lo, hi};
}

double node_tolerance(const Mesh& mesh) {
  const auto [lo, hi] = node_bounds(mesh);
  return 1e-9 * head_norm(hi - lo, mesh.dim());
}

std::vector<ResolvedFixity> resolve_fixities(const Mesh& mesh,
                                             const std::vector<spec::Fixity>& fixities) {
  const int dim = mesh.dim();
  const auto [lo, hi] = node_bounds(mesh);
  const double tol = node_tolerance(mesh);

  std::vector<ResolvedFixity> out;
  for (const auto& f : fixities) {
    ResolvedFixity r;
    int normal_axis = -1;
    if (!f.boundary.empty()) {
      r.name = f.boundary;
      r.nodes = mesh.node_groups.at(f.boundary);
      if (f.normal_only) {
        for (int d = 0; d < dim && normal_axis < 0; ++d) {
          double a = std::numeric_limits<double>::max(), b = -a;
          for (Index n : r.nodes) {
            a = std::min(a, mesh.nodes[n](d));
            b = std::max(b, mesh.nodes[n](d));
          }
          if (b - a <= tol) normal_axis = d;
        }
        if (normal_axis < 0)
          throw InputError(f.source,
                           fmt::format("boundary '{}' is not a plane normal to x, y or z, "
                                       "so 'normal' is ambiguous; fix components instead",
                                       f.boundary));
      }
    } else {
      r.name = fmt::format("plane {}={:g}", "xyz"[f.plane_axis], f.plane_value);
      for (Index n = 0; n < mesh.num_nodes(); ++n)
        if (std::abs(mesh.nodes[n](f.plane_axis) - f.plane_value) <= tol) r.nodes.push_back(n);
      if (r.nodes.empty())
        throw InputError(
            f.source, fmt::format("no mesh node lies on the plane {} (the mesh spans "
                                  "[{:g}, {:g}] in {})",
                                  r.name, lo(f.plane_axis), hi(f.plane_axis), "xyz"[f.plane_axis]));
      normal_axis = f.plane_axis;
    }
    if (f.normal_only)
      r.components[normal_axis] = true;
    else
      r.components = f.components;
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace geompm

#include "geompm/boundary/grid_motions.hpp"

#include <fmt/format.h>

#include <limits>
#include <map>

#include "geompm/boundary/fixities.hpp"
#include "geompm/core/error.hpp"

namespace geompm {

Vec3 prescribed_increment(const std::array<std::optional<Expression>, 3>& components, bool velocity,
                          double t0, double t1) {
  Vec3 du = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  for (int d = 0; d < 3; ++d) {
    if (!components[d]) continue;
    const Expression& f = *components[d];
    du(d) = velocity ? 0.5 * (t1 - t0) * (f.at_time(t0) + f.at_time(t1))
                     : f.at_time(t1) - f.at_time(t0);
  }
  return du;
}

Vec3 ResolvedGridMotion::increment(double t0, double t1) const {
  return prescribed_increment(components, velocity, t0, t1);
}

std::vector<ResolvedGridMotion> resolve_grid_motions(const Mesh& mesh,
                                                     const std::vector<spec::GridMotion>& motions) {
  std::vector<ResolvedGridMotion> out;
  // (node, component) -> the motion that drives it, to refuse two motions of one unknown.
  std::map<std::pair<Index, int>, const spec::GridMotion*> driven;
  for (const auto& m : motions) {
    // The nodes are found as a fixity finds them (a boundary, node set or plane).
    spec::Fixity selection;
    selection.boundary = m.boundary;
    selection.plane_axis = m.plane_axis;
    selection.plane_value = m.plane_value;
    selection.source = m.source;
    ResolvedFixity nodes = resolve_fixities(mesh, {selection}).front();
    ResolvedGridMotion r;
    r.name = nodes.name;
    r.nodes = std::move(nodes.nodes);
    r.velocity = m.velocity;
    for (int d = 0; d < 3; ++d) {
      if (m.components[d].empty()) continue;
      r.components[d] = Expression(m.components[d], component_place(m.source, d));
      for (Index n : r.nodes) {
        const auto [at, added] = driven.try_emplace({n, d}, &m);
        if (!added) {
          const Vec3& x = mesh.nodes[n];
          throw InputError(
              m.source,
              fmt::format("the node at [{:g}, {:g}, {:g}] is already driven in {} by {} (line "
                          "{}); a node component takes one motion",
                          x.x(), x.y(), x.z(), "xyz"[d], at -> second -> source.key_path,
                          at->second->source.line));
        }
      }
    }
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace geompm

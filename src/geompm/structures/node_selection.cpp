#include "geompm/structures/node_selection.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "geompm/core/error.hpp"

namespace geompm {

std::vector<Index> select_nodes(const StructureMesh& mesh, const spec::StructureNodes& s) {
  using Kind = spec::StructureNodes::Kind;
  const std::vector<Vec3>& x = mesh.nodes();
  const Index n = static_cast<Index>(x.size());
  std::vector<Index> selected;
  if (s.kind == Kind::Group) {
    const auto it = mesh.mesh().node_groups.find(s.group);
    if (it == mesh.mesh().node_groups.end()) {
      std::vector<std::string> names;
      for (const auto& [name, ids] : mesh.mesh().node_groups) names.push_back(name);
      throw InputError(
          s.source,
          fmt::format("the structure's mesh has no node group '{}'; it has: {} (or "
                      "use all, top, bottom, left, right or a box {{min, max}})",
                      s.group, names.empty() ? "none" : fmt::format("{}", fmt::join(names, ", "))));
    }
    selected = it->second;
  } else {
    Vec3 lo = x.front(), hi = x.front();
    for (const Vec3& p : x) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    // Nodes on a side within a millionth of the structure's size of it (round-off of a mesher).
    const double tol = 1e-6 * (hi - lo).norm();
    const int up = mesh.dim() - 1;  // y in 2D, z in 3D
    for (Index a = 0; a < n; ++a) {
      const Vec3& p = x[a];
      bool in = true;
      switch (s.kind) {
        case Kind::Top:
          in = p(up) >= hi(up) - tol;
          break;
        case Kind::Bottom:
          in = p(up) <= lo(up) + tol;
          break;
        case Kind::Left:
          in = p.x() <= lo.x() + tol;
          break;
        case Kind::Right:
          in = p.x() >= hi.x() - tol;
          break;
        case Kind::Box:
          for (int i = 0; i < mesh.dim(); ++i)
            in = in && p(i) >= s.min(i) - tol && p(i) <= s.max(i) + tol;
          break;
        default:
          break;
      }
      if (in) selected.push_back(a);
    }
  }
  std::sort(selected.begin(), selected.end());
  if (selected.empty()) throw InputError(s.source, "selects none of the structure's nodes");
  return selected;
}

}  // namespace geompm

#include "geompm/analysis/region_test.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace geompm {

std::string group_names(const std::map<std::string, std::vector<Index>>& groups) {
  std::string names;
  for (const auto& [name, members] : groups) names += (names.empty() ? "" : ", ") + name;
  return names.empty() ? "(none)" : names;
}

RegionTest::RegionTest(const spec::Region& region, const Mesh& mesh, int dim)
    : region_(region), dim_(dim) {
  if (region.kind == spec::Region::Kind::Group) {
    auto it = mesh.cell_groups.find(region.group);
    if (it == mesh.cell_groups.end())
      throw InputError(region.source,
                       fmt::format("the mesh has no region '{}'; its regions are: {}", region.group,
                                   group_names(mesh.cell_groups)));
    cells_ = &it->second;
  }
}

bool RegionTest::contains(const Vec3& x, Index cell) const {
  using K = spec::Region::Kind;
  switch (region_.kind) {
    case K::All:
      return true;
    case K::Group:
      return std::binary_search(cells_->begin(), cells_->end(), cell);
    case K::Box:
      for (int d = 0; d < dim_; ++d)
        if (x(d) < region_.min(d) || x(d) > region_.max(d)) return false;
      return true;
    case K::Circle:
      return (x - region_.center).head(dim_).norm() <= region_.radius;
    case K::Polygon:
      return inside_polygon(x);
  }
  return false;
}

std::optional<std::pair<Vec3, Vec3>> RegionTest::bounds() const {
  using K = spec::Region::Kind;
  if (region_.kind == K::Box) return std::make_pair(region_.min, region_.max);
  if (region_.kind == K::Circle)
    return std::make_pair(Vec3(region_.center.array() - region_.radius),
                          Vec3(region_.center.array() + region_.radius));
  if (region_.kind == K::Polygon) {
    Vec3 lo = region_.polygon.front(), hi = lo;
    for (const auto& v : region_.polygon) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    return std::make_pair(lo, hi);
  }
  return std::nullopt;
}

bool RegionTest::inside_polygon(const Vec3& x) const {
  // Even-odd rule.
  bool inside = false;
  const auto& v = region_.polygon;
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    if ((v[i].y() > x.y()) != (v[j].y() > x.y()) &&
        x.x() < (v[j].x() - v[i].x()) * (x.y() - v[i].y()) / (v[j].y() - v[i].y()) + v[i].x())
      inside = !inside;
  }
  return inside;
}

}  // namespace geompm

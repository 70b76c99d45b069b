#include "geompm/analysis/mesh_regions.hpp"

#include <fmt/format.h>

#include "geompm/analysis/region_test.hpp"
#include "geompm/core/error.hpp"
#include "geompm/mesh/element.hpp"

namespace geompm {

Vec3 cell_centroid(const Mesh& mesh, Index c) {
  const auto nodes = mesh.cell_nodes(c);
  const int corners = dispatch_cell_type(mesh.cell_type, [](auto e) {
    return decltype(e)::dim == 2 ? (decltype(e)::nodes == 6 ? 3 : decltype(e)::nodes)
                                 : decltype(e)::nodes;
  });
  Vec3 x = Vec3::Zero();
  for (int a = 0; a < corners; ++a) x += mesh.nodes[nodes[a]];
  return x / corners;
}

std::vector<CellKind> classify_cells(const spec::Model& spec, const Mesh& mesh) {
  if (spec.regions.empty()) return {};
  const Index n = mesh.num_cells();
  std::vector<CellKind> kind(n, CellKind::Mpm);
  std::vector<int> named_by(n, -1);  // the region that set the cell's kind
  std::vector<Vec3> centroid(n);
  for (Index c = 0; c < n; ++c) centroid[c] = cell_centroid(mesh, c);
  for (std::size_t r = 0; r < spec.regions.size(); ++r) {
    const spec::MeshRegion& region = spec.regions[r];
    const RegionTest test(region.region, mesh, mesh.dim());
    Index count = 0;
    for (Index c = 0; c < n; ++c) {
      if (!test.contains(centroid[c], c)) continue;
      ++count;
      if (named_by[c] >= 0 && kind[c] != region.kind) {
        const spec::MeshRegion& other = spec.regions[named_by[c]];
        throw InputError(
            region.source,
            fmt::format("regions '{}' ({}) and '{}' ({}) overlap at cell {} (centroid "
                        "[{:g}, {:g}, {:g}]): a cell has one kind; make the regions "
                        "disjoint",
                        other.name, to_string(other.kind), region.name, to_string(region.kind), c,
                        centroid[c].x(), centroid[c].y(), centroid[c].z()));
      }
      kind[c] = region.kind;
      named_by[c] = static_cast<int>(r);
    }
    if (count == 0)
      throw InputError(region.source,
                       fmt::format("region '{}' holds no cell of the mesh (a cell belongs to it "
                                   "when the region holds the cell's centroid)",
                                   region.name));
  }
  return kind;
}

}  // namespace geompm

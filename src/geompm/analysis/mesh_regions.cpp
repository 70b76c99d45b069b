#include "geompm/analysis/mesh_regions.hpp"

#include <fmt/format.h>

#include "geompm/analysis/region_test.hpp"
#include "geompm/core/error.hpp"
#include "geompm/mesh/element.hpp"
#include "geompm/structures/structure_distance.hpp"

namespace geompm {

Vec3 cell_centroid(const Mesh& mesh, Index c) {
  const auto nodes = mesh.cell_nodes(c);
  const int corners = dispatch_cell_type(mesh.type_of(c), [](auto e) {
    return decltype(e)::dim == 2 ? (decltype(e)::nodes == 6 ? 3 : decltype(e)::nodes)
                                 : decltype(e)::nodes;
  });
  Vec3 x = Vec3::Zero();
  for (int a = 0; a < corners; ++a) x += mesh.nodes[nodes[a]];
  return x / corners;
}

namespace {

// Per cell, whether region r's distance from its structure admits the cell's centroid (every cell
// when the region gives no distance).
std::vector<char> near_structure(const spec::MeshRegion& region, const std::vector<Vec3>& centroid,
                                 const spec::Model& spec,
                                 const std::vector<std::unique_ptr<Structure>>& structures) {
  if (!region.near) return std::vector<char>(centroid.size(), 1);
  const spec::MeshRegion::Near& near = *region.near;
  std::string names;
  for (std::size_t s = 0; s < spec.structures.size(); ++s) {
    if (spec.structures[s].name != near.structure) {
      names += (names.empty() ? "" : ", ") + spec.structures[s].name;
      continue;
    }
    const StructureDistance distance(structures[s]->mesh());
    std::vector<char> admits(centroid.size());
    for (std::size_t c = 0; c < centroid.size(); ++c)
      admits[c] = (distance(centroid[c]) <= near.distance) != near.beyond;
    return admits;
  }
  throw InputError(near.source,
                   fmt::format("region '{}': the model has no structure '{}'; its "
                               "structures are: {}",
                               region.name, near.structure, names.empty() ? "(none)" : names));
}

}  // namespace

std::vector<CellKind> classify_cells(const spec::Model& spec, const Mesh& mesh,
                                     const std::vector<std::unique_ptr<Structure>>& structures) {
  if (spec.regions.empty()) return {};
  const Index n = mesh.num_cells();
  std::vector<CellKind> kind(n, CellKind::Mpm);
  std::vector<int> named_by(n, -1);  // the region that set the cell's kind
  std::vector<Vec3> centroid(n);
  for (Index c = 0; c < n; ++c) centroid[c] = cell_centroid(mesh, c);
  for (std::size_t r = 0; r < spec.regions.size(); ++r) {
    const spec::MeshRegion& region = spec.regions[r];
    const RegionTest test(region.region, mesh, mesh.dim());
    const std::vector<char> near = near_structure(region, centroid, spec, structures);
    Index count = 0;
    for (Index c = 0; c < n; ++c) {
      if (!near[c] || !test.contains(centroid[c], c)) continue;
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

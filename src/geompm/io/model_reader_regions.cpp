// Model file section `regions`: the kinds of the background mesh's cells (seed §3.4): MPM (the
// default), FEM or buffer, each a region of the mesh (a Gmsh physical group of cells, or a box,
// polygon, circle or sphere holding the cells' centroids). Which cells overlap is known only when
// the mesh is built (analysis/mesh_regions.cpp).
#include <fmt/format.h>

#include "geompm/io/model_reader_sections.hpp"

namespace geompm::model_reader {

std::vector<spec::MeshRegion> read_regions(const yaml::Node& node, const Context& context) {
  std::vector<spec::MeshRegion> regions;
  for (const auto& [name, region_node] : node.entries()) {
    if (name.empty()) region_node.fail("a region needs a name");
    const yaml::Map entry = region_node.map({"kind", "region"});
    spec::MeshRegion region;
    region.name = name;
    region.source = region_node.where();
    const std::string kind = entry.required("kind").choice({"mpm", "fem", "buffer"});
    region.kind = kind == "fem"      ? CellKind::Fem
                  : kind == "buffer" ? CellKind::Buffer
                                     : CellKind::Mpm;
    region.region = read_region(entry.required("region"), context);
    regions.push_back(std::move(region));
  }
  return regions;
}

}  // namespace geompm::model_reader

// Model file section `regions`: the kinds of the background mesh's cells (seed §3.4): MPM (the
// default), FEM or buffer, each a region of the mesh (a Gmsh physical group of cells, or a box,
// polygon, circle or sphere holding the cells' centroids). Which cells overlap is known only when
// the mesh is built (analysis/mesh_regions.cpp). A region of a generated mesh may give its cells'
// type.
#include <fmt/format.h>

#include "geompm/io/model_reader_sections.hpp"

namespace geompm::model_reader {

namespace {

// `within` / `beyond`: {structure: name, distance: d}, the cells by their distance from it.
spec::MeshRegion::Near read_near(const yaml::Node& node) {
  const yaml::Map entry = node.map({"structure", "distance"});
  spec::MeshRegion::Near near;
  near.structure = entry.required("structure").text();
  near.distance = read_positive(entry.required("distance"));
  near.source = node.where();
  return near;
}

// `cell`: the type of a generated mesh's rectangles in the region (quad4 <-> tri3), only where
// both share their corner nodes, so that the mesh stays conforming.
CellType read_cell_type(const yaml::Node& cell, const yaml::Map& entry, const Context& context) {
  const std::string type = cell.choice({"tri3", "quad4"});
  if (!context.cell_type)
    cell.fail(
        "a region's cell type applies to a generated mesh (mesh.generate); an imported mesh's "
        "cells are Gmsh's: mesh the region with the cells you want there");
  if (context.dimension != 2 ||
      (*context.cell_type != CellType::Quad4 && *context.cell_type != CellType::Tri3))
    cell.fail(
        fmt::format("a region's cell type mixes quad4 and tri3 cells of a generated 2D "
                    "mesh, but the mesh's cells are {}; generate quad4 or tri3 cells, or "
                    "remove 'cell'",
                    to_string(*context.cell_type)));
  if (entry.find("within") || entry.find("beyond"))
    cell.fail(
        "a region's cell type needs the region as a shape (box, polygon, circle), not a "
        "distance from a structure: the mesh is generated before the structures");
  if (!entry.find("region"))
    cell.fail("a region's cell type needs the region as a shape (region: {box: ...})");
  return *parse_cell_type(type);
}

}  // namespace

std::vector<spec::MeshRegion> read_regions(const yaml::Node& node, const Context& context) {
  std::vector<spec::MeshRegion> regions;
  for (const auto& [name, region_node] : node.entries()) {
    if (name.empty()) region_node.fail("a region needs a name");
    const yaml::Map entry = region_node.map({"kind", "region", "within", "beyond", "cell"});
    spec::MeshRegion region;
    region.name = name;
    region.source = region_node.where();
    const std::string kind = entry.required("kind").choice({"mpm", "fem", "buffer"});
    region.kind = kind == "fem"      ? CellKind::Fem
                  : kind == "buffer" ? CellKind::Buffer
                                     : CellKind::Mpm;
    const auto within = entry.find("within"), beyond = entry.find("beyond");
    if (within && beyond) beyond->fail("give either within or beyond, not both");
    if (within || beyond) {
      region.near = read_near(within ? *within : *beyond);
      region.near->beyond = beyond.has_value();
    }
    if (auto cell = entry.find("cell")) {
      region.cell = read_cell_type(*cell, entry, context);
      region.cell_source = cell->where();
    }
    if (auto given = entry.find("region"))
      region.region = read_region(*given, context);
    else if (!region.near)
      region_node.fail(
          "a region needs `region` (cells of a group or a shape), `within` or `beyond`");
    else
      region.region.source = region_node.where();
    regions.push_back(std::move(region));
  }
  return regions;
}

}  // namespace geompm::model_reader

#include "geompm/mesh/gmsh_import.hpp"

#include <fmt/format.h>
#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <unordered_map>

#include "geompm/core/byte_archive.hpp"
#include "geompm/core/error.hpp"
#include "geompm/core/isolated_call.hpp"
#include "geompm/mesh/cell_geometry.hpp"
#include "geompm/mesh/face_conformity.hpp"
#include "geompm/mesh/gmsh_session.hpp"

namespace geompm {

namespace {

/// Gmsh element type numbers of the cells geompm knows (their node order is Gmsh's, see
/// element.hpp, so no renumbering is needed).
std::optional<CellType> cell_type_of_gmsh(int gmsh_type) {
  switch (gmsh_type) {
    case 2:
      return CellType::Tri3;
    case 9:
      return CellType::Tri6;
    case 3:
      return CellType::Quad4;
    case 4:
      return CellType::Tet4;
    case 5:
      return CellType::Hex8;
    case 7:
      return CellType::Pyramid5;
    default:
      return std::nullopt;
  }
}

std::string gmsh_type_name(int gmsh_type) {
  if (const auto type = cell_type_of_gmsh(gmsh_type)) return to_string(*type);
  try {
    std::string name;
    int dim = 0, order = 0, nodes = 0, primary = 0;
    std::vector<double> local;
    gmsh::model::mesh::getElementProperties(gmsh_type, name, dim, order, nodes, local, primary);
    return fmt::format("'{}' (Gmsh type {})", name, gmsh_type);
  } catch (...) {
    return fmt::format("Gmsh type {}", gmsh_type);
  }
}

struct PhysicalGroup {
  int dim = 0;
  std::string name;
  std::vector<std::size_t> element_tags;  // dim == mesh dimension: the region's cells
  std::vector<std::size_t> node_tags;     // dim < mesh dimension: the boundary's nodes
};

/// The cells of the open model: per Gmsh type block, its cell type, Gmsh tags and node tags.
struct GmshCells {
  struct Block {
    CellType type = CellType::Tri3;
    std::vector<std::size_t> tags, node_tags;
  };
  std::vector<Block> blocks;
  std::vector<std::size_t> tags() const {
    std::vector<std::size_t> all;
    for (const Block& block : blocks) all.insert(all.end(), block.tags.begin(), block.tags.end());
    return all;
  }
  std::vector<std::size_t> node_tags() const {
    std::vector<std::size_t> all;
    for (const Block& block : blocks)
      all.insert(all.end(), block.node_tags.begin(), block.node_tags.end());
    return all;
  }
};

std::string type_list(const std::vector<int>& types) {
  std::string found;
  for (int type : types) found += (found.empty() ? "" : ", ") + gmsh_type_name(type);
  return found;
}

// The model's cells of the mesh dimension, of types geompm knows: one type, or tri3 with quad4
// (2D), or any of tet4, hex8 and pyramid5 (3D), which share their corner nodes on a conforming
// interface (checked after the import: check_conforming_faces). Tri6 mixes with nothing: its
// mid-side nodes have no partner on a linear neighbour's edge. Prisms are not supported.
GmshCells read_cells(const SourceLocation& where, int dimension) {
  const char* expected = dimension == 2
                             ? "triangles (tri3, tri6) or quadrangles (quad4)"
                             : "tetrahedra (tet4), hexahedra (hex8) and pyramids (pyramid5)";

  std::vector<int> types;
  std::vector<std::vector<std::size_t>> element_tags, element_nodes;
  gmsh::model::mesh::getElements(types, element_tags, element_nodes, dimension, -1);
  if (types.empty())
    throw InputError(where, fmt::format("has no {}D cells; expected {}", dimension, expected));
  for (int type : types) {
    if (type == 6)  // Gmsh's prism
      throw InputError(
          where, fmt::format("has prism (wedge6) cells, which geompm does not support; Gmsh makes "
                             "them by extruding triangles or in boundary layers, but expected {} "
                             "only: mesh the volume with tetrahedra, or recombine it into "
                             "hexahedra",
                             expected));
    if (!cell_type_of_gmsh(type))
      throw InputError(where, fmt::format("has {}D cells of the unsupported type {}; expected {}",
                                          dimension, gmsh_type_name(type), expected));
  }
  if (types.size() > 1 && std::find(types.begin(), types.end(), 9) != types.end())
    throw InputError(where, fmt::format("mixes tri6 with other cells ({}); tri6 cells have "
                                        "mid-side nodes no linear cell shares, so expected tri6 "
                                        "alone, or tri3 with quad4",
                                        type_list(types)));
  GmshCells cells;
  for (std::size_t b = 0; b < types.size(); ++b)
    cells.blocks.push_back(
        {*cell_type_of_gmsh(types[b]), std::move(element_tags[b]), std::move(element_nodes[b])});
  return cells;
}

// The physical groups up to the mesh dimension: regions of cells (of the mesh dimension) and
// boundaries of nodes (of lower dimensions), unnamed ones named after their tag.
std::vector<PhysicalGroup> read_physical_groups(int dimension) {
  std::vector<PhysicalGroup> groups;
  gmsh::vectorpair physical;
  gmsh::model::getPhysicalGroups(physical, -1);
  for (const auto& [dim, tag] : physical) {
    if (dim > dimension) continue;
    PhysicalGroup group;
    group.dim = dim;
    gmsh::model::getPhysicalName(dim, tag, group.name);
    if (group.name.empty()) group.name = fmt::format("group_{}", tag);
    if (dim == dimension) {
      std::vector<int> entities;
      gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
      for (int entity : entities) {
        std::vector<int> entity_types;
        std::vector<std::vector<std::size_t>> tags, nodes;
        gmsh::model::mesh::getElements(entity_types, tags, nodes, dim, entity);
        for (const auto& some : tags)
          group.element_tags.insert(group.element_tags.end(), some.begin(), some.end());
      }
    } else {
      std::vector<double> coordinates;
      gmsh::model::mesh::getNodesForPhysicalGroup(dim, tag, group.node_tags, coordinates);
    }
    groups.push_back(std::move(group));
  }
  return groups;
}

/// The Gmsh tags of the nodes geompm keeps, ascending, and the node id of each.
struct NodeNumbering {
  std::vector<std::size_t> used;
  std::unordered_map<std::size_t, Index> index;
};

// Compact node ids to 0..n-1, in the order of the Gmsh tags, keeping only the nodes of the
// cells and of the boundaries (Gmsh also stores nodes of geometry points, for example).
NodeNumbering number_nodes(const std::vector<std::size_t>& cell_node_tags,
                           const std::vector<PhysicalGroup>& groups) {
  NodeNumbering numbering;
  std::vector<std::size_t>& used = numbering.used;
  used = cell_node_tags;
  for (const PhysicalGroup& group : groups)
    used.insert(used.end(), group.node_tags.begin(), group.node_tags.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::unordered_map<std::size_t, Index>& node_index = numbering.index;
  node_index.reserve(used.size());
  for (std::size_t n = 0; n < used.size(); ++n) node_index.emplace(used[n], static_cast<Index>(n));
  return numbering;
}

// The coordinates of the numbered nodes, each of which the file must define.
void read_node_coordinates(const SourceLocation& where, const NodeNumbering& numbering,
                           Mesh& mesh) {
  const std::vector<std::size_t>& used = numbering.used;
  std::vector<std::size_t> all_tags;
  std::vector<double> coordinates, parametric;
  gmsh::model::mesh::getNodes(all_tags, coordinates, parametric, -1, -1, false, false);
  mesh.nodes.assign(used.size(), Vec3::Constant(std::numeric_limits<double>::quiet_NaN()));
  std::vector<char> seen(used.size(), 0);
  for (std::size_t k = 0; k < all_tags.size(); ++k) {
    const auto it = numbering.index.find(all_tags[k]);
    if (it == numbering.index.end()) continue;
    mesh.nodes[it->second] =
        Vec3(coordinates[3 * k], coordinates[3 * k + 1], coordinates[3 * k + 2]);
    seen[it->second] = 1;
  }
  for (std::size_t n = 0; n < used.size(); ++n)
    if (!seen[n])
      throw InputError(where, fmt::format("an element refers to Gmsh node {}, which is not "
                                          "defined; "
                                          "expected every node in the $Nodes section",
                                          used[n]));
}

// A planar mesh written by Gmsh has z = 0 exactly; allow only round-off beyond that.
void flatten_planar_nodes(const SourceLocation& where, const std::vector<std::size_t>& used,
                          Mesh& mesh) {
  Vec3 lower = mesh.nodes[0], upper = mesh.nodes[0];
  for (const Vec3& x : mesh.nodes) lower = lower.cwiseMin(x), upper = upper.cwiseMax(x);
  const double round_off = 1e-12 * (upper - lower).norm();
  for (std::size_t n = 0; n < used.size(); ++n) {
    double& z = mesh.nodes[n][2];
    if (std::abs(z) > round_off)
      throw InputError(where, fmt::format("Gmsh node {} has z = {:g}; a 2D mesh must lie in the "
                                          "plane z = 0 (x horizontal, y up)",
                                          used[n], z));
    z = 0.0;
  }
}

// The physical groups as the mesh's cell groups (regions) and node groups (boundaries), in
// geompm's numbering, each sorted and without repeats.
void add_groups(const std::vector<PhysicalGroup>& groups, const std::vector<std::size_t>& cell_tags,
                const NodeNumbering& numbering, int dimension, Mesh& mesh) {
  std::unordered_map<std::size_t, Index> cell_index;
  cell_index.reserve(cell_tags.size());
  for (std::size_t c = 0; c < cell_tags.size(); ++c)
    cell_index.emplace(cell_tags[c], static_cast<Index>(c));
  for (const PhysicalGroup& group : groups) {
    if (group.dim == dimension) {
      std::vector<Index>& cells = mesh.cell_groups[group.name];
      for (std::size_t tag : group.element_tags)
        if (const auto it = cell_index.find(tag); it != cell_index.end())
          cells.push_back(it->second);
      std::sort(cells.begin(), cells.end());
      cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    } else {
      // Groups of several lower dimensions may share a name (a curve and its end points).
      std::vector<Index>& nodes = mesh.node_groups[group.name];
      for (std::size_t tag : group.node_tags) nodes.push_back(numbering.index.at(tag));
      std::sort(nodes.begin(), nodes.end());
      nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    }
  }
}

Mesh read_open_model(const std::string& path, int dimension) {
  const SourceLocation where{path, "", 0};
  const GmshCells cells = read_cells(where, dimension);
  Mesh mesh;
  mesh.cell_type = cells.blocks.front().type;
  const std::vector<PhysicalGroup> groups = read_physical_groups(dimension);
  const NodeNumbering numbering = number_nodes(cells.node_tags(), groups);
  read_node_coordinates(where, numbering, mesh);
  if (dimension == 2) flatten_planar_nodes(where, numbering.used, mesh);
  std::vector<Index> cell;
  for (const GmshCells::Block& block : cells.blocks) {
    const std::size_t per_cell = static_cast<std::size_t>(nodes_per_cell(block.type));
    for (std::size_t first = 0; first < block.node_tags.size(); first += per_cell) {
      cell.clear();
      for (std::size_t a = 0; a < per_cell; ++a)
        cell.push_back(numbering.index.at(block.node_tags[first + a]));
      mesh.add_cell(block.type, cell);
    }
  }
  add_groups(groups, cells.tags(), numbering, dimension, mesh);
  if (mesh.mixed()) check_conforming_faces(mesh, path);
  return mesh;
}

Mesh read_file_unvalidated(const SourceLocation& where, const std::string& path, int dimension) {
  GmshSession session;
  try {
    gmsh::open(path);
  } catch (...) {
    throw InputError(where, "cannot be read as a Gmsh mesh (" + current_exception_message() +
                                "); expected a .msh file in format 2 or 4");
  }
  try {
    return read_open_model(path, dimension);
  } catch (const InputError&) {
    throw;
  } catch (...) {
    throw InputError(where, "cannot be read as a Gmsh mesh (" + current_exception_message() + ")");
  }
}

void put_mesh(ByteWriter& writer, const Mesh& mesh) {
  writer.put(mesh.cell_type);
  writer.put(mesh.nodes);
  writer.put(mesh.connectivity);
  writer.put(mesh.cell_types);
  writer.put(mesh.cell_offsets);
  writer.put(mesh.cell_groups);
  writer.put(mesh.node_groups);
}

Mesh get_mesh(ByteReader& reader) {
  Mesh mesh;
  reader.get(mesh.cell_type);
  reader.get(mesh.nodes);
  reader.get(mesh.connectivity);
  reader.get(mesh.cell_types);
  reader.get(mesh.cell_offsets);
  reader.get(mesh.cell_groups);
  reader.get(mesh.node_groups);
  reader.expect_end();
  return mesh;
}

}  // namespace

Mesh mesh_from_gmsh_model(const std::string& what, int dimension) {
  Mesh mesh = read_open_model(what, dimension);
  validate_mesh(mesh, what);
  return mesh;
}

Mesh read_gmsh_mesh(const std::string& path, int dimension) {
  const SourceLocation where{path, "", 0};
  if (dimension != 2 && dimension != 3)
    throw InputError(
        where, fmt::format("cannot be read as a {}D mesh; expected dimension 2 or 3", dimension));
  // Gmsh would silently open an empty model for a missing file, so look first.
  std::error_code error;
  if (!std::filesystem::exists(path, error))
    throw InputError(where, "file not found; expected a Gmsh mesh file (.msh)");
  if (!std::filesystem::is_regular_file(path, error))
    throw InputError(where, "is not a regular file; expected a Gmsh mesh file (.msh)");

  // Gmsh's reader can crash on a damaged file (found by fuzzing: an MSH4 $Nodes section whose
  // counts do not match its blocks), so it reads in a child process (core/isolated_call.hpp).
  const std::string bytes = call_isolated(path, [&] {
    ByteWriter writer;
    put_mesh(writer, read_file_unvalidated(where, path, dimension));
    return writer.take();
  });
  ByteReader reader(bytes, path);
  Mesh mesh = get_mesh(reader);
  try {
    validate_mesh(mesh, path);
  } catch (const InputError& error) {
    // validate_mesh counts from 0; say how that maps onto the file.
    throw InputError(std::string(error.what()) +
                     " (cells and nodes are counted from 0, in the order of the file)");
  }
  return mesh;
}

}  // namespace geompm

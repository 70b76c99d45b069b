#include "geompm/mesh/gmsh_generate.hpp"

#include <fmt/format.h>
#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "geompm/core/memory.hpp"
#include "geompm/mesh/gmsh_session.hpp"

namespace geompm {

namespace {

// Gmsh meshes whatever it is asked to, until the memory runs out: the cells are estimated first
// (about 2 triangles per h^2, 6 tetrahedra per h^3, the refinement box at its own size) and a
// mesh that Gmsh could not hold (some 500 bytes a cell at least) is refused with the estimate.
void check_size(const char* what, int dim, const Vec3& size, double h,
                const std::optional<RefineBox>& refine_box, double h_refined) {
  const double per_box = dim == 3 ? 6.0 : 2.0;
  double volume = 1.0, refined = refine_box ? 1.0 : 0.0;
  for (int i = 0; i < dim; ++i) {
    volume *= size[i];
    if (refine_box) refined *= std::max(0.0, refine_box->second[i] - refine_box->first[i]);
  }
  const double cells = per_box * (volume / std::pow(h, dim) +
                                  (refine_box ? refined / std::pow(h_refined, dim) : 0.0));
  constexpr double bytes_per_cell = 500;
  const double memory = physical_memory_bytes();
  if (cells > 2e9 || (memory > 0 && cells * bytes_per_cell > memory))
    throw std::invalid_argument(fmt::format(
        "{}: h = {:g}{} gives about {:.3g} cells, needing at least {:.3g} GB of memory; this "
        "machine has {:.3g} GB (and a mesh may have at most 2e9 cells): choose a larger cell size",
        what, h, refine_box ? fmt::format(" (h_refined = {:g})", h_refined) : "", cells,
        cells * bytes_per_cell / 1e9, memory / 1e9));
}

void check_arguments(const char* what, int dim, const Vec3& size, double h,
                     const std::optional<RefineBox>& refine_box, double h_refined) {
  for (int i = 0; i < dim; ++i)
    if (!(size[i] > 0.0) || !std::isfinite(size[i]))
      throw std::invalid_argument(
          fmt::format("{}: size[{}] = {}; expected a positive size", what, i, size[i]));
  if (!(h > 0.0) || !std::isfinite(h))
    throw std::invalid_argument(fmt::format("{}: h = {}; expected a positive cell size", what, h));
  if (refine_box && (!(h_refined > 0.0) || !std::isfinite(h_refined)))
    throw std::invalid_argument(
        fmt::format("{}: h_refined = {}; expected a positive cell size inside the refinement box",
                    what, h_refined));
  check_size(what, dim, size, h, refine_box, h_refined);
}

void add_named_group(int dim, const std::vector<int>& entities, const std::string& name) {
  const int tag = gmsh::model::addPhysicalGroup(dim, entities);
  gmsh::model::setPhysicalName(dim, tag, name);
}

/// Cells of size h_refined inside the box, h outside, through a Gmsh "Box" background field.
void add_refinement(const RefineBox& box, double h, double h_refined) {
  const int field = gmsh::model::mesh::field::add("Box");
  namespace field_api = gmsh::model::mesh::field;
  field_api::setNumber(field, "VIn", h_refined);
  field_api::setNumber(field, "VOut", h);
  field_api::setNumber(field, "XMin", box.first[0]);
  field_api::setNumber(field, "XMax", box.second[0]);
  field_api::setNumber(field, "YMin", box.first[1]);
  field_api::setNumber(field, "YMax", box.second[1]);
  field_api::setNumber(field, "ZMin", box.first[2]);
  field_api::setNumber(field, "ZMax", box.second[2]);
  field_api::setNumber(field, "Thickness", h);  // a band of graded size instead of a jump
  field_api::setAsBackgroundMesh(field);
}

/// Every element of dimension `dim` must be of `gmsh_type`, else the generation failed.
void check_element_types(int dim, int gmsh_type, const char* what) {
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> tags, nodes;
  gmsh::model::mesh::getElements(types, tags, nodes, dim, -1);
  if (types.size() != 1 || types[0] != gmsh_type)
    throw std::runtime_error(
        fmt::format("{}: Gmsh produced {} element types of dimension {}; "
                    "expected only Gmsh type {}",
                    what, types.size(), dim, gmsh_type));
}

void write_msh41(const std::filesystem::path& file) {
  gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
  gmsh::option::setNumber("Mesh.Binary", 0);
  gmsh::option::setNumber("Mesh.SaveAll", 0);  // only the physical groups, as read back
  gmsh::write(file.string());
}

}  // namespace

void write_gmsh_rectangle(const std::filesystem::path& file, const Vec3& origin, const Vec3& size,
                          double h, CellType type, std::optional<RefineBox> refine_box,
                          double h_refined) {
  constexpr const char* what = "write_gmsh_rectangle";
  check_arguments(what, 2, size, h, refine_box, h_refined);
  if (type != CellType::Tri3 && type != CellType::Tri6 && type != CellType::Quad4)
    throw std::invalid_argument(
        fmt::format("{}: cell type {}; expected tri3, tri6 or quad4", what, to_string(type)));
  GmshSession session;
  try {
    namespace geo = gmsh::model::geo;
    gmsh::model::add("rectangle");
    const double x0 = origin[0], y0 = origin[1], x1 = x0 + size[0], y1 = y0 + size[1];
    const int p1 = geo::addPoint(x0, y0, 0, h), p2 = geo::addPoint(x1, y0, 0, h),
              p3 = geo::addPoint(x1, y1, 0, h), p4 = geo::addPoint(x0, y1, 0, h);
    const int bottom = geo::addLine(p1, p2), right = geo::addLine(p2, p3),
              top = geo::addLine(p3, p4), left = geo::addLine(p4, p1);
    // Counter-clockwise loop: the surface normal is +z, so the cells are counter-clockwise.
    const int loop = geo::addCurveLoop({bottom, right, top, left});
    const int surface = geo::addPlaneSurface({loop});
    geo::synchronize();
    add_named_group(1, {left}, "left");
    add_named_group(1, {right}, "right");
    add_named_group(1, {bottom}, "bottom");
    add_named_group(1, {top}, "top");
    add_named_group(2, {surface}, "all");
    if (refine_box) add_refinement(*refine_box, h, h_refined);

    if (type == CellType::Quad4) {
      // Frontal-Delaunay triangles, then blossom recombination into quadrangles only (the
      // "full-quad" variant leaves no triangle). Gmsh's "Frontal-Delaunay for quads"
      // (Mesh.Algorithm 8) would give squarer cells but crashes in Gmsh 4.8 (Debian 12).
      gmsh::option::setNumber("Mesh.Algorithm", 6);
      gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 3);
      gmsh::option::setNumber("Mesh.RecombineAll", 1);
    }
    gmsh::model::mesh::generate(2);
    if (type == CellType::Tri6) gmsh::model::mesh::setOrder(2);
    check_element_types(2, type == CellType::Tri3 ? 2 : type == CellType::Tri6 ? 9 : 3, what);
    write_msh41(file);
  } catch (const std::runtime_error&) {
    throw;
  } catch (...) {
    throw std::runtime_error(fmt::format("{}: Gmsh failed to mesh or write {}: {}", what,
                                         file.string(), current_exception_message()));
  }
}

void write_gmsh_box(const std::filesystem::path& file, const Vec3& origin, const Vec3& size,
                    double h, CellType type, std::optional<RefineBox> refine_box,
                    double h_refined) {
  constexpr const char* what = "write_gmsh_box";
  check_arguments(what, 3, size, h, refine_box, h_refined);
  if (type != CellType::Tet4)
    throw std::invalid_argument(
        fmt::format("{}: cell type {}; expected tet4", what, to_string(type)));
  GmshSession session;
  try {
    namespace geo = gmsh::model::geo;
    gmsh::model::add("box");
    const double x0 = origin[0], y0 = origin[1], z0 = origin[2];
    const double x1 = x0 + size[0], y1 = y0 + size[1];
    const int p1 = geo::addPoint(x0, y0, z0, h), p2 = geo::addPoint(x1, y0, z0, h),
              p3 = geo::addPoint(x1, y1, z0, h), p4 = geo::addPoint(x0, y1, z0, h);
    const int loop = geo::addCurveLoop(
        {geo::addLine(p1, p2), geo::addLine(p2, p3), geo::addLine(p3, p4), geo::addLine(p4, p1)});
    const int base = geo::addPlaneSurface({loop});
    // A geometric (not layered) extrusion of the base: the volume is meshed unstructured.
    gmsh::vectorpair extruded;
    geo::extrude({{2, base}}, 0, 0, size[2], extruded);
    geo::synchronize();

    int volume = -1;
    std::vector<int> faces{base};
    for (const auto& [dim, tag] : extruded) {
      if (dim == 3) volume = tag;
      if (dim == 2) faces.push_back(tag);
    }
    if (volume < 0)
      throw std::runtime_error(fmt::format("{}: Gmsh extrusion made no volume", what));
    // Name each face by the plane it lies in, rather than trusting the extrusion's order.
    const double tolerance = 1e-9 * size.norm();
    std::vector<std::pair<const char*, std::vector<int>>> named = {
        {"left", {}}, {"right", {}}, {"front", {}}, {"back", {}}, {"bottom", {}}, {"top", {}}};
    for (int face : faces) {
      double lower[3], upper[3];
      gmsh::model::getBoundingBox(2, face, lower[0], lower[1], lower[2], upper[0], upper[1],
                                  upper[2]);
      for (int axis = 0; axis < 3; ++axis) {
        if (upper[axis] - lower[axis] > tolerance) continue;
        const bool at_max = std::abs(lower[axis] - (origin[axis] + size[axis])) <= tolerance;
        named[2 * axis + (at_max ? 1 : 0)].second.push_back(face);
      }
    }
    for (const auto& [name, tags] : named) {
      if (tags.size() != 1)
        throw std::runtime_error(
            fmt::format("{}: found {} faces for '{}'", what, tags.size(), name));
      add_named_group(2, tags, name);
    }
    add_named_group(3, {volume}, "all");
    if (refine_box) add_refinement(*refine_box, h, h_refined);

    gmsh::model::mesh::generate(3);
    check_element_types(3, 4, what);
    write_msh41(file);
  } catch (const std::runtime_error&) {
    throw;
  } catch (...) {
    throw std::runtime_error(fmt::format("{}: Gmsh failed to mesh or write {}: {}", what,
                                         file.string(), current_exception_message()));
  }
}

}  // namespace geompm

// Unstructured meshes of a rectangle (2D) or a box (3D) written by Gmsh, for tests and
// examples that need cells of irregular shape and size (the structured generator makes only
// regular grids). Files are Gmsh format 4.1 ASCII and are read back with read_gmsh_mesh.
//
// Physical groups: the curves (2D) or surfaces (3D) "left"/"right" (x min/max), in 2D
// "bottom"/"top" (y min/max), in 3D "front"/"back" (y min/max) and "bottom"/"top" (z min/max),
// the same names as a structured mesh; the surface (2D) or volume (3D) "all".
#pragma once

#include <filesystem>
#include <optional>
#include <utility>

#include "geompm/core/types.hpp"
#include "geompm/mesh/cell_type.hpp"

namespace geompm {

/// Refinement region: lower and upper corner of an axis-aligned box.
using RefineBox = std::pair<Vec3, Vec3>;

/// Meshes the rectangle [origin, origin + size] (x, y; z ignored) with cells of about size h,
/// of type tri3, tri6 (straight-sided) or quad4, and writes `file`. With `refine_box` the cells
/// inside the box have about size h_refined. Quad4 meshes are made by recombining a
/// triangulation (Gmsh's "blossom full-quad"), which always yields quadrangles only; this is
/// checked before writing. Throws std::invalid_argument on bad arguments, std::runtime_error
/// when Gmsh fails.
void write_gmsh_rectangle(const std::filesystem::path& file, const Vec3& origin, const Vec3& size,
                          double h, CellType type, std::optional<RefineBox> refine_box = {},
                          double h_refined = 0);

/// Meshes the box [origin, origin + size] with tetrahedra (tet4, the only type accepted) of
/// about size h, refined to h_refined inside `refine_box`, and writes `file`.
void write_gmsh_box(const std::filesystem::path& file, const Vec3& origin, const Vec3& size,
                    double h, CellType type = CellType::Tet4,
                    std::optional<RefineBox> refine_box = {}, double h_refined = 0);

}  // namespace geompm

// Import of Gmsh .msh files (format 4, ASCII or binary; through the Gmsh API). Physical groups of
// the mesh's dimension become regions (cell groups); lower-dimensional physical groups become
// boundaries (node groups). All cells of the mesh's dimension must be of one type.
#pragma once

#include <string>

#include "geompm/mesh/mesh.hpp"

namespace geompm {

/// Reads `path`. `dimension` is 2 or 3: cells of that dimension are the mesh; in 2D the z
/// coordinate must be 0. Throws InputError naming the file and what is wrong (missing file, not
/// a mesh, mixed cell types, unsupported cell type, no cells of that dimension).
Mesh read_gmsh_mesh(const std::string& path, int dimension);

}  // namespace geompm

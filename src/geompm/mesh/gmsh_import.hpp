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

/// The cells of the model open in the caller's GmshSession (one just meshed through the API, as
/// the built-in structure shapes are), read and checked as read_gmsh_mesh reads a file; `what`
/// names it in errors.
Mesh mesh_from_gmsh_model(const std::string& what, int dimension);

}  // namespace geompm

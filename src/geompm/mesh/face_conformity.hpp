// Conformity of a mixed 3D mesh: a quadrangular face (of a hex8 or a pyramid5's base) must meet
// another quadrangle, not two triangles of tetrahedra, across which the bilinear and the linear
// traces differ (the displacement field would open a gap). Gmsh puts pyramids there.
#pragma once

#include <string>

#include "geompm/mesh/mesh.hpp"

namespace geompm {

/// Throws InputError (naming `source`, the cells and the face's nodes) if a quadrangular face of
/// a 3D mesh is held by one cell only while triangular faces held by one cell only lie on it
/// (three of its four corners): hexahedra or pyramids against tetrahedra. A 2D mesh passes.
void check_conforming_faces(const Mesh& mesh, const std::string& source);

}  // namespace geompm

// The faces of each cell type by their corner nodes (local numbering of mesh/element.hpp), for
// code that walks a cell's boundary: boundary nodes, conformity, mesh quality, surfaces.
#pragma once

#include <vector>

#include "geompm/mesh/cell_type.hpp"

namespace geompm {

/// A 3D cell's faces (a 2D cell's edges), each by its corners counter-clockwise seen from
/// outside the cell (a 2D edge in the cell's counter-clockwise order). Tri6's mid-side nodes are
/// not corners.
const std::vector<std::vector<int>>& cell_corner_faces(CellType type);

}  // namespace geompm

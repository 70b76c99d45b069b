#include "geompm/mesh/cell_faces.hpp"

namespace geompm {

const std::vector<std::vector<int>>& cell_corner_faces(CellType type) {
  using Faces = std::vector<std::vector<int>>;
  static const Faces triangle = {{0, 1}, {1, 2}, {2, 0}};
  static const Faces quadrangle = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  static const Faces tetrahedron = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  static const Faces hexahedron = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                   {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  // The quadrangular base, then the four triangles about the apex.
  static const Faces pyramid = {{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  switch (type) {
    case CellType::Tri3:
    case CellType::Tri6:
      return triangle;
    case CellType::Quad4:
      return quadrangle;
    case CellType::Tet4:
      return tetrahedron;
    case CellType::Pyramid5:
      return pyramid;
    case CellType::Hex8:
      break;
  }
  return hexahedron;
}

}  // namespace geompm

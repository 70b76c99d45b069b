#include "geompm/mesh/cell_type.hpp"

namespace geompm {

int cell_dimension(CellType t) { return (t == CellType::Tet4 || t == CellType::Hex8) ? 3 : 2; }

int nodes_per_cell(CellType t) {
  switch (t) {
    case CellType::Tri3:
      return 3;
    case CellType::Tri6:
      return 6;
    case CellType::Quad4:
      return 4;
    case CellType::Tet4:
      return 4;
    case CellType::Hex8:
      return 8;
  }
  return 0;
}

const char* to_string(CellType t) {
  switch (t) {
    case CellType::Tri3:
      return "tri3";
    case CellType::Tri6:
      return "tri6";
    case CellType::Quad4:
      return "quad4";
    case CellType::Tet4:
      return "tet4";
    case CellType::Hex8:
      return "hex8";
  }
  return "?";
}

std::optional<CellType> parse_cell_type(const std::string& name) {
  for (CellType t :
       {CellType::Tri3, CellType::Tri6, CellType::Quad4, CellType::Tet4, CellType::Hex8})
    if (name == to_string(t)) return t;
  return std::nullopt;
}

}  // namespace geompm

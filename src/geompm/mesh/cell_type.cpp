#include "geompm/mesh/cell_type.hpp"

namespace geompm {

int cell_dimension(CellType t) {
  return (t == CellType::Tet4 || t == CellType::Hex8 || t == CellType::Pyramid5) ? 3 : 2;
}

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
    case CellType::Pyramid5:
      return 5;
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
    case CellType::Pyramid5:
      return "pyramid5";
  }
  return "?";
}

std::optional<CellType> parse_cell_type(const std::string& name) {
  for (CellType t : all_cell_types)
    if (name == to_string(t)) return t;
  return std::nullopt;
}

}  // namespace geompm

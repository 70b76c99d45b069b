// The cell (element) types of a background mesh and their compile-time traits.
#pragma once

#include <optional>
#include <string>

namespace geompm {

enum class CellType { Tri3, Tri6, Quad4, Tet4, Hex8 };

int cell_dimension(CellType t);
int nodes_per_cell(CellType t);
const char* to_string(CellType t);
/// "tri3", "tri6", "quad4", "tet4", "hex8" (lower case); nullopt for anything else.
std::optional<CellType> parse_cell_type(const std::string& name);

}  // namespace geompm

// The cell (element) types of a background mesh and their compile-time traits.
#pragma once

#include <array>
#include <optional>
#include <string>

namespace geompm {

enum class CellType { Tri3, Tri6, Quad4, Tet4, Hex8, Pyramid5 };

/// Every cell type, in CellType order.
inline constexpr std::array<CellType, 6> all_cell_types = {CellType::Tri3,  CellType::Tri6,
                                                           CellType::Quad4, CellType::Tet4,
                                                           CellType::Hex8,  CellType::Pyramid5};

int cell_dimension(CellType t);
int nodes_per_cell(CellType t);
const char* to_string(CellType t);
/// "tri3", "tri6", "quad4", "tet4", "hex8", "pyramid5" (lower case); nullopt for anything else.
std::optional<CellType> parse_cell_type(const std::string& name);

}  // namespace geompm

#include "geompm/mesh/mesh.hpp"

#include <algorithm>

namespace geompm {

int Mesh::nodes_per_cell() const {
  if (!mixed()) return geompm::nodes_per_cell(cell_type);
  int most = 0;
  for (CellType t : types_present()) most = std::max(most, geompm::nodes_per_cell(t));
  return most;
}

std::vector<CellType> Mesh::types_present() const {
  if (!mixed()) return {cell_type};
  std::vector<CellType> types;
  for (CellType t : all_cell_types)
    if (std::find(cell_types.begin(), cell_types.end(), t) != cell_types.end()) types.push_back(t);
  return types;
}

void Mesh::add_cell(CellType type, std::span<const Index> cell) {
  const Index before = connectivity.empty() ? 0 : num_cells();
  if (before == 0) cell_type = type;
  if (!mixed() && type != cell_type) {
    // Becomes mixed: the cells so far are all of cell_type.
    cell_types.assign(before, cell_type);
    cell_offsets.resize(before + 1);
    for (Index c = 0; c <= before; ++c) cell_offsets[c] = c * geompm::nodes_per_cell(cell_type);
  }
  connectivity.insert(connectivity.end(), cell.begin(), cell.end());
  if (mixed()) {
    cell_types.push_back(type);
    cell_offsets.push_back(static_cast<Index>(connectivity.size()));
  }
}

void Mesh::compact() {
  if (!mixed()) return;
  if (std::all_of(cell_types.begin(), cell_types.end(),
                  [&](CellType t) { return t == cell_types.front(); })) {
    cell_type = cell_types.front();
    cell_types.clear();
    cell_offsets.clear();
  }
}

std::string cell_type_names(const Mesh& mesh) {
  std::string names;
  for (CellType t : mesh.types_present())
    names += (names.empty() ? "" : " + ") + std::string(to_string(t));
  return names;
}

}  // namespace geompm

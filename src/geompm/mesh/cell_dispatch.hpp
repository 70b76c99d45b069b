// Loops over cells whose bodies are templated on the cell type (Element<T>, compile-time sizes):
// a uniform mesh dispatches once per loop, a mixed one (mesh.hpp) once per cell.
#pragma once

#include "geompm/mesh/cell_geometry.hpp"
#include "geompm/mesh/element.hpp"
#include "geompm/mesh/mesh.hpp"

namespace geompm {

/// body(Element<T>{}, k) for k in [0, count), T the type of mesh cell cell_of(k); the items on
/// all threads when `parallel` (dynamic schedule: cells differ in work).
template <class CellOf, class Body>
void for_each_cell_typed(const Mesh& mesh, Index count, CellOf&& cell_of, Body&& body,
                         bool parallel = false) {
  if (!mesh.mixed()) {
    dispatch_cell_type(mesh.cell_type, [&](auto element) {
#pragma omp parallel for schedule(dynamic, 16) if (parallel)
      for (Index k = 0; k < count; ++k) body(element, k);
    });
    return;
  }
#pragma omp parallel for schedule(dynamic, 16) if (parallel)
  for (Index k = 0; k < count; ++k)
    dispatch_cell_type(mesh.type_of(cell_of(k)), [&](auto element) { body(element, k); });
}

/// body(Element<T>{}, c) for every cell c of the mesh, serially.
template <class Body>
void for_each_mesh_cell_typed(const Mesh& mesh, Body&& body) {
  for_each_cell_typed(
      mesh, mesh.num_cells(), [](Index c) { return c; }, body);
}

}  // namespace geompm

// The kind of each cell of the background mesh (seed §3.4, docs/theory.md §19), from the model
// file's `regions`: MPM unless a region says FEM or buffer.
#pragma once

#include <memory>
#include <vector>

#include "geompm/mesh/cell_kind.hpp"
#include "geompm/mesh/mesh.hpp"
#include "geompm/spec/model_spec.hpp"
#include "geompm/structures/structure.hpp"

namespace geompm {

/// Per cell of `mesh`, its kind; empty when every cell is MPM (no region asks otherwise). A cell
/// is in a region if the region's cell group holds it, or else if the region holds its centroid,
/// and, for a region given by its distance from a structure (`structures`, in the order of
/// spec.structures, as built), if its centroid lies within (beyond) that distance. Throws
/// InputError at a region's source for a group or structure the model lacks, for a region that
/// holds no cell, and for a cell two regions of different kinds hold.
std::vector<CellKind> classify_cells(const spec::Model& spec, const Mesh& mesh,
                                     const std::vector<std::unique_ptr<Structure>>& structures);

/// The centroid of cell c (the mean of its corner nodes' positions).
Vec3 cell_centroid(const Mesh& mesh, Index c);

}  // namespace geompm

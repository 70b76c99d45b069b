// The bodies' material points, seeded in two passes so that a process of a distributed run
// creates only the points of its own cells (docs/architecture.md, "Distributed runs"), with the
// ids and values the serial run gives them. The census goes through every cell of every body and
// counts the seeding positions each keeps, checking the bodies on the way (a body that overlaps
// another, a point in a tri6 cell, a body with no point), without creating a point (a serial run
// creates them in the same pass, having nothing to cut); the cells are
// cut among the processes by those counts (mesh/partition.hpp), and each process then seeds the
// cells it owns, counting the ids on through the cells it does not in the serial order: body by
// body, cell by cell, seeding position by position (points/seeding.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include "geompm/analysis/model.hpp"

namespace geompm {

/// How many material points seeding puts in each mesh cell, per body.
struct SeedCensus {
  std::vector<std::vector<std::uint8_t>> per_cell;  // [body][cell]; at most 64 a cell
  /// The points in each cell over all bodies.
  std::vector<double> points_in_cell() const;
};

/// Counts the seeding positions each body keeps in each cell (those in its region, outside the
/// structures, in MPM cells), and sets model.seeds_inside_structures. Throws InputError for a
/// points_per_cell the cell type does not take, a point in a tri6 cell, bodies that overlap and a
/// body with no point (and no FEM cell). The same on every process. With `add_points` (a serial
/// run, which needs no cut) it also adds every point as seed_own_cells would, in the one pass.
SeedCensus count_body_points(Model& model, bool add_points = false);

/// Adds the material points of the cells `cell_part` gives to `rank` (every cell when it is
/// empty), with the serial run's ids: their material by layer, point-dependent state and initial
/// velocity. Throws InputError where a material cannot initialise a point. Makes no collective
/// call.
void seed_own_cells(const SeedCensus& census, const std::vector<int>& cell_part, int rank,
                    Model& model);

}  // namespace geompm

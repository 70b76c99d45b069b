// Material points between the processes of a distributed run (docs/architecture.md,
// "Distributed runs"): a point belongs to the process that owns its cell. After the points are
// convected, those that crossed into another process's cell are sent to it (one all-to-all
// exchange of whole points, their state included). A checkpoint passes them to process 0 a slice
// at a time (points/streamed_points.hpp); gather_points, which holds them all there, is for tests.
#pragma once

#include <vector>

#include "geompm/core/communicator.hpp"
#include "geompm/points/material_points.hpp"

namespace geompm {

/// Keeps only the points whose cell `cell_part` gives to process `rank` (the others are some
/// other process's), in their order.
void keep_own_points(MaterialPoints& points, const std::vector<int>& cell_part, int rank);

/// Sends every point whose cell belongs to another process to that process, and appends the
/// points the others send here. Collective. Returns the points sent away.
Index migrate_points(MaterialPoints& points, const std::vector<int>& cell_part,
                     const Communicator& communicator);

/// Every process's points, ordered by id, on process 0; an empty store elsewhere. Collective.
MaterialPoints gather_points(const MaterialPoints& points, const Communicator& communicator);

}  // namespace geompm

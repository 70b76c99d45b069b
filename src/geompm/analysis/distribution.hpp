// What a distributed run (mpirun -np N geompm run) distributes, and what it refuses
// (docs/architecture.md, "Distributed runs"; docs/user-guide.md, "Running on several processes").
// The mesh and the grid are replicated on every process; the cells are cut into one part per
// process (mesh/partition.hpp) by the points they hold when the run starts (counted before they are
// seeded: analysis/body_seeding.hpp) or resumes, and each process holds the points of its cells
// and works on the FEM region's cells it owns.
#pragma once

#include <vector>

#include "geompm/analysis/model.hpp"
#include "geompm/core/communicator.hpp"

namespace geompm {

/// Throws InputError naming the model file and every feature of the model that a distributed
/// run does not handle yet (the tangent check), so that none is ever run wrongly.
void check_distributable(const Model& model, int processes);

/// Per mesh cell, the process that owns it: the cells cut by the work in them, the material points
/// `points_in_cell` counts (of every process) and an FEM cell's Gauss points. The same on every
/// process given the same counts.
std::vector<int> partition_by_work(const Model& model, std::vector<double> points_in_cell,
                                   int processes);

/// partition_by_work for the points the model holds (every process must hold every point, as
/// read from a checkpoint).
std::vector<int> partition_by_points(const Model& model, int processes);

}  // namespace geompm

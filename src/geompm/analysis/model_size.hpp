// How big a model will be, estimated from its specification before anything is built: a
// generated mesh of 10^10 cells would otherwise be discovered by std::bad_alloc after minutes.
// The estimate is deliberately low (what the mesh, the points and one step's sparse system need
// at the least), so a model refused by it cannot fit, and a model that fits is never refused.
#pragma once

#include <cstdint>
#include <string>

#include "geompm/spec/model_spec.hpp"

namespace geompm {

struct ModelSize {
  double cells = 0, nodes = 0, points = 0;  // doubles: they may exceed any integer type
  double bytes = 0;                         // the least memory a run needs
};

/// The size of a generated mesh and of the points every body could hold (all cells filled);
/// zero cells for an imported mesh (the file bounds its size).
ModelSize estimate_model_size(const spec::Model& spec);

/// Throws InputError at the mesh's place in the model file if the model cannot be built: more
/// cells or nodes than an index can count, or an estimate above the physical memory. The
/// message gives the estimate.
void check_model_size(const spec::Model& spec);

}  // namespace geompm

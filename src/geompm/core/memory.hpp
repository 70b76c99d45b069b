// The machine's memory, for refusing a model (or a mesh to generate) that cannot fit before
// trying to allocate it.
#pragma once

namespace geompm {

/// The physical memory of this machine, in bytes (0 if unknown).
double physical_memory_bytes();

}  // namespace geompm

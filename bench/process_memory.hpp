// How much memory the process holds, for the memory-per-point figures of docs/performance.md.
//
// Two views, because neither alone answers "how much does a point cost": the heap in use
// (glibc mallinfo2, summed over all arenas, mmapped blocks included) measures exactly what each
// stage of a step keeps allocated, while the peak resident set (VmHWM, reset through
// /proc/self/clear_refs) also catches the temporaries a step allocates and frees again (sorting
// copies, UMFPACK's work space), which a before/after heap reading misses.
#pragma once

#include <cstddef>

namespace geompm::bench {

/// Bytes currently allocated through malloc (all arenas, mmapped blocks included).
std::size_t heap_in_use();

/// Current resident set size in bytes (VmRSS), 0 if /proc is not readable.
std::size_t resident_bytes();

/// Peak resident set size in bytes since the last reset_peak_resident() (VmHWM).
std::size_t peak_resident_bytes();

/// Resets the peak resident set to the current one; false if the kernel refused.
bool reset_peak_resident();

/// Returns freed heap to the system, so that the next RSS reading starts from what is in use.
void release_free_heap();

}  // namespace geompm::bench

// The "points" section of a checkpoint (MaterialPoints::save's bytes) made a slice at a time, so
// that no process holds a copy of every point (docs/checkpoint-format.md; issue 44). On one
// process: the store's arrays, a slice of points at a time, in the store's order (what save()
// writes; a serial run resumes bit for bit from it). In a distributed run: every process's points
// together, ordered by id (what save() writes of them gathered and sorted, as the serial run's
// store holds them when it is in id order): array by array, window by window of ids, each process
// sends process 0 the ids and values of its points in the window, and process 0 merges them by id
// and passes them on. Process 0 holds one window of one array at a time, of every process.
#pragma once

#include <cstdint>
#include <functional>
#include <string_view>
#include <vector>

#include "geompm/core/communicator.hpp"
#include "geompm/points/material_points.hpp"

namespace geompm {

/// Receives the bytes, in order, a piece at a time.
using ByteSink = std::function<void(std::string_view)>;

/// Ids a window holds: at most 4.5 MiB of values of the largest array (a Mat3) per window.
inline constexpr Index streamed_points_window = Index{1} << 16;

/// The bytes MaterialPoints::save writes for `count` points.
std::uint64_t saved_points_bytes(Index count);

/// Passes MaterialPoints::save's bytes to `sink` a piece at a time: on one process, of the points
/// `which` of `points` in that order; in a distributed run (collective), of the points `which` of
/// every process's `points` together, ordered by id, to process 0's `sink` (the others' is not
/// called). The ids must be unique over the processes and not negative. `sink` must not throw in
/// a distributed run (a process that left the collective steps would leave the others waiting).
void stream_saved_points(const MaterialPoints& points, const std::vector<Index>& which,
                         const Communicator& processes, const ByteSink& sink,
                         Index window = streamed_points_window);

/// stream_saved_points of every point of `points`.
void stream_saved_points(const MaterialPoints& points, const Communicator& processes,
                         const ByteSink& sink, Index window = streamed_points_window);

}  // namespace geompm

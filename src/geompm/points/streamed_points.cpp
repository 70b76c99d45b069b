#include "geompm/points/streamed_points.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

#include "geompm/core/byte_archive.hpp"

namespace geompm {

namespace {

void put_count(std::uint64_t count, const ByteSink& sink) {
  ByteWriter out;
  out.put(count);
  sink(out.bytes());
}

// One process: the arrays of the points `which`, in that order, a window of points at a time.
void stream_in_order(const MaterialPoints& points, const std::vector<Index>& which,
                     const ByteSink& sink, Index window) {
  const std::size_t arrays = MaterialPoints::saved_layout().value_bytes.size();
  const std::size_t slice = static_cast<std::size_t>(window);
  for (std::size_t k = 0; k < arrays; ++k) {
    put_count(which.size(), sink);
    for (std::size_t first = 0; first < which.size(); first += slice) {
      ByteWriter out;
      points.put_saved(k, which.data() + first, std::min(slice, which.size() - first), out);
      sink(out.bytes());
    }
  }
}

// Process 0: the values of one array of the points in ids lo .. lo + window - 1 of every process
// (`parts`: each a count, the ids, then the values), ordered by id.
std::string merge_window(const std::vector<std::string>& parts, std::int64_t lo, Index window,
                         std::size_t value_bytes) {
  struct Source {
    int part = -1;
    std::size_t at = 0;  // where its value starts in the part
  };
  std::vector<Source> by_id(static_cast<std::size_t>(window));
  std::size_t count = 0;
  for (std::size_t r = 0; r < parts.size(); ++r) {
    if (parts[r].empty()) continue;
    ByteReader in(parts[r], "points from another process");
    const auto n = in.get<std::uint64_t>();
    const std::size_t values = sizeof(std::uint64_t) + n * sizeof(Index);
    for (std::uint64_t i = 0; i < n; ++i) {
      const std::int64_t slot = in.get<Index>() - lo;
      if (slot < 0 || slot >= window || by_id[slot].part >= 0)
        throw std::logic_error(
            fmt::format("stream_saved_points: point id {} out of its window or "
                        "held by two processes",
                        slot + lo));
      by_id[slot] = {static_cast<int>(r), values + i * value_bytes};
    }
    count += n;
  }
  std::string merged;
  merged.reserve(count * value_bytes);
  for (const Source& s : by_id)
    if (s.part >= 0) merged.append(parts[s.part], s.at, value_bytes);
  return merged;
}

// Distributed: every process's points `which`, ordered by id, through process 0.
void stream_by_id(const MaterialPoints& points, std::vector<Index> which,
                  const Communicator& processes, const ByteSink& sink, Index window) {
  std::sort(which.begin(), which.end(),
            [&](Index a, Index b) { return points.id[a] < points.id[b]; });
  if (!which.empty() && points.id[which.front()] < 0)
    throw std::logic_error("stream_saved_points: a negative point id");
  const Index total = processes.sum(static_cast<Index>(which.size()));
  int last_id = which.empty() ? -1 : points.id[which.back()];
  processes.max(&last_id, 1);
  const MaterialPoints::SavedLayout layout = MaterialPoints::saved_layout();
  const bool writes = processes.rank() == 0;
  for (std::size_t k = 0; k < layout.value_bytes.size(); ++k) {
    if (writes) put_count(static_cast<std::uint64_t>(total), sink);
    std::size_t from = 0;
    for (std::int64_t lo = 0; lo <= last_id; lo += window) {
      std::size_t to = from;
      while (to < which.size() && points.id[which[to]] < lo + window) ++to;
      ByteWriter part;
      part.put(static_cast<std::uint64_t>(to - from));
      for (std::size_t i = from; i < to; ++i) part.put(points.id[which[i]]);
      points.put_saved(k, which.data() + from, to - from, part);
      from = to;
      const std::vector<std::string> parts = processes.gather(part.take());
      if (writes) sink(merge_window(parts, lo, window, layout.value_bytes[k]));
    }
  }
}

}  // namespace

std::uint64_t saved_points_bytes(Index count) {
  std::uint64_t bytes = 0;
  for (const std::size_t value_bytes : MaterialPoints::saved_layout().value_bytes)
    bytes += sizeof(std::uint64_t) + static_cast<std::uint64_t>(count) * value_bytes;
  return bytes;
}

void stream_saved_points(const MaterialPoints& points, const std::vector<Index>& which,
                         const Communicator& processes, const ByteSink& sink, Index window) {
  if (processes.distributed())
    stream_by_id(points, which, processes, sink, window);
  else
    stream_in_order(points, which, sink, window);
}

void stream_saved_points(const MaterialPoints& points, const Communicator& processes,
                         const ByteSink& sink, Index window) {
  std::vector<Index> all(static_cast<std::size_t>(points.size()));
  std::iota(all.begin(), all.end(), 0);
  stream_saved_points(points, all, processes, sink, window);
}

}  // namespace geompm

// The material points a checkpoint holds, read by each process of a distributed run for the cells
// it owns only (docs/architecture.md, "Distributed runs"). MaterialPoints::save writes the points
// array by array, each a count and that many values of a fixed size, so the reader steps from array
// to array in the file without reading them, reads the cells' array first (to cut the mesh by the
// points in each cell), then of every array only the values of the points it keeps, a slice at a
// time: no process holds every point, only a flag per point of which it keeps.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "geompm/points/material_points.hpp"

namespace geompm {

class SavedPoints {
 public:
  /// The points MaterialPoints::save wrote at bytes offset .. offset + length of `file`
  /// (`context` names them in messages). Throws InputError when the arrays do not fill those
  /// bytes or their lengths differ.
  SavedPoints(std::filesystem::path file, std::uint64_t offset, std::uint64_t length,
              std::string context);

  Index size() const { return size_; }
  /// The points in each of the mesh's `cells` cells; throws InputError for a point in no cell of
  /// it.
  std::vector<double> points_in_cell(Index cells) const;
  /// The points whose cell `cell_part` gives to `rank` (all of them when it is empty), in the
  /// file's order.
  MaterialPoints load(const std::vector<int>& cell_part, int rank) const;

 private:
  /// Calls fn(bytes, first) on the values of array `array`, a slice of points first, first + 1,
  /// ... at a time.
  template <class Fn>
  void for_each_slice(std::size_t array, Fn&& fn) const;

  std::filesystem::path file_;
  std::string context_;
  MaterialPoints::SavedLayout layout_;
  std::vector<std::uint64_t> values_at_;  // where each array's values start in the file
  Index size_ = 0;
};

}  // namespace geompm

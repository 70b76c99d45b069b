#include "geompm/points/saved_points.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>

#include "geompm/core/byte_archive.hpp"
#include "geompm/core/error.hpp"

namespace geompm {

namespace {

// Points a slice holds: 64 Ki values, at most 4.5 MiB of the largest (the internal variables).
constexpr std::uint64_t slice_points = std::uint64_t{1} << 16;

std::ifstream open_at(const std::filesystem::path& file, std::uint64_t at,
                      const std::string& context) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot open the checkpoint", context));
  in.seekg(static_cast<std::streamoff>(at));
  return in;
}

}  // namespace

SavedPoints::SavedPoints(std::filesystem::path file, std::uint64_t offset, std::uint64_t length,
                         std::string context)
    : file_(std::move(file)),
      context_(std::move(context)),
      layout_(MaterialPoints::saved_layout()) {
  std::ifstream in = open_at(file_, offset, context_);
  const std::uint64_t end = offset + length;
  std::uint64_t at = offset;
  for (std::size_t k = 0; k < layout_.value_bytes.size(); ++k) {
    std::uint64_t count = 0;
    if (end - at < sizeof count || !in.read(reinterpret_cast<char*>(&count), sizeof count))
      throw InputError(fmt::format("{}: ends too early (array {} of the points)", context_, k));
    if (k == 0) size_ = static_cast<Index>(count);
    if (count != static_cast<std::uint64_t>(size_))
      throw InputError(
          fmt::format("{}: {} points, but an array of {} values", context_, size_, count));
    at += sizeof count;
    values_at_.push_back(at);
    if (count > (end - at) / layout_.value_bytes[k])
      throw InputError(fmt::format("{}: ends too early (array {} of the points)", context_, k));
    at += count * layout_.value_bytes[k];
    in.seekg(static_cast<std::streamoff>(at));
  }
  if (at != end)
    throw InputError(
        fmt::format("{}: {} bytes left over after reading it (damaged, or written by "
                    "another layout of the same format version)",
                    context_, end - at));
}

template <class Fn>
void SavedPoints::for_each_slice(std::size_t array, Fn&& fn) const {
  std::ifstream in = open_at(file_, values_at_[array], context_);
  const std::uint64_t size = static_cast<std::uint64_t>(size_);
  const std::size_t value_bytes = layout_.value_bytes[array];
  std::string bytes;
  for (std::uint64_t first = 0; first < size; first += slice_points) {
    bytes.resize(std::min(slice_points, size - first) * value_bytes);
    if (!in.read(bytes.data(), static_cast<std::streamsize>(bytes.size())))
      throw InputError(fmt::format("{}: cannot read the points", context_));
    fn(std::string_view(bytes), static_cast<std::size_t>(first));
  }
}

std::vector<double> SavedPoints::points_in_cell(Index cells) const {
  std::vector<double> count(cells, 0.0);
  for_each_slice(layout_.cell_array, [&](std::string_view bytes, std::size_t) {
    ByteReader in(bytes, context_);
    while (in.remaining() > 0) {
      const auto c = in.get<Index>();
      if (c < 0 || c >= cells)
        throw InputError(
            fmt::format("{}: a point in cell {}, but the mesh has {} cells", context_, c, cells));
      count[c] += 1.0;
    }
  });
  return count;
}

MaterialPoints SavedPoints::load(const std::vector<int>& cell_part, int rank) const {
  std::vector<char> keep(static_cast<std::size_t>(size_), 1);
  if (!cell_part.empty())
    for_each_slice(layout_.cell_array, [&](std::string_view bytes, std::size_t first) {
      ByteReader in(bytes, context_);
      for (std::size_t i = first; in.remaining() > 0; ++i) {
        const auto c = in.get<Index>();
        keep[i] = c >= 0 && c < static_cast<Index>(cell_part.size()) && cell_part[c] == rank;
      }
    });
  MaterialPoints points;
  for (std::size_t k = 0; k < layout_.value_bytes.size(); ++k)
    for_each_slice(k, [&](std::string_view bytes, std::size_t first) {
      points.append_saved(k, bytes, keep, first);
    });
  return points;
}

}  // namespace geompm

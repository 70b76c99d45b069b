#include "geompm/core/byte_archive.hpp"

#include <fmt/format.h>

#include "geompm/core/error.hpp"

namespace geompm {

void ByteReader::expect_end() const {
  if (remaining() != 0)
    throw InputError(
        fmt::format("{}: {} bytes left over after reading it (damaged, or written by "
                    "another layout of the same format version)",
                    context_, remaining()));
}

std::size_t ByteReader::count(std::size_t element_bytes) {
  std::uint64_t n = 0;
  raw(&n, sizeof(n));
  // Checked before anything is allocated: a damaged count must not ask for terabytes.
  if (n > remaining() / element_bytes) fail_short(n * element_bytes);
  return static_cast<std::size_t>(n);
}

void ByteReader::fail_short(std::size_t needed) const {
  throw InputError(fmt::format("{}: ends too early (needs {} more bytes at byte {}, has {})",
                               context_, needed, at_, remaining()));
}

}  // namespace geompm

#include "geompm/core/fnv1a.hpp"

#include <fmt/format.h>

namespace geompm {

std::string fnv1a_hex(std::uint64_t hash) { return fmt::format("{:016x}", hash); }

// The published test vectors of FNV-1a 64.
static_assert(fnv1a_64("") == 0xcbf29ce484222325ull);
static_assert(fnv1a_64("a") == 0xaf63dc4c8601ec8cull);
static_assert(fnv1a_64("foobar") == 0x85944171f73967e8ull);

}  // namespace geompm

// FNV-1a, 64-bit (Fowler, Noll, Vo; http://www.isthe.com/chongo/tech/comp/fnv/): the hash of the
// model file's text that a checkpoint and summary.json record, and the checksum over a
// checkpoint's payload. Not cryptographic: it guards against a truncated or damaged file and a
// checkpoint resumed with another model, not against tampering. Every step (xor a byte, then
// multiply by an odd number modulo 2^64) is a bijection of the state, so changing any one byte
// always changes the hash.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace geompm {

inline constexpr std::uint64_t fnv1a_offset_basis = 0xcbf29ce484222325ull;
inline constexpr std::uint64_t fnv1a_prime = 0x100000001b3ull;

/// Continues the hash `h` over `bytes` (start with fnv1a_offset_basis).
constexpr std::uint64_t fnv1a_64(std::string_view bytes, std::uint64_t h = fnv1a_offset_basis) {
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= fnv1a_prime;
  }
  return h;
}

/// The hash as 16 lower-case hex digits, as summary.json and error messages show it.
std::string fnv1a_hex(std::uint64_t hash);

}  // namespace geompm

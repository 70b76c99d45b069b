#include "geompm/core/error.hpp"

namespace geompm {

std::string SourceLocation::describe() const {
  std::string out = file;
  // Appended piece by piece: GCC 12 warns (-Wrestrict, wrongly) about "literal" + string.
  if (line > 0) {
    out += ':';
    out += std::to_string(line);
  }
  if (!key_path.empty()) {
    if (!out.empty()) out += ": ";
    out += key_path;
  }
  return out;
}

InputError::InputError(const SourceLocation& where, const std::string& what)
    : std::runtime_error(where.describe() + ": " + what) {}

}  // namespace geompm

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

std::string component_place(const SourceLocation& where, int component) {
  static const char* names[3] = {"x", "y", "z"};
  return where.describe() + " (its " + (component >= 0 && component < 3 ? names[component] : "?") +
         " component)";
}

InputError::InputError(const SourceLocation& where, const std::string& what)
    : std::runtime_error(where.describe() + ": " + what) {}

}  // namespace geompm

#include "geompm/core/error.hpp"

namespace geompm {

std::string SourceLocation::describe() const {
  std::string out = file;
  if (line > 0) out += ":" + std::to_string(line);
  if (!key_path.empty()) out += (out.empty() ? "" : ": ") + key_path;
  return out;
}

InputError::InputError(const SourceLocation& where, const std::string& what)
    : std::runtime_error(where.describe() + ": " + what) {}

}  // namespace geompm

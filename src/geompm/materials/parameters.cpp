#include "geompm/materials/parameters.hpp"

#include <fmt/format.h>

#include <cmath>

#include "geompm/core/error.hpp"

namespace geompm {

ParameterReader::ParameterReader(const std::string& model, const ParameterMap& p,
                                 std::initializer_list<const char*> known)
    : model_(model), p_(p) {
  for (const auto& [key, value] : p) {
    bool found = false;
    std::string list;
    for (const char* k : known) {
      found = found || key == k;
      list += (list.empty() ? "" : ", ") + std::string(k);
    }
    if (!found)
      throw ParameterError(key, fmt::format("unknown parameter '{}' for material model '{}'; "
                                            "expected one of: {}",
                                            key, model, list));
    if (!std::isfinite(value))
      throw ParameterError(key, fmt::format("'{}' must be a finite number", key));
  }
}

double ParameterReader::required(const std::string& key) const {
  auto it = p_.find(key);
  if (it == p_.end())
    throw ParameterError(key,
                         fmt::format("material model '{}' needs the parameter '{}'", model_, key));
  return it->second;
}

double ParameterReader::optional(const std::string& key, double fallback) const {
  auto it = p_.find(key);
  return it == p_.end() ? fallback : it->second;
}

SurfaceTangent ParameterReader::surface_tangent() const {
  const double v = optional("surface_tangent", 0);
  if (v != 0 && v != 1)
    throw ParameterError(
        "surface_tangent",
        fmt::format("'surface_tangent' must be elastic (0) or plastic (1), got {}", v));
  return v == 1 ? SurfaceTangent::plastic : SurfaceTangent::elastic;
}

double ParameterReader::positive(const std::string& key, double v) {
  if (!(v > 0)) throw ParameterError(key, fmt::format("'{}' must be > 0, got {}", key, v));
  return v;
}

double ParameterReader::non_negative(const std::string& key, double v) {
  if (!(v >= 0)) throw ParameterError(key, fmt::format("'{}' must be >= 0, got {}", key, v));
  return v;
}

double ParameterReader::poisson_ratio(const std::string& key, double v) {
  if (!(v > -1.0 && v < 0.5))
    throw ParameterError(key, fmt::format("'{}' must lie in (-1, 0.5), got {}", key, v));
  return v;
}

}  // namespace geompm

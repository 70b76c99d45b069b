// A material's history variables at one point (equivalent plastic strain, a point's own s_u, ...):
// the material says how many it uses (Material::internal_variable_count). They belong to the
// material's room; the point store (points/material_points.hpp) keeps one set per point.
#pragma once

#include <array>

namespace geompm {

inline constexpr int max_internal_variables = 4;
using InternalVariables = std::array<double, max_internal_variables>;

}  // namespace geompm

// Standard MPM: a point sees the nodes of its cell through the cell's shape functions (seed eq.
// 9, docs/theory.md §7).
#pragma once

#include "geompm/interpolation/interpolation.hpp"

namespace geompm {

class StandardInterpolation final : public Interpolation {
 public:
  const char* name() const override { return "standard"; }
};

}  // namespace geompm

// DDMP: smoothed gradients over a wider stencil (Zhang, Ma & Giguere 2011; docs/theory.md §8).
#pragma once

#include "geompm/interpolation/interpolation.hpp"

namespace geompm {

class DualDomainInterpolation final : public Interpolation {
 public:
  const char* name() const override { return "ddmp"; }
  bool wide() const override { return true; }
  void after_activation(const MaterialPoints& points, const StencilInputs& in,
                        WideStencils& out) const override;
};

}  // namespace geompm

// Richardson extrapolation of a value computed on three meshes, each halving the cell size of
// the one before: the observed order of convergence and the extrapolated value at h -> 0.
#pragma once

#include <cmath>

namespace geompm::testing {

struct Extrapolation {
  double order;  // p in value(h) = value(0) + C h^p
  double value;  // value(0)
};

/// From the values on h, h/2, h/4 (coarse first).
inline Extrapolation richardson(double coarse, double mid, double fine) {
  const double order = std::log2((coarse - mid) / (mid - fine));
  return {order, fine - (mid - fine) / (std::pow(2.0, order) - 1.0)};
}

}  // namespace geompm::testing

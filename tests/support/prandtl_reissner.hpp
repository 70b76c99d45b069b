// The bearing capacity factor of a strip on weightless c-phi soil, for the footing tests.
#pragma once

#include <cmath>
#include <numbers>

namespace geompm::testing {

/// Prandtl (1921), Reissner (1924): N_c = (N_q - 1) cot(phi), N_q = e^(pi tan phi) tan^2(45 +
/// phi/2), exact for associated flow; 14.83 for phi = 20 deg, 30.14 for 30 deg.
inline double prandtl_reissner_nc(double phi_degrees) {
  const double phi = phi_degrees * std::numbers::pi / 180.0;
  const double Nq = std::exp(std::numbers::pi * std::tan(phi)) *
                    std::pow(std::tan(std::numbers::pi / 4 + phi / 2), 2);
  return (Nq - 1.0) / std::tan(phi);
}

}  // namespace geompm::testing

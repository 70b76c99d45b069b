// Closed form of the elastic column under self-weight (docs/references.md §2; Coombs & Augarde
// 2020, "AMPLE", Adv. Eng. Softw. 139, §5.1): 1D confined compression, nu = 0.
//   Cauchy stress at initial height Y: sigma(Y) = -rho0 g (l0 - Y) (the weight above is conserved)
//   Hencky law: E ln(lambda) / lambda = sigma, i.e. lambda = exp(-W(s)), s = rho0 g (l0 - Y) / E
//   displacement u(Y) = int_0^Y (lambda(eta) - 1) d eta.
#pragma once

#include <cmath>

namespace geompm::testing {

struct Column {
  double height = 50.0, density = 0.08, gravity = 10.0, youngs_modulus = 1000.0;

  double stress(double Y) const { return -density * gravity * (height - Y); }

  /// Vertical stretch of the Hencky law at initial height Y (Newton on ln(l) + s l = 0).
  double stretch(double Y) const {
    const double s = density * gravity * (height - Y) / youngs_modulus;
    double l = 1.0;
    for (int k = 0; k < 50; ++k) {
      const double f = std::log(l) + s * l, df = 1.0 / l + s;
      l -= f / df;
    }
    return l;
  }

  /// u(Y) by composite Simpson integration of (lambda - 1).
  double displacement(double Y) const {
    const int n = 2000;
    const double h = Y / n;
    double sum = (stretch(0) - 1) + (stretch(Y) - 1);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4 : 2) * (stretch(i * h) - 1);
    return sum * h / 3.0;
  }
};

}  // namespace geompm::testing

// Bilinear quadrilateral on [-1,1]^2, nodes counter-clockwise from (-1,-1).
#include <cmath>

#include "geompm/mesh/element.hpp"

namespace geompm {

using Quad4 = Element<CellType::Quad4>;

namespace {
constexpr double corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
}

Quad4::Values Quad4::shape(const Local& xi) {
  Values n;
  for (int a = 0; a < 4; ++a)
    n[a] = 0.25 * (1.0 + corner[a][0] * xi[0]) * (1.0 + corner[a][1] * xi[1]);
  return n;
}

Quad4::Gradients Quad4::shape_gradients(const Local& xi) {
  Gradients g;
  for (int a = 0; a < 4; ++a) {
    g(a, 0) = 0.25 * corner[a][0] * (1.0 + corner[a][1] * xi[1]);
    g(a, 1) = 0.25 * corner[a][1] * (1.0 + corner[a][0] * xi[0]);
  }
  return g;
}

bool Quad4::contains(const Local& xi, double tol) {
  return std::abs(xi[0]) <= 1.0 + tol && std::abs(xi[1]) <= 1.0 + tol;
}

Quad4::Local Quad4::centroid() { return Local::Zero(); }

Quad4::Local Quad4::node(int a) { return Local(corner[a][0], corner[a][1]); }

// 2x2 Gauss: exact to degree 3 in each direction, so for the biquadratic mass matrix.
int Quad4::quadrature_size() { return 4; }

Quad4::Local Quad4::quadrature_point(int q) {
  const double g = 1.0 / std::sqrt(3.0);
  return Local(corner[q][0] * g, corner[q][1] * g);
}

double Quad4::quadrature_weight(int /*q*/) { return 1.0; }

}  // namespace geompm

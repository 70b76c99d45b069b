// Trilinear hexahedron on [-1,1]^3: bottom face counter-clockwise from (-1,-1,-1), then the top.
#include <cmath>

#include "geompm/mesh/element.hpp"

namespace geompm {

using Hex8 = Element<CellType::Hex8>;

namespace {
constexpr double corner[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                 {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
}

Hex8::Values Hex8::shape(const Local& xi) {
  Values n;
  for (int a = 0; a < 8; ++a)
    n[a] = 0.125 * (1.0 + corner[a][0] * xi[0]) * (1.0 + corner[a][1] * xi[1]) *
           (1.0 + corner[a][2] * xi[2]);
  return n;
}

Hex8::Gradients Hex8::shape_gradients(const Local& xi) {
  Gradients g;
  for (int a = 0; a < 8; ++a) {
    const double fx = 1.0 + corner[a][0] * xi[0];
    const double fy = 1.0 + corner[a][1] * xi[1];
    const double fz = 1.0 + corner[a][2] * xi[2];
    g(a, 0) = 0.125 * corner[a][0] * fy * fz;
    g(a, 1) = 0.125 * corner[a][1] * fx * fz;
    g(a, 2) = 0.125 * corner[a][2] * fx * fy;
  }
  return g;
}

bool Hex8::contains(const Local& xi, double tol) {
  return std::abs(xi[0]) <= 1.0 + tol && std::abs(xi[1]) <= 1.0 + tol &&
         std::abs(xi[2]) <= 1.0 + tol;
}

Hex8::Local Hex8::centroid() { return Local::Zero(); }

Hex8::Local Hex8::node(int a) { return Local(corner[a][0], corner[a][1], corner[a][2]); }

// 2x2x2 Gauss: exact to degree 3 in each direction, so for the triquadratic mass matrix.
int Hex8::quadrature_size() { return 8; }

Hex8::Local Hex8::quadrature_point(int q) {
  const double g = 1.0 / std::sqrt(3.0);
  return Local(corner[q][0] * g, corner[q][1] * g, corner[q][2] * g);
}

double Hex8::quadrature_weight(int /*q*/) { return 1.0; }

}  // namespace geompm

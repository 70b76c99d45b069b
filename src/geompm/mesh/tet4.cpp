// Linear tetrahedron: N = barycentric coordinates (1 - xi - eta - zeta, xi, eta, zeta).
#include "geompm/mesh/element.hpp"

namespace geompm {

using Tet4 = Element<CellType::Tet4>;

Tet4::Values Tet4::shape(const Local& xi) {
  return Values(1.0 - xi[0] - xi[1] - xi[2], xi[0], xi[1], xi[2]);
}

Tet4::Gradients Tet4::shape_gradients(const Local& /*xi*/) {
  Gradients g;
  g << -1.0, -1.0, -1.0,  //
      1.0, 0.0, 0.0,      //
      0.0, 1.0, 0.0,      //
      0.0, 0.0, 1.0;
  return g;
}

bool Tet4::contains(const Local& xi, double tol) {
  return xi[0] >= -tol && xi[1] >= -tol && xi[2] >= -tol && xi.sum() <= 1.0 + tol;
}

Tet4::Local Tet4::centroid() { return Local(0.25, 0.25, 0.25); }

Tet4::Local Tet4::node(int a) {
  static const double coordinates[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  return Local(coordinates[a][0], coordinates[a][1], coordinates[a][2]);
}

// Four-point rule of degree 2, exact for the (quadratic) mass matrix.
int Tet4::quadrature_size() { return 4; }

Tet4::Local Tet4::quadrature_point(int q) {
  constexpr double a = 0.58541019662496845446;  // (5 + 3 sqrt 5) / 20
  constexpr double b = 0.13819660112501051518;  // (5 - sqrt 5) / 20
  static const double points[4][3] = {{b, b, b}, {a, b, b}, {b, a, b}, {b, b, a}};
  return Local(points[q][0], points[q][1], points[q][2]);
}

double Tet4::quadrature_weight(int /*q*/) { return 1.0 / 24.0; }

}  // namespace geompm

// Linear triangle: N = barycentric coordinates (1 - xi - eta, xi, eta).
#include "geompm/mesh/element.hpp"

namespace geompm {

using Tri3 = Element<CellType::Tri3>;

Tri3::Values Tri3::shape(const Local& xi) { return Values(1.0 - xi[0] - xi[1], xi[0], xi[1]); }

Tri3::Gradients Tri3::shape_gradients(const Local& /*xi*/) {
  Gradients g;
  g << -1.0, -1.0,  //
      1.0, 0.0,     //
      0.0, 1.0;
  return g;
}

bool Tri3::contains(const Local& xi, double tol) {
  return xi[0] >= -tol && xi[1] >= -tol && xi[0] + xi[1] <= 1.0 + tol;
}

Tri3::Local Tri3::centroid() { return Local(1.0 / 3.0, 1.0 / 3.0); }

Tri3::Local Tri3::node(int a) {
  static const double coordinates[3][2] = {{0, 0}, {1, 0}, {0, 1}};
  return Local(coordinates[a][0], coordinates[a][1]);
}

// Three interior points, degree 2: exact for the (quadratic) mass matrix N_a N_b.
int Tri3::quadrature_size() { return 3; }

Tri3::Local Tri3::quadrature_point(int q) {
  static const double points[3][2] = {
      {1.0 / 6.0, 1.0 / 6.0}, {2.0 / 3.0, 1.0 / 6.0}, {1.0 / 6.0, 2.0 / 3.0}};
  return Local(points[q][0], points[q][1]);
}

double Tri3::quadrature_weight(int /*q*/) { return 1.0 / 6.0; }

}  // namespace geompm

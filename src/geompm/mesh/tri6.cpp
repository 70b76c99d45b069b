// Quadratic triangle: corner nodes 0-2, then mid-side nodes on edges 0-1, 1-2, 2-0 (Gmsh order).
// Written in barycentric coordinates L = (1 - xi - eta, xi, eta).
#include "geompm/mesh/element.hpp"

namespace geompm {

using Tri6 = Element<CellType::Tri6>;

Tri6::Values Tri6::shape(const Local& xi) {
  const double l0 = 1.0 - xi[0] - xi[1], l1 = xi[0], l2 = xi[1];
  Values n;
  n << l0 * (2.0 * l0 - 1.0), l1 * (2.0 * l1 - 1.0), l2 * (2.0 * l2 - 1.0), 4.0 * l0 * l1,
      4.0 * l1 * l2, 4.0 * l2 * l0;
  return n;
}

Tri6::Gradients Tri6::shape_gradients(const Local& xi) {
  const double l0 = 1.0 - xi[0] - xi[1], l1 = xi[0], l2 = xi[1];
  // dl0/dxi = (-1, -1), dl1/dxi = (1, 0), dl2/dxi = (0, 1).
  Gradients g;
  g << 1.0 - 4.0 * l0, 1.0 - 4.0 * l0,  //
      4.0 * l1 - 1.0, 0.0,              //
      0.0, 4.0 * l2 - 1.0,              //
      4.0 * (l0 - l1), -4.0 * l1,       //
      4.0 * l2, 4.0 * l1,               //
      -4.0 * l2, 4.0 * (l0 - l2);
  return g;
}

bool Tri6::contains(const Local& xi, double tol) {
  return xi[0] >= -tol && xi[1] >= -tol && xi[0] + xi[1] <= 1.0 + tol;
}

Tri6::Local Tri6::centroid() { return Local(1.0 / 3.0, 1.0 / 3.0); }

Tri6::Local Tri6::node(int a) {
  static const double coordinates[6][2] = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
  return Local(coordinates[a][0], coordinates[a][1]);
}

// Six-point rule of degree 4 (Dunavant / Strang-Fix), exact for the quartic mass matrix.
int Tri6::quadrature_size() { return 6; }

namespace {
constexpr double a = 0.44594849091596488632;  // orbit 1: (a, a, 1 - 2a)
constexpr double b = 0.09157621350977074346;  // orbit 2: (b, b, 1 - 2b)
constexpr double weight_a = 0.11169079483900573285;
constexpr double weight_b = 0.05497587182766093382;
}  // namespace

Tri6::Local Tri6::quadrature_point(int q) {
  static const double points[6][2] = {{a, a}, {1.0 - 2.0 * a, a}, {a, 1.0 - 2.0 * a},
                                      {b, b}, {1.0 - 2.0 * b, b}, {b, 1.0 - 2.0 * b}};
  return Local(points[q][0], points[q][1]);
}

double Tri6::quadrature_weight(int q) { return q < 3 ? weight_a : weight_b; }

}  // namespace geompm

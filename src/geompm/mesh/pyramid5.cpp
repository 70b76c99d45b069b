// Five-node pyramid: base (-1,-1,0) (1,-1,0) (1,1,0) (-1,1,0), apex (0,0,1) (Gmsh's order).
//
// The rational shape functions of Bedrosian (1992) and Zgainski et al. (1996), docs/theory.md
// eq. 19.7: with s = 1 - zeta and the base corner (xi_a, eta_a),
//   N_a = (s + xi_a xi)(s + eta_a eta) / (4 s)
//       = [s + xi_a xi + eta_a eta + xi_a eta_a xi eta / s] / 4,      N_apex = zeta.
// They are the trilinear hexahedron with its top face collapsed onto the apex, written in the
// pyramid's own coordinates: on the base (zeta = 0) the bilinear quadrangle, so a pyramid conforms
// with the hex8 beside it; on each triangular face (say xi = -s) linear, so it conforms with a
// tet4. They are non-negative in the cell, which material points need.
//
// At the apex (s = 0) the rational term xi eta / s is 0/0. In the cell |xi|, |eta| <= s, so the
// term and its value tend to 0; its gradient (eta / s, xi / s, xi eta / s^2) has no single limit
// (it depends on the direction the apex is approached from) and is taken along the axis xi = eta
// = 0, where it is 0 (eq. 19.8). The quadrature points stay away from the apex.
#include <cmath>

#include "geompm/mesh/element.hpp"

namespace geompm {

using Pyramid5 = Element<CellType::Pyramid5>;

namespace {

constexpr double base[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};

// Closer to the apex than this, the rational term and its gradient take their limit on the axis.
constexpr double apex_distance = 1e-12;

/// xi / s, eta / s for s = 1 - zeta: bounded by 1 in the cell; 0 at the apex (its axis limit).
struct Ratios {
  double xi = 0.0, eta = 0.0;
};

Ratios ratios(const Pyramid5::Local& x) {
  const double s = 1.0 - x[2];
  if (std::abs(s) < apex_distance) return {};
  return {x[0] / s, x[1] / s};
}

}  // namespace

Pyramid5::Values Pyramid5::shape(const Local& x) {
  const Ratios r = ratios(x);
  const double s = 1.0 - x[2];
  const double rational = x[0] * r.eta;  // xi eta / s
  Values n;
  for (int a = 0; a < 4; ++a)
    n[a] = 0.25 * (s + base[a][0] * x[0] + base[a][1] * x[1] + base[a][0] * base[a][1] * rational);
  n[4] = x[2];
  return n;
}

Pyramid5::Gradients Pyramid5::shape_gradients(const Local& x) {
  const Ratios r = ratios(x);
  Gradients g;
  for (int a = 0; a < 4; ++a) {
    const double corner = base[a][0] * base[a][1];
    g(a, 0) = 0.25 * (base[a][0] + corner * r.eta);
    g(a, 1) = 0.25 * (base[a][1] + corner * r.xi);
    g(a, 2) = 0.25 * (-1.0 + corner * r.xi * r.eta);
  }
  g.row(4) << 0.0, 0.0, 1.0;
  return g;
}

bool Pyramid5::contains(const Local& x, double tol) {
  const double s = 1.0 - x[2];
  return x[2] >= -tol && s >= -tol && std::abs(x[0]) <= s + tol && std::abs(x[1]) <= s + tol;
}

// The centroid of the reference pyramid: a quarter of its height above the base.
Pyramid5::Local Pyramid5::centroid() { return Local(0.0, 0.0, 0.25); }

Pyramid5::Local Pyramid5::node(int a) {
  if (a == 4) return Local(0.0, 0.0, 1.0);
  return Local(base[a][0], base[a][1], 0.0);
}

// The collapsed-hexahedron (Duffy) rule, eq. 19.9: xi = u (1 - w), eta = v (1 - w), zeta = w
// maps the box [-1,1]^2 x [0,1] onto the pyramid with dxi deta dzeta = (1 - w)^2 du dv dw; 2-point
// Gauss-Legendre in u and v and 2-point Gauss-Jacobi for the weight (1 - w)^2 in w (Stroud 1971,
// Duffy 1982). The gradients of eq. 19.7 are bilinear in (u, v) and independent of w, so the rule
// integrates exactly the volume of any straight-sided pyramid, the stiffness and the mass matrix
// of one whose base is a parallelogram (an affine image of the reference), and so linear fields.
// Its points lie at w < 0.55, away from the apex.
int Pyramid5::quadrature_size() { return 8; }

namespace {

/// The 2-point Gauss-Jacobi rule on [0, 1] for the weight (1 - w)^2: t = 1 - w are the roots of
/// t^2 - 4 t / 3 + 2 / 5 (orthogonal to 1 and t under t^2 dt), the weights match the moments
/// 1/3 and 1/4.
struct JacobiRule {
  double w[2], weight[2];
};

const JacobiRule& jacobi_rule() {
  static const JacobiRule rule = [] {
    const double spread = std::sqrt(2.0 / 45.0);
    const double t[2] = {2.0 / 3.0 + spread, 2.0 / 3.0 - spread};
    JacobiRule r;
    r.weight[0] = (0.25 - t[1] / 3.0) / (t[0] - t[1]);
    r.weight[1] = 1.0 / 3.0 - r.weight[0];
    r.w[0] = 1.0 - t[0];
    r.w[1] = 1.0 - t[1];
    return r;
  }();
  return rule;
}

}  // namespace

Pyramid5::Local Pyramid5::quadrature_point(int q) {
  const double g = 1.0 / std::sqrt(3.0);
  const double w = jacobi_rule().w[q / 4];
  return Local(base[q % 4][0] * g * (1.0 - w), base[q % 4][1] * g * (1.0 - w), w);
}

double Pyramid5::quadrature_weight(int q) { return jacobi_rule().weight[q / 4]; }

}  // namespace geompm

#include "geompm/points/seeding.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geompm/mesh/cell_geometry.hpp"
#include "geompm/mesh/element.hpp"

namespace geompm {

namespace {

using Simplex2 = std::array<Eigen::Vector2d, 3>;
using Simplex3 = std::array<Eigen::Vector3d, 4>;

// k^2 sub-triangles of the reference triangle (vertices (0,0), (1,0), (0,1)).
std::vector<Simplex2> split_triangle(int k) {
  std::vector<Simplex2> out;
  const double h = 1.0 / k;
  for (int i = 0; i < k; ++i)
    for (int j = 0; i + j < k; ++j) {
      const Eigen::Vector2d o(i * h, j * h);
      out.push_back({o, o + Eigen::Vector2d(h, 0), o + Eigen::Vector2d(0, h)});
      if (i + j < k - 1)
        out.push_back(
            {o + Eigen::Vector2d(h, 0), o + Eigen::Vector2d(h, h), o + Eigen::Vector2d(0, h)});
    }
  return out;
}

// Each triangle split in three by its centroid.
std::vector<Simplex2> split_by_centroid(const std::vector<Simplex2>& in) {
  std::vector<Simplex2> out;
  for (const auto& t : in) {
    const Eigen::Vector2d c = (t[0] + t[1] + t[2]) / 3.0;
    out.push_back({t[0], t[1], c});
    out.push_back({t[1], t[2], c});
    out.push_back({t[2], t[0], c});
  }
  return out;
}

std::vector<Simplex3> split_tetrahedron(int count) {
  const Eigen::Vector3d v0(0, 0, 0), v1(1, 0, 0), v2(0, 1, 0), v3(0, 0, 1);
  if (count == 1) return {{v0, v1, v2, v3}};
  if (count == 4) {
    const Eigen::Vector3d c = (v0 + v1 + v2 + v3) / 4.0;
    return {{v1, v2, v3, c}, {v0, v3, v2, c}, {v0, v1, v3, c}, {v0, v2, v1, c}};
  }
  // Mid-edge (Freudenthal) split: four corner tetrahedra and the inner octahedron in four.
  const Eigen::Vector3d m01 = (v0 + v1) / 2, m02 = (v0 + v2) / 2, m03 = (v0 + v3) / 2,
                        m12 = (v1 + v2) / 2, m13 = (v1 + v3) / 2, m23 = (v2 + v3) / 2;
  return {{v0, m01, m02, m03},  {m01, v1, m12, m13},  {m02, m12, v2, m23},  {m03, m13, m23, v3},
          {m01, m02, m03, m13}, {m01, m02, m13, m12}, {m02, m03, m13, m23}, {m02, m12, m13, m23}};
}

int integer_root(int n, int power) {
  for (int k = 1; k <= 8; ++k) {
    int p = 1;
    for (int i = 0; i < power; ++i) p *= k;
    if (p == n) return k;
  }
  return -1;
}

// |dX/dxi| (times the radius in axisymmetry) at xi: the volume density in reference space.
template <class E>
double volume_density(const Eigen::Matrix<double, E::nodes, E::dim>& X, const typename E::Local& xi,
                      bool axisymmetric) {
  const Eigen::Matrix<double, E::dim, E::dim> J = X.transpose() * E::shape_gradients(xi);
  double d = std::abs(J.determinant());
  if (axisymmetric) d *= E::shape(xi).dot(X.col(0));
  return d;
}

// corners: the vertices of the point's sub-cell in reference coordinates; the half-lengths are half
// the extent of their images along each axis, the exact half-lengths of the sub-cell on an
// axis-aligned cell, the initial particle domain of GIMP (docs/theory.md eq. 9.4).
template <class E, class Corners>
SeedPoint make_point(const Eigen::Matrix<double, E::nodes, E::dim>& X, const typename E::Local& xi,
                     double volume, const Corners& corners) {
  constexpr int dim = E::dim;
  SeedPoint p;
  p.xi = Vec3::Zero();
  p.xi.head<dim>() = xi;
  p.position = Vec3::Zero();
  p.position.head<dim>() = X.transpose() * E::shape(xi);
  p.volume = volume;
  std::vector<Eigen::Matrix<double, dim, 1>> images;
  for (const auto& corner : corners) images.push_back(X.transpose() * E::shape(corner));
  Eigen::Matrix<double, dim, 1> lo, hi;
  lo.setConstant(std::numeric_limits<double>::max());
  hi = -lo;
  for (const auto& x : images) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  p.half_size = Vec3::Zero();
  p.half_size.head<dim>() = 0.5 * (hi - lo);
  return p;
}

/// The tensor-product box of a cell's sub-cells and its map onto the reference cell: the box
/// itself, [-1,1]^dim, for quad4 and hex8; for pyramid5 the collapsed hexahedron [-1,1]^2 x [0,1],
/// xi = u (1 - w), eta = v (1 - w), zeta = w (docs/theory.md eq. 19.9).
template <class E>
struct TensorBox {
  static constexpr bool collapsed = cell_type_of<E> == CellType::Pyramid5;
  static double lower(int d) { return collapsed && d == 2 ? 0.0 : -1.0; }
  static double length(int d) { return collapsed && d == 2 ? 1.0 : 2.0; }
  static typename E::Local reference(const typename E::Local& u) {
    if constexpr (collapsed)
      return typename E::Local(u(0) * (1.0 - u(2)), u(1) * (1.0 - u(2)), u(2));
    else
      return u;
  }
  /// d(xi) / d(u): (1 - w)^2 for the collapse.
  static double volume_factor(const typename E::Local& u) {
    if constexpr (collapsed)
      return (1.0 - u(2)) * (1.0 - u(2));
    else
      return 1.0;
  }
};

template <class E>
std::vector<SeedPoint> seed_tensor_cell(const Eigen::Matrix<double, E::nodes, E::dim>& X, int k,
                                        bool axisymmetric) {
  // Sub-cells of the box, each integrated with a 3-point Gauss rule per direction (exact for the
  // bilinear/trilinear Jacobian times the radius, and for the pyramid's (1 - w)^2 times its
  // Jacobian, biquadratic in u and v).
  using Box = TensorBox<E>;
  constexpr int dim = E::dim;
  const double gauss[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  const double weight[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  std::vector<SeedPoint> out;
  const int cells = dim == 2 ? k * k : k * k * k;
  for (int s = 0; s < cells; ++s) {
    const int idx[3] = {s % k, (s / k) % k, s / (k * k)};
    typename E::Local centre, h;
    for (int d = 0; d < dim; ++d) {
      h(d) = Box::length(d) / k;
      centre(d) = Box::lower(d) + (idx[d] + 0.5) * h(d);
    }
    double volume = 0.0;
    const int nq = dim == 2 ? 9 : 27;
    for (int q = 0; q < nq; ++q) {
      const int qi[3] = {q % 3, (q / 3) % 3, q / 9};
      typename E::Local u;
      double w = 1.0;
      for (int d = 0; d < dim; ++d) {
        u(d) = centre(d) + 0.5 * h(d) * gauss[qi[d]];
        w *= 0.5 * h(d) * weight[qi[d]];
      }
      volume += w * Box::volume_factor(u) * volume_density<E>(X, Box::reference(u), axisymmetric);
    }
    std::vector<typename E::Local> corners;
    for (int c = 0; c < (1 << dim); ++c) {
      typename E::Local corner;
      for (int d = 0; d < dim; ++d) corner(d) = centre(d) + (c >> d & 1 ? 0.5 : -0.5) * h(d);
      corners.push_back(Box::reference(corner));
    }
    out.push_back(make_point<E>(X, Box::reference(centre), volume, corners));
  }
  return out;
}

template <class E>
std::vector<SeedPoint> seed_triangle(const Eigen::Matrix<double, E::nodes, E::dim>& X, int count,
                                     bool axisymmetric) {
  std::vector<Simplex2> parts;
  if (integer_root(count, 2) > 0) {
    parts = split_triangle(integer_root(count, 2));
  } else {
    parts = split_by_centroid(split_triangle(integer_root(count / 3, 2)));
  }
  // Degree-4 six-point rule (Dunavant) on each sub-triangle: exact for a Tri6 Jacobian times r.
  const double a1 = 0.445948490915965, b1 = 0.091576213509771;
  const double w1 = 0.223381589678011, w2 = 0.109951743655322;
  const double bary[6][3] = {{a1, a1, 1 - 2 * a1}, {a1, 1 - 2 * a1, a1}, {1 - 2 * a1, a1, a1},
                             {b1, b1, 1 - 2 * b1}, {b1, 1 - 2 * b1, b1}, {1 - 2 * b1, b1, b1}};
  const double w[6] = {w1, w1, w1, w2, w2, w2};
  std::vector<SeedPoint> out;
  for (const auto& t : parts) {
    const double area = 0.5 * std::abs((t[1] - t[0]).x() * (t[2] - t[0]).y() -
                                       (t[2] - t[0]).x() * (t[1] - t[0]).y());
    double volume = 0.0;
    for (int q = 0; q < 6; ++q) {
      const Eigen::Vector2d xi = bary[q][0] * t[0] + bary[q][1] * t[1] + bary[q][2] * t[2];
      volume += w[q] * area * volume_density<E>(X, xi, axisymmetric);
    }
    out.push_back(make_point<E>(X, (t[0] + t[1] + t[2]) / 3.0, volume, t));
  }
  return out;
}

template <class E>
std::vector<SeedPoint> seed_tetrahedron(const Eigen::Matrix<double, E::nodes, E::dim>& X,
                                        int count) {
  std::vector<SeedPoint> out;
  for (const auto& t : split_tetrahedron(count)) {
    Eigen::Matrix3d edges;
    edges << t[1] - t[0], t[2] - t[0], t[3] - t[0];
    const double reference_volume = std::abs(edges.determinant()) / 6.0;
    const Eigen::Vector3d centre = (t[0] + t[1] + t[2] + t[3]) / 4.0;
    // The Tet4 map is affine: the density is constant.
    out.push_back(
        make_point<E>(X, centre, reference_volume * volume_density<E>(X, centre, false), t));
  }
  return out;
}

}  // namespace

std::vector<int> allowed_points_per_cell(CellType type) {
  switch (type) {
    case CellType::Quad4:
      return {1, 4, 9, 16};
    case CellType::Tri3:
    case CellType::Tri6:
      return {1, 3, 4, 9, 12, 16};
    case CellType::Tet4:
      return {1, 4, 8};
    case CellType::Hex8:
    case CellType::Pyramid5:  // k^3 sub-cells of the collapsed hexahedron
      return {1, 8, 27, 64};
  }
  return {};
}

int default_points_per_cell(CellType type) {
  return type == CellType::Hex8 || type == CellType::Pyramid5 ? 8 : 4;
}

std::vector<SeedPoint> seed_cell(const Mesh& mesh, Index c, int count, bool axisymmetric) {
  const CellType type = mesh.type_of(c);
  const auto allowed = allowed_points_per_cell(type);
  if (std::find(allowed.begin(), allowed.end(), count) == allowed.end()) {
    std::string list;
    for (int n : allowed) list += (list.empty() ? "" : ", ") + std::to_string(n);
    throw std::invalid_argument(std::to_string(count) + " points per cell is not available for " +
                                to_string(type) + " cells; expected one of " + list);
  }
  return dispatch_cell_type(type, [&](auto element) -> std::vector<SeedPoint> {
    using E = decltype(element);
    const Eigen::Matrix<double, E::nodes, E::dim> X =
        cell_node_coordinates<cell_type_of<E>>(mesh, c).transpose();
    if constexpr (std::is_same_v<E, Element<CellType::Quad4>>)
      return seed_tensor_cell<E>(X, integer_root(count, 2), axisymmetric);
    else if constexpr (std::is_same_v<E, Element<CellType::Hex8>> ||
                       std::is_same_v<E, Element<CellType::Pyramid5>>)
      return seed_tensor_cell<E>(X, integer_root(count, 3), false);
    else if constexpr (std::is_same_v<E, Element<CellType::Tet4>>)
      return seed_tetrahedron<E>(X, count);
    else
      return seed_triangle<E>(X, count, axisymmetric);
  });
}

}  // namespace geompm

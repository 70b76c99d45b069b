#include "geompm/contact/contact_surface.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "geompm/mesh/cell_geometry.hpp"

namespace geompm {

double cell_size_at(const PointLocator& locator, const Vec3& x, double fallback) {
  const auto where = locator.locate(x);
  if (!where) return fallback;
  const Mesh& mesh = locator.mesh();
  return std::pow(cell_measure(mesh, where->cell, false), 1.0 / mesh.dim());
}

ContactSegment segment_frame(const Facet& facet, Index index, int dim) {
  ContactSegment s;
  s.facet = index;
  s.structure_cell = facet.cell;
  s.normal = facet.normal;
  if (dim == 2) {
    s.tangents[0] = Vec3(-facet.normal.y(), facet.normal.x(), 0.0);
    return s;
  }
  // Any unit vector across the normal, then the one across both.
  const Vec3 helper = std::abs(facet.normal.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  s.tangents[0] = facet.normal.cross(helper).normalized();
  s.tangents[1] = facet.normal.cross(s.tangents[0]);
  return s;
}

void cut_segment(const Vec3& a, const Vec3& b, int pieces, bool axisymmetric,
                 ContactSegment prototype, std::vector<ContactSegment>& out) {
  // Two Gauss points a piece (exact for the cubic r (linear)^2 of axisymmetry's weights).
  const double g = 0.5 / std::sqrt(3.0);
  const double length = (b - a).norm() / pieces;
  for (int k = 0; k < pieces; ++k) {
    ContactSegment s = prototype;
    for (double t : {0.5 - g, 0.5 + g}) {
      const Vec3 x = a + (b - a) * ((k + t) / pieces);
      const double w = 0.5 * length * (axisymmetric ? x.x() : 1.0);
      s.points.push_back({x, w});
      s.measure += w;
    }
    out.push_back(std::move(s));
  }
}

void cut_triangle(const Vec3& a, const Vec3& b, const Vec3& c, int pieces, ContactSegment prototype,
                  std::vector<ContactSegment>& out) {
  // The triangle's pieces^2 similar triangles (upright and inverted rows), three-point rule each.
  const Vec3 e1 = (b - a) / pieces, e2 = (c - a) / pieces;
  const double area = 0.5 * e1.cross(e2).norm();
  const auto add = [&](const Vec3& p, const Vec3& q, const Vec3& r) {
    ContactSegment s = prototype;
    // Strang & Fix's degree-2 rule: barycentric (2/3, 1/6, 1/6) and its permutations.
    for (const auto& l : {Vec3(4, 1, 1), Vec3(1, 4, 1), Vec3(1, 1, 4)}) {
      s.points.push_back({(l(0) * p + l(1) * q + l(2) * r) / 6.0, area / 3.0});
      s.measure += area / 3.0;
    }
    out.push_back(std::move(s));
  };
  for (int i = 0; i < pieces; ++i)
    for (int j = 0; i + j < pieces; ++j) {
      const Vec3 p = a + i * e1 + j * e2;
      add(p, p + e1, p + e2);
      if (i + j + 1 < pieces) add(p + e1, p + e1 + e2, p + e2);
    }
}

}  // namespace geompm

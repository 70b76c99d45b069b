// A structure's surface as contact sees it (docs/theory.md §18.1): its boundary facets cut into
// pieces no longer than the background cell around them, each with a Gauss rule on it. The
// contact groups the pieces into segments of about two cells, each with one set of multipliers
// (level_set_contact.hpp): finer multipliers than the grid can resolve would make their equations
// linearly dependent, and one per cell lets them oscillate.
#pragma once

#include <vector>

#include "geompm/core/types.hpp"
#include "geompm/mesh/point_locator.hpp"
#include "geompm/structures/structure_mesh.hpp"

namespace geompm {

struct ContactGaussPoint {
  Vec3 x = Vec3::Zero();  // at the start of the step
  double weight = 0.0;    // length (2D) or area (3D) share; times the radius in axisymmetry
};

/// A piece of one facet of the structure's surface. The normal points out of the structure; in
/// 2D the tangent is the normal turned counter-clockwise, in 3D two tangents complete the frame.
struct ContactSegment {
  Index facet = -1;
  Index structure_cell = -1;
  Vec3 normal = Vec3::Zero();
  std::array<Vec3, 2> tangents = {Vec3::Zero(), Vec3::Zero()};
  std::vector<ContactGaussPoint> points;
  /// The sum of the weights: the segment's length or area (per radian in axisymmetry).
  double measure = 0.0;
};

/// The surface of `mesh` cut into segments at most `spacing(x)` long (x a facet's centre; the
/// background cell size there), numbered facet by facet so that the same structure gives the
/// same segments step after step while the grid does not change.
template <class Spacing>
std::vector<ContactSegment> contact_segments(const StructureMesh& mesh, Spacing&& spacing);

/// The size of the background cell at x ((area or volume)^(1/dim)), or `fallback` outside the
/// mesh.
double cell_size_at(const PointLocator& locator, const Vec3& x, double fallback);

// --- implementation ------------------------------------------------------------------------------

void cut_segment(const Vec3& a, const Vec3& b, int pieces, bool axisymmetric,
                 ContactSegment prototype, std::vector<ContactSegment>& out);
void cut_triangle(const Vec3& a, const Vec3& b, const Vec3& c, int pieces, ContactSegment prototype,
                  std::vector<ContactSegment>& out);
ContactSegment segment_frame(const Facet& facet, Index index, int dim);

template <class Spacing>
std::vector<ContactSegment> contact_segments(const StructureMesh& mesh, Spacing&& spacing) {
  std::vector<ContactSegment> out;
  const auto& nodes = mesh.nodes();
  const bool axisymmetric = mesh.kinematics() == Kinematics::Axisymmetric;
  for (std::size_t f = 0; f < mesh.surface().size(); ++f) {
    const Facet& facet = mesh.surface()[f];
    const ContactSegment prototype = segment_frame(facet, static_cast<Index>(f), mesh.dim());
    const double h = spacing(facet.centre(nodes));
    const auto corner = [&](int k) { return nodes[facet.nodes[k]]; };
    if (facet.corners == 2) {
      const int pieces = std::max(1, static_cast<int>(std::ceil(facet.size / h - 1e-9)));
      cut_segment(corner(0), corner(1), pieces, axisymmetric, prototype, out);
      continue;
    }
    // Triangles as they are, quadrilaterals as two; each into pieces^2 similar triangles.
    const auto cut = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
      const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
      const int pieces = std::max(1, static_cast<int>(std::ceil(longest / h - 1e-9)));
      cut_triangle(a, b, c, pieces, prototype, out);
    };
    cut(corner(0), corner(1), corner(2));
    if (facet.corners == 4) cut(corner(0), corner(2), corner(3));
  }
  return out;
}

}  // namespace geompm

// Checks shared by the structures' unit tests: the boundary surface's normals point outward and
// the surface is closed (every corner of a 2D surface in two segments, every edge of a 3D surface
// in two facets; in axisymmetry open only at the axis).
#pragma once

#include <gtest/gtest.h>

#include <map>
#include <utility>

#include "geompm/structures/structure_mesh.hpp"

namespace geompm::testing {

/// For a star-shaped body about `centre`: every facet's normal points away from it.
inline void expect_outward_normals(const StructureMesh& s, const Vec3& centre) {
  for (const Facet& f : s.surface()) {
    EXPECT_NEAR(f.normal.norm(), 1.0, 1e-12);
    EXPECT_GT(f.normal.dot(f.centre(s.nodes()) - centre), 0.0)
        << "facet of cell " << f.cell << " at " << f.centre(s.nodes()).transpose();
  }
}

/// Facets of a closed surface meet in pairs; in axisymmetry the ends on the axis meet one
/// (`axis_ends` of them: 2 for a solid body on the axis, 4 for a shell).
inline void expect_closed_surface(const StructureMesh& s, int axis_ends = 2) {
  std::map<std::pair<Index, Index>, int> edges;
  for (const Facet& f : s.surface()) {
    if (f.corners == 2) {
      ++edges[{f.nodes[0], -1}];
      ++edges[{f.nodes[1], -1}];
      continue;
    }
    for (int a = 0; a < f.corners; ++a) {
      const Index i = f.nodes[a], j = f.nodes[(a + 1) % f.corners];
      ++edges[{std::min(i, j), std::max(i, j)}];
    }
  }
  int open = 0;
  for (const auto& [edge, count] : edges) {
    const bool on_axis =
        s.kinematics() == Kinematics::Axisymmetric && std::abs(s.nodes()[edge.first].x()) < 1e-12;
    if (count == 2) continue;
    if (count == 1 && on_axis) {
      ++open;
      continue;
    }
    ADD_FAILURE() << "node/edge " << edge.first << "-" << edge.second << " in " << count
                  << " facets";
  }
  if (s.kinematics() == Kinematics::Axisymmetric)
    EXPECT_EQ(open, axis_ends);
  else
    EXPECT_EQ(open, 0);
}

}  // namespace geompm::testing

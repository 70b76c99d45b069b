// Seeding records each point's domain: on quadrilaterals and hexahedra the half-lengths of its
// sub-cell along the axes, the initial particle domain of GIMP (docs/theory.md eq. 9.4), which
// tile an axis-aligned cell exactly; on triangles and tetrahedra the top face of its sub-cell,
// where a rigid footing touches it (eq. 13.1), whose widths tile a flat surface exactly.
#include "geompm/points/seeding.hpp"

#include <gtest/gtest.h>

#include "geompm/mesh/structured_mesh.hpp"

#include <map>

namespace geompm {
namespace {

TEST(Seeding, HalfSizesTileAnAxisAlignedCell) {
  for (CellType type : {CellType::Quad4, CellType::Hex8}) {
    StructuredMeshSpec spec;
    spec.cell_type = type;
    spec.axes = {std::vector<AxisSegment>{{2.0, 1, 1.0}}, {{1.0, 1, 1.0}}, {{0.5, 1, 1.0}}};
    const Mesh mesh = generate_structured_mesh(spec);
    const int dim = mesh.dim();
    for (int k : {1, 2, 3}) {
      const int count = dim == 2 ? k * k : k * k * k;
      const auto points = seed_cell(mesh, 0, count, false);
      double covered = 0.0;
      for (const auto& p : points) {
        double box = 1.0;
        for (int d = 0; d < dim; ++d) {
          const double extent = d == 0 ? 2.0 : d == 1 ? 1.0 : 0.5;
          EXPECT_NEAR(p.half_size(d), 0.5 * extent / k, 1e-14);
          box *= 2 * p.half_size(d);
        }
        EXPECT_NEAR(box, p.volume, 1e-14);
        covered += box;
      }
      EXPECT_NEAR(covered, dim == 2 ? 2.0 : 1.0, 1e-13);
    }
  }
}

TEST(Seeding, BoxDomainsAreTouchedAtTheirTopFace) {
  StructuredMeshSpec spec;
  spec.cell_type = CellType::Quad4;
  spec.axes = {std::vector<AxisSegment>{{2.0, 1, 1.0}}, {{1.0, 1, 1.0}}, {}};
  const Mesh mesh = generate_structured_mesh(spec);
  for (const auto& p : seed_cell(mesh, 0, 4, false))
    EXPECT_EQ(p.top_offset, Vec3(0, p.half_size(1), 0));
}

// The points of a mesh of [0, 2] x [0, 1] (or [0, 2] x [0, 1] x [0, 1]) whose domains' tops lie
// on its top surface: the widths (areas) of those tops, which must add up to the surface's; and
// no domain's top may lie above the surface, where a footing resting on it would press it.
void check_top_faces_tile_the_surface(const StructuredMeshSpec& spec, int count) {
  const Mesh mesh = generate_structured_mesh(spec);
  const int dim = mesh.dim(), v = dim - 1;
  const double surface = 1.0;
  double covered = 0.0;
  int touching = 0;
  for (Index c = 0; c < mesh.num_cells(); ++c)
    for (const auto& p : seed_cell(mesh, c, count, false)) {
      const double top = p.position(v) + p.top_offset(v);
      EXPECT_LE(top, surface + 1e-12) << to_string(spec.cell_type);
      EXPECT_NEAR(p.half_size(v), p.top_offset(v), 1e-15);
      for (int t = 0; t < v; ++t) EXPECT_GE(p.half_size(t), 0.0);
      if (top < surface - 1e-12) continue;
      double area = 1.0;
      for (int t = 0; t < v; ++t) area *= 2 * p.half_size(t);
      covered += area;
      touching += area > 0.0;
      // In 2D the top is the face itself, within the surface (in 3D a box of its area, which
      // may reach past the face's triangle).
      for (int t = 0; t < v && dim == 2; ++t) {
        const double middle = p.position(t) + p.top_offset(t);
        EXPECT_GE(middle - p.half_size(t), -1e-12);
        EXPECT_LE(middle + p.half_size(t), (t == 0 ? 2.0 : 1.0) + 1e-12);
      }
    }
  EXPECT_GT(touching, 0);
  EXPECT_NEAR(covered, 2.0, 1e-12) << to_string(spec.cell_type) << ", " << count << " points";
}

TEST(Seeding, SimplexTopFacesTileTheSurfaceAndStayBelowIt) {
  for (Diagonals diagonals : {Diagonals::Alternating, Diagonals::Crossed})
    for (int count : {1, 3, 4, 12}) {
      StructuredMeshSpec spec;
      spec.cell_type = CellType::Tri3;
      spec.diagonals = diagonals;
      spec.axes = {std::vector<AxisSegment>{{2.0, 4, 1.0}}, {{1.0, 3, 0.5}}, {}};
      check_top_faces_tile_the_surface(spec, count);
    }
  for (int count : {1, 4, 8}) {
    StructuredMeshSpec spec;
    spec.cell_type = CellType::Tet4;
    spec.axes = {std::vector<AxisSegment>{{2.0, 2, 1.0}}, {{1.0, 2, 1.0}}, {{1.0, 2, 1.0}}};
    // Here the top is z = 1 over [0, 2] x [0, 1]: the same numbers as the 2D check.
    check_top_faces_tile_the_surface(spec, count);
  }
}

}  // namespace
}  // namespace geompm

// The distance from a point to a structure (structures/structure_distance; the regions given by
// their distance from a structure, docs/user-guide.md "regions"): to a segment and a triangle
// against hand-computed values, and to a rectangular body in plane strain and axisymmetry (zero
// inside, the distance to the nearest side or corner outside; not to the axis, which is no
// surface in axisymmetry).
#include <gtest/gtest.h>

#include <cmath>

#include "geompm/mesh/structured_mesh.hpp"
#include "geompm/structures/structure_distance.hpp"

namespace geompm {
namespace {

TEST(StructureDistance, ToASegmentItsInteriorOrItsEnds) {
  const Vec3 a(0, 0, 0), b(2, 0, 0);
  EXPECT_DOUBLE_EQ(distance_to_segment(Vec3(1, 3, 0), a, b), 3.0);
  EXPECT_DOUBLE_EQ(distance_to_segment(Vec3(-3, 4, 0), a, b), 5.0);
  EXPECT_DOUBLE_EQ(distance_to_segment(Vec3(5, -4, 0), a, b), 5.0);
}

TEST(StructureDistance, ToATriangleItsFaceEdgesOrCorners) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_DOUBLE_EQ(distance_to_triangle(Vec3(0.25, 0.25, 2), a, b, c), 2.0);
  EXPECT_NEAR(distance_to_triangle(Vec3(1, 1, 0), a, b, c), std::sqrt(0.5), 1e-15);
  EXPECT_DOUBLE_EQ(distance_to_triangle(Vec3(-3, -4, 0), a, b, c), 5.0);
  EXPECT_DOUBLE_EQ(distance_to_triangle(Vec3(0.5, -1, 1), a, b, c), std::sqrt(2.0));
}

// A 0.5 x 2 rectangle [0, 0.5] x [1, 3] of 2 x 4 quad4 cells.
Mesh rectangle() {
  StructuredMeshSpec spec;
  spec.cell_type = CellType::Quad4;
  spec.origin = Vec3(0, 1, 0);
  spec.axes[0] = {AxisSegment{0.5, 2, 1.0}};
  spec.axes[1] = {AxisSegment{2.0, 4, 1.0}};
  return generate_structured_mesh(spec);
}

TEST(StructureDistance, ZeroInsideTheNearestSideOrCornerOutside) {
  const StructureMesh body(rectangle(), Kinematics::PlaneStrain);
  const StructureDistance distance(body);
  EXPECT_EQ(distance(Vec3(0.3, 2.1, 0)), 0.0);
  EXPECT_NEAR(distance(Vec3(1.5, 2.0, 0)), 1.0, 1e-14);             // beside
  EXPECT_NEAR(distance(Vec3(0.25, 0.2, 0)), 0.8, 1e-14);            // below
  EXPECT_NEAR(distance(Vec3(0.8, 0.6, 0)), 0.5, 1e-14);             // off the corner (0.5, 1)
  EXPECT_NEAR(distance(Vec3(-0.4, 2.0, 0)), 0.4, 1e-14);            // left of its left side
  const StructureMesh pile(rectangle(), Kinematics::Axisymmetric);  // the axis is no surface
  const StructureDistance from_pile(pile);
  EXPECT_NEAR(from_pile(Vec3(0.0, 0.5, 0)), 0.5, 1e-14);  // below its base, on the axis
  EXPECT_NEAR(from_pile(Vec3(0.9, 2.0, 0)), 0.4, 1e-14);
}

}  // namespace
}  // namespace geompm

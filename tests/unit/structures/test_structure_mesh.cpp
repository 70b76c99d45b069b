// A structure's mesh and boundary surface (structures/structure_mesh, docs/theory.md §17.1): the
// facets no two cells share, with outward unit normals, closed (open only on the axis in
// axisymmetry), and the measures of the body and its surface, against hand-made meshes whose
// answers are known exactly.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <map>

#include "geompm/structures/mass_properties.hpp"
#include "geompm/structures/structure_mesh.hpp"
#include "structure_test_support.hpp"

namespace geompm {
namespace {

using testing::expect_closed_surface;
using testing::expect_outward_normals;

// Two quad4 cells side by side: [0, 2] x [0, 1].
Mesh two_quads() {
  Mesh m;
  m.cell_type = CellType::Quad4;
  m.nodes = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0),
             Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(2, 1, 0)};
  m.connectivity = {0, 1, 4, 3, 1, 2, 5, 4};
  return m;
}

TEST(StructureMesh, FindsTheBoundaryOfTwoQuadsWithOutwardNormals) {
  const StructureMesh s(two_quads(), Kinematics::PlaneStrain);
  ASSERT_EQ(s.surface().size(), 6u);  // the shared edge 1-4 is inside
  for (const Facet& f : s.surface())
    EXPECT_FALSE((f.nodes[0] == 1 && f.nodes[1] == 4) || (f.nodes[0] == 4 && f.nodes[1] == 1));
  EXPECT_DOUBLE_EQ(s.measure(), 2.0);
  EXPECT_DOUBLE_EQ(s.surface_measure(), 6.0);
  expect_outward_normals(s, Vec3(1, 0.5, 0));
  expect_closed_surface(s);
  // The bottom facets point down, exactly.
  for (const Facet& f : s.surface())
    if (f.centre(s.nodes()).y() == 0.0) {
      EXPECT_EQ(f.normal, Vec3(0, -1, 0));
    }
}

TEST(StructureMesh, LeavesTheAxisOutOfTheSurfaceInAxisymmetry) {
  // [0, 2] x [0, 1] as the half-section of a disc of radius 2, height 1.
  const StructureMesh s(two_quads(), Kinematics::Axisymmetric);
  EXPECT_EQ(s.axis_facets(), 1);
  EXPECT_EQ(s.surface().size(), 5u);
  // Per radian: volume R^2 H / 2, surface (top and bottom R^2 / 2 each, side R H).
  EXPECT_DOUBLE_EQ(s.measure(), 2.0);
  EXPECT_DOUBLE_EQ(s.surface_measure(), 2.0 + 2.0 + 2.0);
  expect_closed_surface(s);
}

TEST(StructureMesh, MovesItsNodesAndTurnsItsNormals) {
  StructureMesh s(two_quads(), Kinematics::PlaneStrain);
  std::vector<Vec3> turned = s.nodes();
  for (Vec3& x : turned) x = Vec3(-x.y(), x.x(), 0);  // a quarter turn
  const std::vector<Facet> before = s.surface();
  s.move_nodes(turned);
  for (std::size_t k = 0; k < before.size(); ++k) {
    EXPECT_NEAR(s.surface()[k].normal.x(), -before[k].normal.y(), 1e-15);
    EXPECT_NEAR(s.surface()[k].normal.y(), before[k].normal.x(), 1e-15);
    EXPECT_DOUBLE_EQ(s.surface()[k].size, before[k].size);
  }
}

TEST(StructureMesh, FindsTheSixFacesOfAHexAndTheFourOfATet) {
  Mesh hex;
  hex.cell_type = CellType::Hex8;
  hex.nodes = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 1, 0), Vec3(0, 1, 0),
               Vec3(0, 0, 3), Vec3(2, 0, 3), Vec3(2, 1, 3), Vec3(0, 1, 3)};
  hex.connectivity = {0, 1, 2, 3, 4, 5, 6, 7};
  const StructureMesh h(hex, Kinematics::ThreeD);
  ASSERT_EQ(h.surface().size(), 6u);
  EXPECT_DOUBLE_EQ(h.measure(), 6.0);
  EXPECT_DOUBLE_EQ(h.surface_measure(), 2 * (2.0 + 6.0 + 3.0));
  expect_outward_normals(h, Vec3(1, 0.5, 1.5));
  expect_closed_surface(h);

  Mesh tets;  // the unit cube's corner tet and its neighbour across the face 1-2-3
  tets.cell_type = CellType::Tet4;
  tets.nodes = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, 1, 1)};
  tets.connectivity = {0, 1, 2, 3, 1, 2, 3, 4};
  // The second tet's orientation: make it positive whatever the order above gives.
  const Vec3 a = tets.nodes[1], b = tets.nodes[2], c = tets.nodes[3], d = tets.nodes[4];
  if ((b - a).cross(c - a).dot(d - a) < 0) std::swap(tets.connectivity[5], tets.connectivity[6]);
  const StructureMesh t(tets, Kinematics::ThreeD);
  EXPECT_EQ(t.surface().size(), 6u);
  EXPECT_NEAR(t.measure(), 1.0 / 6 + 1.0 / 3, 1e-14);
  expect_closed_surface(t);
}

TEST(MassProperties, OfARectangleAreThoseOfTheClosedForm) {
  const StructureMesh s(two_quads(), Kinematics::PlaneStrain);
  const MassProperties p = mass_properties(s, 3.0);
  EXPECT_DOUBLE_EQ(p.mass, 6.0);
  EXPECT_NEAR((p.centroid - Vec3(1, 0.5, 0)).norm(), 0, 1e-15);
  EXPECT_NEAR(p.inertia(2, 2), 6.0 * (4.0 + 1.0) / 12.0, 1e-13);  // m (B^2 + H^2) / 12
  // Parallel axes: about a corner, + m |s|^2.
  EXPECT_NEAR(inertia_about(p, Vec3::Zero())(2, 2), 6.0 * 5.0 / 12.0 + 6.0 * 1.25, 1e-13);
  // Axisymmetry: the disc's mass per radian rho R^2 H / 2, its centre on the axis.
  const MassProperties disc =
      mass_properties(StructureMesh(two_quads(), Kinematics::Axisymmetric), 3.0);
  EXPECT_DOUBLE_EQ(disc.mass, 3.0 * 2.0);
  EXPECT_NEAR((disc.centroid - Vec3(0, 0.5, 0)).norm(), 0, 1e-15);
}

}  // namespace
}  // namespace geompm

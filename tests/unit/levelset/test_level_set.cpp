// The density-based level set (docs/theory.md eq. 16.1) of blocks of points that fill whole unit
// cells exactly (Gauss points carrying their weights, block_of_points.hpp): the points' sums are
// then the exact integrals, so phi is +1/2 at nodes whose support is filled, 0 at nodes on the
// block's free surface (half their support filled, the surface on grid lines), -1/2 at nodes with
// no points around, to round-off; the same with the radius in axisymmetry. Nodes on the mesh's
// own boundary count only the mesh cells around them, so a block that reaches it has no zero
// level set there.
#include <gtest/gtest.h>

#include <cmath>

#include "block_of_points.hpp"
#include "geompm/levelset/level_set.hpp"

namespace geompm {
namespace {

using testing::block_mesh;
using testing::fill_block;

constexpr double round_off = 1e-13;

/// The closed form for a block below y = `top` (2D) or z = `top` (3D) filling the mesh's width:
/// +1/2 below, 0 on, -1/2 above the top's next grid line (the buffer nodes have no points).
double expected_phi(double height, double top) {
  if (height < top - 0.5) return 0.5;
  if (height < top + 0.5) return 0.0;
  return -0.5;
}

void expect_closed_form(const testing::Block& block, const LevelSet& phi, double top) {
  const int up = block.mesh.dim() - 1;
  const auto& active = block.grid->active_nodes();
  ASSERT_EQ(phi.nodal().size(), active.size());
  for (std::size_t a = 0; a < active.size(); ++a) {
    const Vec3& x = block.mesh.nodes[active[a]];
    EXPECT_NEAR(phi.nodal()[a], expected_phi(x(up), top), round_off)
        << "node " << active[a] << " at " << x.transpose();
  }
  // Nodes outside the step's active cells: -1/2.
  for (Index n = 0; n < block.mesh.num_nodes(); ++n)
    if (block.grid->node_to_active()[n] < 0) {
      EXPECT_EQ(phi.node_value(n), LevelSet::outside);
    }
}

TEST(LevelSet, Quad4BlockIsHalfInsideZeroOnItsSurfaceAndMinusHalfOutside) {
  // 4 x 5 unit cells, the block fills y < 2: its surface y = 2 is a grid line.
  auto block = fill_block(block_mesh(CellType::Quad4, {4, 5, 1}), Kinematics::PlaneStrain,
                          [](const Vec3& x) { return x.y() < 2.0 ? 0 : -1; });
  const LevelSet phi(*block->grid, block->points);
  expect_closed_form(*block, phi, 2.0);
}

TEST(LevelSet, Hex8BlockIsHalfInsideZeroOnItsSurfaceAndMinusHalfOutside) {
  auto block = fill_block(block_mesh(CellType::Hex8, {3, 2, 4}), Kinematics::ThreeD,
                          [](const Vec3& x) { return x.z() < 2.0 ? 0 : -1; });
  const LevelSet phi(*block->grid, block->points);
  expect_closed_form(*block, phi, 2.0);
}

TEST(LevelSet, AxisymmetricBlockWeighsItsSupportWithTheRadius) {
  // From the axis (r = 0) out; the points' volumes and V_I are per radian, with r.
  auto block = fill_block(block_mesh(CellType::Quad4, {3, 4, 1}), Kinematics::Axisymmetric,
                          [](const Vec3& x) { return x.y() < 3.0 ? 0 : -1; });
  const LevelSet phi(*block->grid, block->points);
  expect_closed_form(*block, phi, 3.0);
}

TEST(LevelSet, AxisymmetricBlockHasItsZeroOnAVerticalSurfaceToo) {
  // A block r in [1, 3] of a mesh r in [1, 5]: its side r = 3 is a free surface. phi counts the
  // meridian plane's area (eq. 16.1), so the node at r = 3 is 0 exactly; with the radius in both
  // sums it would be int_2^3 N r dr / int_2^4 N r dr - 1/2 = 4/9 - 1/2 = -1/18.
  auto block =
      fill_block(block_mesh(CellType::Quad4, {4, 3, 1}, Vec3(1.0, 0.0, 0.0)),
                 Kinematics::Axisymmetric, [](const Vec3& x) { return x.x() < 3.0 ? 0 : -1; });
  const LevelSet phi(*block->grid, block->points);
  const auto& active = block->grid->active_nodes();
  for (std::size_t a = 0; a < active.size(); ++a) {
    const double r = block->mesh.nodes[active[a]].x();
    EXPECT_NEAR(phi.nodal()[a], r < 2.5 ? 0.5 : (r < 3.5 ? 0.0 : -0.5), round_off) << "r " << r;
  }
}

TEST(LevelSet, CountsOnlyTheSelectedBodies) {
  // Body 0 below y = 2, body 1 (another density) from y = 2 to 3: with body 0 alone the surface
  // is at y = 2; with both at y = 3, and their densities 2 and 3 make no difference at the
  // interface y = 2 (m / rho is the points' volume; a mass-weighted rho would give 25/26 of the
  // support there, phi = 0.46).
  auto block = fill_block(block_mesh(CellType::Quad4, {3, 5, 1}), Kinematics::PlaneStrain,
                          [](const Vec3& x) { return x.y() < 2.0 ? 0 : (x.y() < 3.0 ? 1 : -1); });
  const LevelSet lower(*block->grid, block->points, {1, 0});
  const LevelSet both(*block->grid, block->points);
  const auto& active = block->grid->active_nodes();
  for (std::size_t a = 0; a < active.size(); ++a) {
    const double y = block->mesh.nodes[active[a]].y();
    EXPECT_NEAR(lower.nodal()[a], y < 1.5 ? 0.5 : (y < 2.5 ? 0.0 : -0.5), round_off) << y;
    EXPECT_NEAR(both.nodal()[a], expected_phi(y, 3.0), round_off) << y;
  }
}

TEST(LevelSet, CountsFemCellsAsFilled) {
  // The block fills y < 3, its cells below y = 2 FEM cells with no points (docs/theory.md §19.4):
  // the level set is the whole block's, +1/2 on the FEM-MPM interface y = 2 rather than 0 (the
  // false surface that counting the points alone would give there).
  auto block = fill_block(
      block_mesh(CellType::Quad4, {3, 5, 1}), Kinematics::PlaneStrain,
      [](const Vec3& x) { return x.y() < 3.0 ? 0 : -1; },
      [](const Vec3& x) { return x.y() < 2.0; });
  ASSERT_EQ(block->points.size(), 3 * 4);  // one row of MPM cells, four points each
  const LevelSet phi(*block->grid, block->points);
  expect_closed_form(*block, phi, 3.0);
}

TEST(LevelSet, InterpolatesInACellAndItsGradientPointsIntoTheBody) {
  auto block = fill_block(block_mesh(CellType::Quad4, {4, 4, 1}), Kinematics::PlaneStrain,
                          [](const Vec3& x) { return x.y() < 2.0 ? 0 : -1; });
  const LevelSet phi(*block->grid, block->points);
  // Cell 5 (x in [1, 2], y in [1, 2]): phi 1/2 at its bottom nodes, 0 at its top ones.
  const Index cell = 5;
  EXPECT_NEAR(phi.value(cell, Vec3::Zero()), 0.25, round_off);
  EXPECT_NEAR(phi.value(cell, Vec3(0.3, 1.0, 0.0)), 0.0, round_off);
  const Vec3 g = phi.gradient(cell, Vec3(0.2, -0.4, 0.0));
  EXPECT_NEAR(g.x(), 0.0, round_off);
  EXPECT_NEAR(g.y(), -0.5, round_off);  // (0 - 1/2) over the unit cell: into the body
  // Cell 13 (y in [3, 4]) has inactive top nodes: -1/2 there, -1/2 at its bottom ones too.
  EXPECT_NEAR(phi.value(13, Vec3(0.1, 0.7, 0.0)), -0.5, round_off);
  EXPECT_NEAR(phi.gradient(13, Vec3::Zero()).norm(), 0.0, round_off);
}

TEST(LevelSet, Hex8GradientPointsIntoTheBodyAtItsSide) {
  // A block filling x < 2 of a 4 x 2 x 2 mesh: its free side is x = 2.
  auto block = fill_block(block_mesh(CellType::Hex8, {4, 2, 2}), Kinematics::ThreeD,
                          [](const Vec3& x) { return x.x() < 2.0 ? 0 : -1; });
  const LevelSet phi(*block->grid, block->points);
  for (Index c = 0; c < block->mesh.num_cells(); ++c) {
    const Vec3 centre = map_to_physical(block->mesh, c, Vec3::Zero());
    if (centre.x() < 1.0 || centre.x() > 2.0) continue;  // the last filled column
    EXPECT_NEAR(phi.value(c, Vec3(1.0, 0.3, -0.2)), 0.0, round_off);
    const Vec3 g = phi.gradient(c, Vec3(0.5, 0.5, 0.5));
    EXPECT_NEAR(g.x(), -0.5, round_off);
    EXPECT_NEAR(g.y(), 0.0, round_off);
    EXPECT_NEAR(g.z(), 0.0, round_off);
  }
}

}  // namespace
}  // namespace geompm

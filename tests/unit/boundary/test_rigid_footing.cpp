// The rigid footing's penalty contact (docs/theory.md §13): the force on one point against
// eqs. 13.1-13.4, and the loaded width and area that the edge-overlap weighting makes exact. (The
// reaction of a whole confined block: tests/unit/analysis/test_rigid_footing_block.cpp.)
#include <gtest/gtest.h>

#include <cmath>

#include "geompm/boundary/rigid_footing.hpp"

namespace geompm {
namespace {

FootingPose strip_pose(double low, double high, double base) {
  FootingPose pose;
  pose.base = base;
  pose.low(0) = low;
  pose.high(0) = high;
  return pose;
}

// A soil point as the contact sees it: the centre of its domain's top, its half-lengths, kappa.
FootingContactPoint contact_point(const Vec3& position, const Vec3& half, double kappa) {
  FootingContactPoint point;
  point.position = position;
  point.half = half;
  point.kappa = kappa;
  return point;
}

TEST(RigidFootingContact, NormalForceIsKappaTimesPenetrationTimesArea) {
  const FootingPose pose = strip_pose(0.0, 0.5, 1.0);
  FootingContactPoint point = contact_point(Vec3(0.2, 0.95, 0.0), Vec3(0.05, 0.1, 0.0), 1e5);
  const Vec3 u(0.01, -0.001, 0.0);  // the domain's top at 0.95 + 0.1 - 0.001: g = 0.049
  auto c = footing_contact(pose, point, u, 2, false);
  ASSERT_TRUE(c.touching);
  EXPECT_NEAR(c.penetration, 0.049, 1e-14);
  EXPECT_NEAR(c.area, 0.1, 1e-14);  // the whole domain under the footprint
  EXPECT_NEAR(c.force.y(), 1e5 * 0.049 * 0.1, 1e-9);
  EXPECT_EQ(c.force.x(), 0.0);  // smooth: normal force only
  // Below the base: no force.
  EXPECT_FALSE(footing_contact(pose, point, Vec3(0, -0.2, 0), 2, false).touching);
  // Outside the footprint: no force.
  EXPECT_FALSE(footing_contact(pose, point, Vec3(0.4, 0, 0), 2, false).touching);

  // Rough: the horizontal slip from the anchor, relative to the footing, is held by kappa A.
  point.rough = true;
  point.anchor = Vec3(0.2, 0.0, 0.0);
  FootingPose moved = pose;
  moved.displacement = Vec3(0.004, -0.01, 0.0);
  c = footing_contact(moved, point, u, 2, false);
  EXPECT_NEAR(c.force.x(), 1e5 * 0.1 * (0.21 - 0.004 - 0.2), 1e-9);
}

TEST(RigidFootingContact, ARoughPointSticksWhereItsPathMeetsTheBase) {
  // Eq. 13.4a: a point 0.004 below the base at the start of the step (g_0 = -0.004) that has
  // moved 0.01 sideways and 0.006 up relative to the footing (g = 0.002) touched the base a third
  // of the way from its end: it slips by phi = g / (g - g_0) = 1/3 of its motion.
  const FootingPose pose = strip_pose(0.0, 0.5, 1.0);
  FootingContactPoint point = contact_point(Vec3(0.2, 0.996, 0.0), Vec3(0.05, 0.0, 0.0), 1e5);
  point.rough = true;
  point.start_gap = -0.004;
  point.anchor = Vec3(0.2, 0.0, 0.0);  // its position relative to the footing at the start
  const Vec3 u(0.01, 0.006, 0.0);
  const auto c = footing_contact(pose, point, u, 2, false);
  ASSERT_TRUE(c.on_base);
  EXPECT_NEAR(c.penetration, 0.002, 1e-15);
  EXPECT_NEAR(c.force.x(), 1e5 * 0.1 * 0.01 / 3.0, 1e-9);
  // Continuous where it touches: the stick force grows from zero with g (without eq. 13.4a it
  // would switch on at kappa A 0.01 = 100).
  const auto touching = footing_contact(pose, point, Vec3(0.01, 0.004 + 1e-12, 0.0), 2, false);
  EXPECT_LT(std::abs(touching.force.x()), 1e-6);
  // It sticks from then on where it touched: with that anchor kept (the next step's law), the
  // same motion gives the same force.
  FootingContactPoint kept = point;
  kept.anchored = true;
  kept.anchor = c.stuck_at;
  EXPECT_NEAR(c.stuck_at.x(), 0.2 + 0.01 * 2.0 / 3.0, 1e-15);
  EXPECT_NEAR(footing_contact(pose, kept, u, 2, false).force.x(), c.force.x(), 1e-9);
  // An anchored point slips by its whole motion, as before (eq. 13.4).
  EXPECT_NEAR(footing_contact(pose, kept, Vec3(0.02, 0.006, 0.0), 2, false).force.x(),
              1e5 * 0.1 * (0.22 - c.stuck_at.x()), 1e-9);
  // The tangent of eq. 13.4a (d phi / d g enters d F_x / d u_y) against central differences.
  const double e = 1e-8;
  for (int j = 0; j < 2; ++j) {
    Vec3 plus = u, minus = u;
    plus(j) += e;
    minus(j) -= e;
    const Vec3 column = (footing_contact(pose, point, plus, 2, false).force -
                         footing_contact(pose, point, minus, 2, false).force) /
                        (2 * e);
    for (int i = 0; i < 2; ++i)
      EXPECT_NEAR(c.stiffness(i, j), column(i), 1e-5 * std::abs(c.stiffness(i, i)))
          << i << ", " << j;
  }
}

TEST(RigidFootingContact, SoilHeavedBesideTheFootingIsPushedOutThroughItsSide) {
  // A domain 0.01 above the base that reaches 0.002 over the edge x = 0.5: it is pushed out
  // sideways by kappa s g (eq. 13.5), not down by kappa g o.
  const FootingPose pose = strip_pose(0.0, 0.5, 1.0);
  FootingContactPoint point = contact_point(Vec3(0.523, 1.01, 0.0), Vec3(0.025, 0.0, 0.0), 1e5);
  const auto c = footing_contact(pose, point, Vec3::Zero(), 2, false);
  ASSERT_TRUE(c.touching);
  EXPECT_FALSE(c.on_base);
  EXPECT_NEAR(c.force.x(), -1e5 * 0.002 * 0.01, 1e-9);  // f_int sign: the point is pushed to +x
  EXPECT_EQ(c.force.y(), 0.0);
  // Just under the base instead, the same domain is pressed down by the base on its overlap.
  point.position.y() = 1.001;
  const auto d = footing_contact(pose, point, Vec3::Zero(), 2, false);
  EXPECT_TRUE(d.on_base);
  EXPECT_NEAR(d.force.y(), 1e5 * 0.001 * 0.002, 1e-9);
}

TEST(RigidFootingContact, EdgeOverlapMakesTheLoadedWidthExact) {
  // A row of points whose domains tile [0, 1] (20 of them), pressed uniformly: the contact areas
  // add up to the footprint's width, wherever its edge cuts a domain.
  for (double edge : {0.45, 0.4321, 0.5, 0.0123}) {
    const FootingPose pose = strip_pose(0.0, edge, 1.0);
    double width = 0.0, force = 0.0;
    for (int k = 0; k < 20; ++k) {
      FootingContactPoint point =
          contact_point(Vec3(0.025 + 0.05 * k, 0.975, 0.0), Vec3(0.025, 0.025, 0.0), 2.0);
      const auto c = footing_contact(pose, point, Vec3(0, 0.001, 0), 2, false);
      width += c.area;
      force += c.force.y();
    }
    EXPECT_NEAR(width, edge, 1e-12);
    EXPECT_NEAR(force, 2.0 * 0.001 * edge, 1e-12);  // q = kappa g on exactly the footprint
  }
  // Axisymmetry: per radian, the areas add up to R^2 / 2.
  for (double radius : {0.45, 0.4321}) {
    const FootingPose pose = strip_pose(0.0, radius, 1.0);
    double area = 0.0;
    for (int k = 0; k < 20; ++k) {
      FootingContactPoint point =
          contact_point(Vec3(0.025 + 0.05 * k, 0.975, 0.0), Vec3(0.025, 0.025, 0.0), 1.0);
      area += footing_contact(pose, point, Vec3(0, 0.001, 0), 2, true).area;
    }
    EXPECT_NEAR(area, 0.5 * radius * radius, 1e-12);
  }
  // 3D: a plate over a corner of a tiled square; the areas add up to the plate's.
  FootingPose plate;
  plate.base = 1.0;
  plate.low = Vec3(0.13, -0.2, 0);
  plate.high = Vec3(0.61, 0.377, 0);
  double area = 0.0;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) {
      FootingContactPoint point =
          contact_point(Vec3(0.05 + 0.1 * i, 0.05 + 0.1 * j, 0.95), Vec3(0.05, 0.05, 0.05), 1.0);
      area += footing_contact(plate, point, Vec3(0, 0, 0.001), 3, false).area;
    }
  EXPECT_NEAR(area, (0.61 - 0.13) * 0.377, 1e-12);
}

}  // namespace
}  // namespace geompm

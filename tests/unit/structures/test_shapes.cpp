// The built-in shapes (structures/shapes): areas, volumes and surface measures against their
// closed forms (exactly for polygons; for circles against the inscribed polygon the mesh's own
// boundary nodes make, and within the faceting error for revolved 3D bodies), outward normals and
// a closed boundary.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geompm/structures/shapes.hpp"
#include "geompm/structures/structure_mesh.hpp"
#include "structure_test_support.hpp"

namespace geompm {
namespace {

using testing::expect_closed_surface;
using testing::expect_outward_normals;
constexpr double pi = std::numbers::pi;

spec::StructureShape shape(const std::string& kind, std::map<std::string, double> dimensions,
                           const Vec3& position = Vec3::Zero(), double h = 0.0) {
  spec::StructureShape s;
  s.kind = kind;
  s.dimensions = std::move(dimensions);
  s.position = position;
  s.cell_size = h;
  return s;
}

StructureMesh meshed(const spec::StructureShape& s, Kinematics k) {
  return StructureMesh(shape_mesh(s, k), k);
}

TEST(Shapes, AFootingIsItsRectangleExactly) {
  const auto s = shape("footing", {{"width", 2.0}, {"height", 0.5}}, Vec3(1, 3, 0), 0.2);
  const StructureMesh plane = meshed(s, Kinematics::PlaneStrain);
  EXPECT_NEAR(plane.measure(), 1.0, 1e-12);
  EXPECT_NEAR(plane.surface_measure(), 5.0, 1e-12);
  expect_outward_normals(plane, Vec3(1, 3.25, 0));
  expect_closed_surface(plane);
  // Axisymmetry: a disc of radius 1 and height 0.5: per radian R^2 H / 2 and (R^2 + R H).
  const auto disc = shape("footing", {{"width", 2.0}, {"height", 0.5}}, Vec3(0, 3, 0), 0.2);
  const StructureMesh axi = meshed(disc, Kinematics::Axisymmetric);
  EXPECT_NEAR(axi.measure(), 0.25, 1e-12);
  EXPECT_NEAR(axi.surface_measure(), 1.0 + 0.5, 1e-12);
  EXPECT_EQ(axi.axis_facets() > 0, true);
  expect_closed_surface(axi);
  // 3D: a box, breadth defaulting to the width.
  const StructureMesh box = meshed(
      shape("footing", {{"width", 2.0}, {"height", 0.5}}, Vec3(0, 0, 1), 0.4), Kinematics::ThreeD);
  EXPECT_NEAR(box.measure(), 2.0, 1e-10);
  EXPECT_NEAR(box.surface_measure(), 2 * 4.0 + 4 * 1.0, 1e-10);
  expect_outward_normals(box, Vec3(0, 0, 1.25));
  expect_closed_surface(box);
}

TEST(Shapes, ASpudcanAndAConeAreTheirProfiles) {
  // Spudcan: D = 4, tip 120 deg (tip height 2 / tan 60), shoulder 0.5, a flat top and a shaft.
  const double R = 2.0, tip = R / std::tan(pi / 3), shoulder = 0.5, r = 0.5, shaft = 1.0;
  const auto spud = shape("spudcan",
                          {{"diameter", 4.0},
                           {"tip_angle", 120.0},
                           {"shoulder", shoulder},
                           {"shaft_diameter", 2 * r},
                           {"shaft_length", shaft}},
                          Vec3(0, -1, 0), 0.25);
  const double area = R * tip + 2 * R * shoulder + 2 * r * shaft;  // full section
  const StructureMesh plane = meshed(spud, Kinematics::PlaneStrain);
  EXPECT_NEAR(plane.measure(), area, 1e-10);
  const double side = std::hypot(R, tip);
  EXPECT_NEAR(plane.surface_measure(), 2 * side + 2 * shoulder + 2 * (R - r) + 2 * shaft + 2 * r,
              1e-10);
  expect_outward_normals(plane, Vec3(0, -1 + 0.5 * tip, 0));  // convex below the shaft's foot
  expect_closed_surface(plane);
  // Axisymmetry, per radian: cone R^2 h / 6, cylinders R^2 H / 2 (Pappus).
  const StructureMesh axi = meshed(spud, Kinematics::Axisymmetric);
  EXPECT_NEAR(axi.measure(), R * R * tip / 6 + R * R * shoulder / 2 + r * r * shaft / 2, 1e-10);
  expect_closed_surface(axi);

  // Cone penetrometer: D = 1, apex 60 deg, shaft 2; 3D is faceted: within 3 %.
  const auto cone = shape("cone", {{"diameter", 1.0}, {"shaft_length", 2.0}}, Vec3::Zero(), 0.1);
  const double h = 0.5 / std::tan(pi / 6);
  EXPECT_NEAR(meshed(cone, Kinematics::Axisymmetric).measure(), 0.25 * h / 6 + 0.25 * 2.0 / 2,
              1e-12);
  const StructureMesh solid = meshed(cone, Kinematics::ThreeD);
  const double volume = pi * 0.25 * h / 3 + pi * 0.25 * 2.0;
  EXPECT_NEAR(solid.measure(), volume, 0.03 * volume);
  EXPECT_LT(solid.measure(), volume);  // inscribed facets
  expect_closed_surface(solid);
}

TEST(Shapes, APlateHasItsTip) {
  const auto plate =
      shape("plate", {{"width", 0.2}, {"length", 3.0}, {"tip", 0.2}}, Vec3(0.5, -2, 0), 0.05);
  const StructureMesh s = meshed(plate, Kinematics::PlaneStrain);
  EXPECT_NEAR(s.measure(), 0.2 * 2.8 + 0.5 * 0.2 * 0.2, 1e-12);
  double lowest = 1e9;
  for (const Vec3& x : s.nodes()) lowest = std::min(lowest, x.y());
  EXPECT_DOUBLE_EQ(lowest, -2.0);  // placed by its tip
  expect_outward_normals(s, Vec3(0.5, -0.5, 0));
  expect_closed_surface(s);
  auto wide = plate;
  wide.dimensions["breadth"] = 1.0;
  const StructureMesh pile = meshed(wide, Kinematics::ThreeD);
  EXPECT_NEAR(pile.measure(), 1.0 * (0.2 * 2.8 + 0.5 * 0.2 * 0.2), 1e-10);
  expect_closed_surface(pile);
}

// The area of a circle meshed with straight boundary segments whose nodes lie on it: pi R^2
// less, per segment subtending phi, the circular segment R^2 (phi - sin phi) / 2.
double inscribed_area(const StructureMesh& s, const Vec3& c, double R) {
  double area = pi * R * R;
  for (const Facet& f : s.surface()) {
    const Vec3 a = s.nodes()[f.nodes[0]] - c, b = s.nodes()[f.nodes[1]] - c;
    if (std::abs(a.norm() - R) > 1e-9 * R) continue;  // an inner circle
    const double phi = std::acos(std::clamp(a.dot(b) / (R * R), -1.0, 1.0));
    area -= 0.5 * R * R * (phi - std::sin(phi));
  }
  return area;
}

TEST(Shapes, APipeIsARingAndATBarADisc) {
  const Vec3 c(1, 2, 0);
  const StructureMesh bar =
      meshed(shape("tbar", {{"diameter", 0.8}}, c, 0.05), Kinematics::PlaneStrain);
  for (const Facet& f : bar.surface())
    EXPECT_NEAR((bar.nodes()[f.nodes[0]] - c).norm(), 0.4, 1e-12);
  EXPECT_NEAR(bar.measure(), inscribed_area(bar, c, 0.4), 1e-12);
  EXPECT_NEAR(bar.measure(), pi * 0.16, 0.01 * pi * 0.16);
  expect_outward_normals(bar, c);
  expect_closed_surface(bar);

  const auto pipe = shape("pipe", {{"diameter", 0.8}, {"thickness", 0.1}}, c, 0.05);
  const StructureMesh ring = meshed(pipe, Kinematics::PlaneStrain);
  EXPECT_NEAR(ring.measure(), inscribed_area(ring, c, 0.4) - inscribed_area(ring, c, 0.3), 1e-12);
  expect_closed_surface(ring);
  // The inner surface's normals point into the hole, towards the centre.
  for (const Facet& f : ring.surface())
    if ((f.centre(ring.nodes()) - c).norm() < 0.35) {
      EXPECT_LT(f.normal.dot(f.centre(ring.nodes()) - c), 0.0);
    }

  // Axisymmetry: a sphere (2 R^3 / 3 per radian) and a spherical shell.
  const auto ball = shape("pipe", {{"diameter", 0.8}}, Vec3(0, 1, 0), 0.04);
  const StructureMesh sphere = meshed(ball, Kinematics::Axisymmetric);
  EXPECT_NEAR(sphere.measure(), 2.0 / 3 * 0.064, 0.01 * 0.064);
  expect_closed_surface(sphere);
  auto hollow = ball;
  hollow.dimensions["thickness"] = 0.1;
  expect_closed_surface(meshed(hollow, Kinematics::Axisymmetric), 4);
  // 3D: a cylinder of length 2 along y.
  auto rod = shape("tbar", {{"diameter", 0.8}, {"length", 2.0}}, Vec3(0, 0, 0), 0.1);
  const StructureMesh cylinder = meshed(rod, Kinematics::ThreeD);
  EXPECT_NEAR(cylinder.measure(), pi * 0.16 * 2.0, 0.02 * pi * 0.16 * 2.0);
  expect_outward_normals(cylinder, Vec3::Zero());
  expect_closed_surface(cylinder);
}

TEST(Shapes, RefuseWhatTheyCannotMake) {
  EXPECT_THROW(shape_mesh(shape("tbar", {{"diameter", 1.0}}), Kinematics::Axisymmetric),
               std::invalid_argument);
  EXPECT_THROW(shape_mesh(shape("footing", {{"width", 1.0}}), Kinematics::PlaneStrain),
               std::invalid_argument);  // no height
  EXPECT_THROW(shape_mesh(shape("footing", {{"width", 1.0}, {"height", 1.0}}, Vec3(1, 0, 0)),
                          Kinematics::Axisymmetric),
               std::invalid_argument);  // off the axis
  EXPECT_THROW(
      shape_mesh(shape("pipe", {{"diameter", 1.0}, {"thickness", 0.5}}), Kinematics::PlaneStrain),
      std::invalid_argument);
  EXPECT_THROW(shape_mesh(shape("spudcan", {{"diameter", 1.0}, {"tip_angle", 200.0}}),
                          Kinematics::PlaneStrain),
               std::invalid_argument);
}

TEST(Shapes, MeshWithTheCellTypeAsked) {
  auto s = shape("footing", {{"width", 1.0}, {"height", 0.5}}, Vec3::Zero(), 0.1);
  for (CellType type : {CellType::Tri3, CellType::Tri6, CellType::Quad4}) {
    s.cell = type;
    const StructureMesh m = meshed(s, Kinematics::PlaneStrain);
    EXPECT_EQ(m.mesh().cell_type, type);
    EXPECT_NEAR(m.measure(), 0.5, 1e-12);
    EXPECT_NEAR(m.surface_measure(), 3.0, 1e-12);
    expect_closed_surface(m);
  }
}

}  // namespace
}  // namespace geompm

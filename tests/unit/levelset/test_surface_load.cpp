// The surface load on the zero level set (docs/theory.md §16.3). Its resultant is the load's
// integral over the facets, as the cell's shape functions sum to 1 at every Gauss point: for a
// pressure p on a chain of facets from A to B that is -p (B - A) rotated clockwise, whatever the
// chain's shape, so on a straight surface clipped to a box it is the closed form to round-off,
// and on a circle within the error of the chain's ends (test_zero_level_set.cpp bounds it). A
// pressure that varies linearly along a flat top integrates exactly (2 Gauss points), also on a
// mesh of tri3 and quad4 cells (issue 43), where a tilted line's resultant is the chord too. A
// following pressure turns with a rigid rotation of the grid (its resultant rotates, to round-off),
// and its load stiffness is the derivative of its force: compared with central differences.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "block_of_points.hpp"
#include "geompm/levelset/surface_load.hpp"
#include "geompm/physics/step_system.hpp"

namespace geompm {
namespace {

constexpr double round_off = 1e-11;

using Value = std::function<Vec3(const Vec3&)>;
Value constant(double p) {
  return [p](const Vec3&) { return Vec3(p, 0.0, 0.0); };
}

std::vector<double> nodal(const Mesh& mesh, const std::function<double(const Vec3&)>& phi) {
  std::vector<double> values;
  for (const Vec3& x : mesh.nodes) values.push_back(phi(x));
  return values;
}

/// Every cell of a mesh filled with points: every node active, whatever facets are loaded.
std::unique_ptr<testing::Block> full(CellType type, std::array<int, 3> cells, double size,
                                     Kinematics kinematics) {
  return testing::fill_block(testing::block_mesh(type, cells, Vec3::Zero(), size), kinematics,
                             [](const Vec3&) { return 0; });
}

TEST(SurfaceLoad, PressureOnATiltedLineHasTheChordRotatedAsResultant) {
  auto block = full(CellType::Quad4, {8, 8, 1}, 0.5, Kinematics::PlaneStrain);
  const double a = 1.3, b = -0.6;  // the body below y = a + b x
  const auto phi = [&](const Vec3& x) { return a + b * x.x() - x.y(); };
  FacetBox clip;
  clip.range[0] = std::array<double, 2>{0.4, 1.9};
  auto facets = zero_level_set(block->mesh, nodal(block->mesh, phi), {}, &clip);
  StepSystem system(*block->grid);
  const double p = 7.0;
  const SurfaceLoad load(*block->grid, system.dofs(), facets, SurfaceLoad::Kind::Pressure, false,
                         constant(p));
  // Chord B - A = 1.5 (1, b); the outward area vector 1.5 (-b, 1); the load -p times it.
  const Vec3 expected = -p * 1.5 * Vec3(-b, 1.0, 0.0);
  EXPECT_NEAR((load.resultant(Vector::Zero(system.dofs().size())) - expected).norm(), 0.0,
              round_off);
}

TEST(SurfaceLoad, PressureOnACircularArcHasTheChordRotatedAsResultant) {
  // As the arc of test_zero_level_set.cpp: x in [1.25, 3], y >= 2 on |x - (2, 2)| = 1.3, h = 1/4.
  const double h = 0.25, R = 1.3, p = 3.0;
  auto block = full(CellType::Quad4, {16, 16, 1}, h, Kinematics::PlaneStrain);
  const auto phi = [&](const Vec3& x) { return R - (x - Vec3(2.0, 2.0, 0.0)).norm(); };
  FacetBox clip;
  clip.range[0] = std::array<double, 2>{1.25, 3.0};
  clip.range[1] = std::array<double, 2>{2.0, 4.0};
  StepSystem system(*block->grid);
  const SurfaceLoad load(*block->grid, system.dofs(),
                         zero_level_set(block->mesh, nodal(block->mesh, phi), {}, &clip),
                         SurfaceLoad::Kind::Pressure, false, constant(p));
  const Vec3 F = load.resultant(Vector::Zero(system.dofs().size()));
  const auto height = [&](double x) { return 2.0 + std::sqrt(R * R - (x - 2.0) * (x - 2.0)); };
  const auto end_error = [&](double x) {  // test_zero_level_set.cpp: each end's height error
    const double dx = x - 2.0, dy = height(x) - 2.0;
    return h * h / 8.0 * (dx * dx / std::pow(R - h, 3)) / (dy / R);
  };
  EXPECT_NEAR(F.y(), -p * 1.75, round_off);
  EXPECT_NEAR(F.x(), p * (height(3.0) - height(1.25)), p * (end_error(1.25) + end_error(3.0)));
}

/// On facets of the line y = const over x in [0, 3]: p = 4 + 2 x gives int p dx = 21 and
/// int p x dx = 36; a traction (1 + x, 0) gives 7.5 along x. The forces are consistent: every
/// node's share is int N_a p dx, so also the moment sum_a f_a x_a.
void expect_flat_top_loads(const testing::Block& block, const StepSystem& system,
                           const std::vector<SurfaceFacet>& facets) {
  const SurfaceLoad pressure(*block.grid, system.dofs(), facets, SurfaceLoad::Kind::Pressure, false,
                             [](const Vec3& x) { return Vec3(4.0 + 2.0 * x.x(), 0.0, 0.0); });
  const Vector zero = Vector::Zero(system.dofs().size());
  EXPECT_NEAR((pressure.resultant(zero) - Vec3(0.0, -21.0, 0.0)).norm(), 0.0, round_off);
  const Vector f = pressure.force(zero);
  const int u = system.dofs().find("displacement");
  double moment = 0.0;
  for (std::size_t a = 0; a < block.grid->active_nodes().size(); ++a)
    moment +=
        f(system.dofs().dof(u, Index(a), 1)) * block.mesh.nodes[block.grid->active_nodes()[a]].x();
  EXPECT_NEAR(moment, -36.0, round_off);
  const SurfaceLoad traction(*block.grid, system.dofs(), facets, SurfaceLoad::Kind::Traction, false,
                             [](const Vec3& x) { return Vec3(1.0 + x.x(), 0.0, 0.0); });
  EXPECT_NEAR((traction.resultant(zero) - Vec3(7.5, 0.0, 0.0)).norm(), 0.0, round_off);
}

TEST(SurfaceLoad, LinearPressureAndTractionOnAFlatTopIntegrateExactly) {
  // The top y = 2 of a block on [0, 3].
  auto block =
      testing::fill_block(testing::block_mesh(CellType::Quad4, {3, 4, 1}), Kinematics::PlaneStrain,
                          [](const Vec3& x) { return x.y() < 2.0 ? 0 : -1; });
  StepSystem system(*block->grid);
  const LevelSet phi(*block->grid, block->points);
  expect_flat_top_loads(*block, system, zero_level_set(phi));
}

TEST(SurfaceLoad, OnAMixedMeshPressureAndTractionIntegrateAsTheClosedForm) {
  // The block [0, 3] x [0, 4] of tri3 cells left of x = 1.5 and quad4 cells right of it, full of
  // points; surfaces crossing both kinds of cell: the line y = 2.5 loaded as the flat top above,
  // and the tilted line y = 1.3 + 0.3 x under a constant pressure, whose resultant is the chord
  // rotated.
  auto spec = testing::block_mesh(CellType::Quad4, {3, 4, 1});
  spec.cell_type_at = [](const Vec3& x) { return x.x() < 1.5 ? CellType::Tri3 : CellType::Quad4; };
  auto block = testing::fill_block(spec, Kinematics::PlaneStrain, [](const Vec3&) { return 0; });
  ASSERT_TRUE(block->mesh.mixed());
  StepSystem system(*block->grid);
  const auto flat = zero_level_set(
      block->mesh, nodal(block->mesh, [](const Vec3& x) { return 2.5 - x.y(); }), {});
  int in_triangles = 0;
  for (const SurfaceFacet& facet : flat)
    in_triangles += block->mesh.type_of(facet.cell) == CellType::Tri3;
  EXPECT_GT(in_triangles, 0);
  EXPECT_LT(in_triangles, static_cast<int>(flat.size()));
  expect_flat_top_loads(*block, system, flat);
  const double a = 1.3, b = 0.3, p = 7.0;
  const SurfaceLoad tilted(
      *block->grid, system.dofs(),
      zero_level_set(block->mesh,
                     nodal(block->mesh, [&](const Vec3& x) { return a + b * x.x() - x.y(); }), {}),
      SurfaceLoad::Kind::Pressure, false, constant(p));
  const Vector zero = Vector::Zero(system.dofs().size());
  EXPECT_NEAR((tilted.resultant(zero) + p * 3.0 * Vec3(-b, 1.0, 0.0)).norm(), 0.0, round_off);
}

/// The block's top as a following pressure, its step system with the load's couplings.
struct Following {
  std::unique_ptr<testing::Block> block;
  std::unique_ptr<StepSystem> system;
  SurfaceLoad* load = nullptr;
};

Following following_top(CellType type, Kinematics kinematics, double p) {
  Following f;
  const bool three_d = type == CellType::Hex8;
  const int up = three_d ? 2 : 1;
  f.block = testing::fill_block(testing::block_mesh(type, {3, three_d ? 2 : 4, 4}), kinematics,
                                [&](const Vec3& x) { return x(up) < 2.0 ? 0 : -1; });
  f.system = std::make_unique<StepSystem>(*f.block->grid);
  const LevelSet phi(*f.block->grid, f.block->points);
  f.load = &f.system->add(
      std::make_unique<SurfaceLoad>(*f.block->grid, f.system->dofs(), zero_level_set(phi),
                                    SurfaceLoad::Kind::Pressure, true, constant(p)));
  f.system->build_pattern();
  return f;
}

TEST(SurfaceLoad, FollowingPressureTurnsWithARigidRotation) {
  for (Kinematics kinematics : {Kinematics::PlaneStrain, Kinematics::ThreeD}) {
    const bool three_d = kinematics == Kinematics::ThreeD;
    auto f = following_top(three_d ? CellType::Hex8 : CellType::Quad4, kinematics, 5.0);
    const DofMap& dofs = f.system->dofs();
    const int u = dofs.find("displacement");
    const Mat3 R =
        Eigen::AngleAxisd(0.7, three_d ? Vec3(0.3, -0.5, 0.8).normalized() : Vec3::UnitZ())
            .toRotationMatrix();
    const Vec3 centre(1.5, 1.0, 1.0);
    Vector du = Vector::Zero(dofs.size());
    for (std::size_t a = 0; a < f.block->grid->active_nodes().size(); ++a) {
      const Vec3 X = f.block->mesh.nodes[f.block->grid->active_nodes()[a]];
      const Vec3 moved = centre + R * (X - centre) - X;
      for (int i = 0; i < f.block->grid->dim(); ++i) du(dofs.dof(u, Index(a), i)) = moved(i);
    }
    const Vec3 F0 = f.load->resultant(Vector::Zero(dofs.size()));
    EXPECT_NEAR(F0.norm(), 5.0 * (three_d ? 6.0 : 3.0), round_off);
    EXPECT_NEAR((f.load->resultant(du) - R * F0).norm(), 0.0, round_off);
  }
}

TEST(SurfaceLoad, FollowingPressureTangentMatchesFiniteDifferences) {
  struct Case {
    CellType type;
    Kinematics kinematics;
  };
  for (const Case c : {Case{CellType::Quad4, Kinematics::PlaneStrain},
                       Case{CellType::Quad4, Kinematics::Axisymmetric},
                       Case{CellType::Hex8, Kinematics::ThreeD}}) {
    auto f = following_top(c.type, c.kinematics, 3.0);
    const DofMap& dofs = f.system->dofs();
    std::mt19937 random(7);
    std::uniform_real_distribution<double> uniform(-0.1, 0.1);
    Vector du = Vector::Zero(dofs.size());
    for (Index d = 0; d < du.size(); ++d) du(d) = uniform(random);
    SystemForces forces;
    ASSERT_TRUE(f.system->evaluate(du, forces, true));
    const Eigen::MatrixXd K = Eigen::MatrixXd(f.system->tangent());
    // Central differences of -f_ext, per free unknown: the error is O(h^2) of a quadratic (2D)
    // or cubic (3D, axisymmetric) force, 1e-12 relative at h = 1e-6 with round-off ~1e-10 / h.
    const double h = 1e-6;
    double largest = 0.0, error = 0.0;
    for (Index j = 0; j < dofs.num_free(); ++j) {
      Vector plus = du, minus = du;
      plus(dofs.dof_of_free(j)) += h;
      minus(dofs.dof_of_free(j)) -= h;
      const Vector column = -(f.load->force(plus) - f.load->force(minus)) / (2 * h);
      for (Index i = 0; i < dofs.num_free(); ++i) {
        largest = std::max(largest, std::abs(K(i, j)));
        error = std::max(error, std::abs(K(i, j) - column(dofs.dof_of_free(i))));
      }
    }
    EXPECT_GT(largest, 0.1);
    EXPECT_LT(error, 1e-8 * largest) << to_string(c.kinematics);
  }
}

}  // namespace
}  // namespace geompm

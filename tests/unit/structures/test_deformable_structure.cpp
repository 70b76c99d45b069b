// A deformable structure (structures/deformable_structure, docs/theory.md §17.7): its term's
// tangent is the derivative of its forces (central finite differences, every cell type, plane
// strain, axisymmetry and 3D, elastic and plastic, after a first step that left it strained and
// moved, with and without inertia), a uniform deformation is reproduced exactly on distorted
// meshes (the patch test: the homogeneous deformation solves the equations for any material at
// any strain), its points' displacement is the cells' interpolation, and the checkpoint restores
// it exactly.
#include <gtest/gtest.h>

#include <random>

#include "deformable_test_support.hpp"
#include "geompm/core/byte_archive.hpp"
#include "geompm/materials/material.hpp"

namespace geompm {
namespace {

struct Case {
  CellType cell;
  Kinematics kinematics;
  const char* material;
  bool dynamic;
};

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  const Case& c = info.param;
  return std::string(to_string(c.cell)) +
         (c.kinematics == Kinematics::PlaneStrain    ? "_plane_strain"
          : c.kinematics == Kinematics::Axisymmetric ? "_axisymmetric"
                                                     : "_3d") +
         "_" + c.material + (c.dynamic ? "_dynamic" : "");
}

std::unique_ptr<Material> make_material(const std::string& name) {
  if (name == "tresca")
    return create_material("tresca", {{"E", 1000.0}, {"nu", 0.3}, {"su", 2.0}, {"density", 2.0}});
  if (name == "neo_hookean")
    return create_material("neo_hookean", {{"E", 1000.0}, {"nu", 0.3}, {"density", 2.0}});
  return create_material("linear_elastic", {{"E", 1000.0}, {"nu", 0.3}, {"density", 2.0}});
}

// Two cells a side, every node moved by up to a tenth of a cell: no special geometry (and a node
// inside, for the patch test).
StructureMesh distorted_mesh(CellType type, Kinematics k, unsigned seed) {
  const bool three = k == Kinematics::ThreeD;
  Mesh m = testing::box_mesh(type, k, Vec3(1, 1, 1), {2, 2, three ? 2 : 1},
                             Vec3(k == Kinematics::Axisymmetric ? 0.5 : 0.0, 0, 0))
               .mesh();
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  for (Vec3& x : m.nodes)
    for (int i = 0; i < (three ? 3 : 2); ++i) x(i) += jitter(random);
  return StructureMesh(std::move(m), k);
}

Vector random_increment(Index size, double scale, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> u(-scale, scale);
  Vector du(size);
  for (Index k = 0; k < size; ++k) du(k) = u(random);
  return du;
}

// f_int + M a - f_ext at du (every unknown).
Vector residual(DeformableStructureTerm& term, const DofMap& dofs, const Vector& du) {
  SystemForces f;
  f.reset(dofs.size());
  EXPECT_TRUE(term.add(du, f, nullptr));
  return f.internal + f.inertia - f.external;
}

class DeformableTangent : public ::testing::TestWithParam<Case> {};

TEST_P(DeformableTangent, IsTheDerivativeOfItsForces) {
  const Case c = GetParam();
  const auto material = make_material(c.material);
  DeformableStructure s("body", distorted_mesh(c.cell, c.kinematics, 7), *material,
                        material->density());
  const Vec3 g(0, -10, c.kinematics == Kinematics::ThreeD ? -3 : 0);
  const std::optional<Newmark> newmark =
      c.dynamic ? std::optional<Newmark>(Newmark{0.25, 0.5, 0.1}) : std::nullopt;
  // A first step strains it (plastically for Tresca) and moves its nodes: the tangent is then
  // checked about a state that is not the reference one.
  for (int step = 0; step < 2; ++step) {
    DofMap dofs;
    s.add_unknowns(dofs);
    dofs.number_free();
    DeformableStructureTerm term(s, dofs, g, Vector(), newmark, 0.1);
    SparsityBuilder builder(dofs);
    term.declare_couplings(builder);
    SparseMatrix K = builder.build();
    term.attach(K);
    const Vector du = random_increment(dofs.size(), 0.01, 11 + step);
    SystemForces f;
    f.reset(dofs.size());
    ASSERT_TRUE(term.add(du, f, &K));
    if (step == 0) {
      Reactions unused;
      term.report(du, unused);
      term.commit();
      continue;
    }
    const Eigen::MatrixXd dense(K);
    const double h = 1e-7;
    double largest = dense.cwiseAbs().maxCoeff(), worst = 0.0;
    for (Index j = 0; j < dofs.size(); ++j) {
      Vector plus = du, minus = du;
      plus(j) += h;
      minus(j) -= h;
      const Vector column = (residual(term, dofs, plus) - residual(term, dofs, minus)) / (2 * h);
      worst = std::max(worst, (column - dense.col(j)).cwiseAbs().maxCoeff());
    }
    EXPECT_LT(worst, 1e-6 * largest) << "largest entry " << largest;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cells, DeformableTangent,
    ::testing::Values(Case{CellType::Tri3, Kinematics::PlaneStrain, "linear_elastic", false},
                      Case{CellType::Tri3, Kinematics::Axisymmetric, "tresca", false},
                      Case{CellType::Tri6, Kinematics::PlaneStrain, "neo_hookean", true},
                      Case{CellType::Quad4, Kinematics::PlaneStrain, "tresca", false},
                      Case{CellType::Quad4, Kinematics::Axisymmetric, "linear_elastic", true},
                      Case{CellType::Tet4, Kinematics::ThreeD, "linear_elastic", false},
                      Case{CellType::Tet4, Kinematics::ThreeD, "tresca", true},
                      Case{CellType::Hex8, Kinematics::ThreeD, "linear_elastic", false},
                      Case{CellType::Hex8, Kinematics::ThreeD, "tresca", false}),
    case_name);

class DeformablePatch : public ::testing::TestWithParam<Case> {};

TEST_P(DeformablePatch, ReproducesAUniformDeformationExactly) {
  // Boundary nodes moved by u = H X (finite: 5 % strains and a shear), the interior ones free: a
  // homogeneous deformation solves the weightless equations exactly, so the interior nodes
  // follow it to round-off and every Gauss point has the same stress. In axisymmetry
  // u = (a r, b z) is the homogeneous one.
  const Case c = GetParam();
  const auto material = make_material(c.material);
  DeformableStructure s("body", distorted_mesh(c.cell, c.kinematics, 3), *material, 0.0);
  const int dim = s.dim();
  Mat3 H;
  H << 0.05, 0.02, -0.01, -0.03, -0.04, 0.02, 0.01, 0.03, 0.02;
  if (c.kinematics == Kinematics::Axisymmetric) H = Vec3(0.05, -0.04, 0).asDiagonal();
  // The boundary nodes: those of a facet of the surface (and of the axis facets: none here).
  std::vector<char> boundary(s.num_nodes(), 0);
  for (const Facet& f : s.mesh().surface())
    for (int a = 0; a < f.num_nodes; ++a) boundary[f.nodes[a]] = 1;
  const std::vector<Vec3> X = s.mesh().nodes();
  DofMap dofs;
  s.add_unknowns(dofs);
  int interior = 0;
  for (Index a = 0; a < s.num_nodes(); ++a) {
    interior += !boundary[a];
    if (boundary[a])
      for (int i = 0; i < dim; ++i) dofs.constrain(s.dof(dofs, a, i), (H * X[a])(i));
  }
  ASSERT_GT(interior, 0);
  dofs.number_free();
  DeformableStructureTerm term(s, dofs, Vec3::Zero(), Vector(), std::nullopt, 1.0);
  Vector du;
  testing::solve_structure_step(dofs, term, du);
  for (Index a = 0; a < s.num_nodes(); ++a)
    for (int i = 0; i < dim; ++i)
      EXPECT_NEAR(du(s.dof(dofs, a, i)), (H * X[a])(i), 1e-12) << "node " << a;
  Reactions unused;
  term.report(du, unused);
  term.commit();
  const Mat3 first = s.gauss_points().front().stress;
  EXPECT_GT(first.norm(), 1.0);
  for (const GaussPointState& g : s.gauss_points())
    EXPECT_NEAR((g.stress - first).norm(), 0.0, 1e-9 * first.norm());
}

INSTANTIATE_TEST_SUITE_P(
    Cells, DeformablePatch,
    ::testing::Values(Case{CellType::Tri3, Kinematics::PlaneStrain, "linear_elastic", false},
                      Case{CellType::Tri6, Kinematics::PlaneStrain, "neo_hookean", false},
                      Case{CellType::Quad4, Kinematics::PlaneStrain, "linear_elastic", false},
                      Case{CellType::Quad4, Kinematics::Axisymmetric, "linear_elastic", false},
                      Case{CellType::Tet4, Kinematics::ThreeD, "linear_elastic", false},
                      Case{CellType::Hex8, Kinematics::ThreeD, "neo_hookean", false}),
    case_name);

TEST(DeformableStructure, InterpolatesItsPointsAndRestoresItsState) {
  const auto material = make_material("linear_elastic");
  DeformableStructure s("body", distorted_mesh(CellType::Tri6, Kinematics::PlaneStrain, 5),
                        *material, 2.0);
  DofMap dofs;
  s.add_unknowns(dofs);
  dofs.number_free();
  ASSERT_EQ(dofs.size(), 2 * s.num_nodes());
  const Vector du = random_increment(dofs.size(), 0.01, 3);
  // At a node the weights give the node's own increment; at a facet's midpoint the facet's.
  std::vector<DofWeight> weights;
  for (const Facet& f : s.mesh().surface()) {
    const Vec3 x = s.mesh().nodes()[f.nodes[2]];  // a tri6 edge's middle node
    s.displacement_weights(dofs, x, f.cell, weights);
    Vec3 u = Vec3::Zero();
    double sum = 0.0;
    for (const DofWeight& w : weights) {
      u += w.coefficient * du(w.dof);
      sum += w.coefficient.sum();
    }
    EXPECT_NEAR(sum, 2.0, 1e-12);  // the shape functions sum to one, per component
    EXPECT_NEAR(u.x(), du(s.dof(dofs, f.nodes[2], 0)), 1e-12);
    EXPECT_NEAR(u.y(), du(s.dof(dofs, f.nodes[2], 1)), 1e-12);
  }
  // The mass is the density times the area, whatever the configuration.
  EXPECT_NEAR(s.mass(), 2.0 * s.mesh().measure(), 1e-12);
  DeformableStructureTerm term(s, dofs, Vec3(0, -10, 0), Vector(), std::nullopt, 1.0);
  SystemForces f;
  f.reset(dofs.size());
  ASSERT_TRUE(term.add(du, f, nullptr));
  Reactions unused;
  term.report(du, unused);
  term.commit();
  ByteWriter out;
  s.save(out);
  DeformableStructure restored("body", distorted_mesh(CellType::Tri6, Kinematics::PlaneStrain, 5),
                               *material, 2.0);
  ByteReader in(out.bytes(), "test");
  restored.load(in);
  EXPECT_EQ(restored.mesh().nodes(), s.mesh().nodes());
  ASSERT_EQ(restored.gauss_points().size(), s.gauss_points().size());
  for (std::size_t k = 0; k < s.gauss_points().size(); ++k) {
    EXPECT_EQ(restored.gauss_points()[k].be, s.gauss_points()[k].be);
    EXPECT_EQ(restored.gauss_points()[k].stress, s.gauss_points()[k].stress);
  }
  EXPECT_EQ(restored.velocity(), s.velocity());
}

}  // namespace
}  // namespace geompm

namespace geompm {
namespace {

TEST(DeformableStructureTerm, FallsFreelyAsNewmarkIntegratesAConstantAcceleration) {
  // Nothing holds it: with the consistent mass, M (g, g, ...) is exactly its weight (eq. 17.13,
  // 17.14), so every node falls as the trapezoidal rule integrates g, unstrained.
  const auto material = make_material("linear_elastic");
  DeformableStructure s("block", distorted_mesh(CellType::Quad4, Kinematics::PlaneStrain, 9),
                        *material, 2.0);
  const Vec3 g(0, -9.81, 0);
  const double dt = 0.1;
  Vector a0 = Vector::Zero(2 * s.num_nodes());
  for (Index a = 0; a < s.num_nodes(); ++a) a0(2 * a + 1) = g.y();
  s.set_rates(Vector::Zero(a0.size()), a0);  // released at rest with its acceleration g
  for (int step = 1; step <= 4; ++step) {
    DofMap dofs;
    s.add_unknowns(dofs);
    dofs.number_free();
    DeformableStructureTerm term(s, dofs, g, Vector(), Newmark{0.25, 0.5, dt}, dt);
    Vector du;
    testing::solve_structure_step(dofs, term, du);
    Reactions unused;
    term.report(du, unused);
    term.commit();
    const double t = step * dt;
    for (Index a = 0; a < s.num_nodes(); ++a) {
      EXPECT_NEAR(s.displacement(a).y(), 0.5 * g.y() * t * t, 1e-10);
      EXPECT_NEAR(s.displacement(a).x(), 0.0, 1e-10);
    }
    for (const GaussPointState& p : s.gauss_points()) EXPECT_LT(p.stress.norm(), 1e-6);
  }
}

}  // namespace
}  // namespace geompm

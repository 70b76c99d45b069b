// Deformable structures (docs/theory.md §17.7-17.9) against closed forms: a confined column under
// its own weight (the 1D finite-strain solution of the Hencky law, plane strain, axisymmetry and
// 3D; its base carries its weight), a cantilever under a tip load (Timoshenko's beam), and a very
// stiff deformable plate pressed onto soil through contact (docs/theory.md §18) that settles as
// the rigid plate of the contact patch test does.
#include <gtest/gtest.h>

#include <Eigen/SparseLU>
#include <cmath>
#include <iostream>

#include "geompm/dofs/sparsity.hpp"
#include "geompm/io/model_reader.hpp"
#include "geompm/materials/material.hpp"
#include "geompm/mesh/structured_mesh.hpp"
#include "geompm/structures/cross_section.hpp"
#include "geompm/structures/deformable_structure_term.hpp"
#include "run_model.hpp"

namespace geompm {
namespace {

StructureMesh box(CellType type, Kinematics k, const Vec3& size, const std::array<int, 3>& cells,
                  const Vec3& origin = Vec3::Zero()) {
  StructuredMeshSpec spec;
  spec.cell_type = type;
  spec.origin = origin;
  for (int i = 0; i < 3; ++i) spec.axes[i] = {AxisSegment{size(i), cells[i], 1.0}};
  return StructureMesh(generate_structured_mesh(spec), k);
}

spec::StructureDrive held(spec::StructureNodes::Kind where, std::array<bool, 3> components) {
  spec::StructureDrive d;
  d.nodes = spec::StructureNodes{};
  d.nodes->kind = where;
  for (int i = 0; i < 3; ++i)
    if (components[i]) d.motion[i] = "0";
  return d;
}

// One quasi-static step of the structure alone, driven by `drive` and loaded by gravity g and
// the drive's forces at t = 1: Newton to round-off. Returns the drive's reaction.
DriveForces solve(DeformableStructure& s, const StructureDrive& drive, const Vec3& g) {
  DofMap dofs;
  s.add_unknowns(dofs);
  for (const DriveConstraint& c : drive.constraints(0.0, 1.0))
    dofs.constrain(s.dof(dofs, c.entity, c.component), c.value);
  dofs.number_free();
  DeformableStructureTerm term(s, dofs, g, drive.nodal_load(1.0, s.num_nodes()), std::nullopt, 1.0);
  SparsityBuilder builder(dofs);
  term.declare_couplings(builder);
  SparseMatrix K = builder.build();
  Vector du = dofs.prescribed();
  SystemForces f;
  for (int it = 0; it < 20; ++it) {
    f.reset(dofs.size());
    K.coeffs().setZero();
    EXPECT_TRUE(term.add(du, f, &K));
    Vector r;
    dofs.restrict_to_free(f.external - f.internal, r);
    if (r.cwiseAbs().maxCoeff() < 1e-13 * f.external.cwiseAbs().maxCoeff()) break;
    Eigen::SparseLU<SparseMatrix> lu(K);
    const Vector dx = lu.solve(r);
    for (Index k = 0; k < dofs.num_free(); ++k) du(dofs.dof_of_free(k)) += dx(k);
  }
  f.reset(dofs.size());
  term.add(du, f, nullptr);
  const Vector reaction = f.internal - f.external;
  Reactions unused;
  term.report(du, unused);
  const DriveForces forces = drive_forces(s, drive, dofs, reaction, 1.0);
  term.commit();
  return forces;
}

// The confined Hencky column under its weight, exactly (docs/theory.md eq. 17.16): at reference
// height Y the stretch l solves M ln(l) / l = -rho g (L - Y) (the Cauchy stress of the laterally
// confined law against the weight above, per the unchanged cross section), and u(Y) = integral of
// (l - 1) from 0 to Y (Simpson, 2000 intervals).
double column_settlement(double M, double rho_g, double L, double Y) {
  const auto stretch = [&](double y) {
    double l = 1.0;
    for (int k = 0; k < 50; ++k) {
      const double r = M * std::log(l) / l + rho_g * (L - y);
      const double dr = M * (1.0 - std::log(l)) / (l * l);
      l -= r / dr;
    }
    return l - 1.0;
  };
  const int n = 2000;
  const double h = Y / n;
  double sum = stretch(0) + stretch(Y);
  for (int k = 1; k < n; ++k) sum += (k % 2 ? 4 : 2) * stretch(k * h);
  return sum * h / 3.0;
}

struct ColumnCase {
  CellType cell;
  Kinematics kinematics;
};

class DeformableColumn : public ::testing::TestWithParam<ColumnCase> {};

TEST_P(DeformableColumn, SettlesUnderItsWeightAsTheFiniteStrainClosedForm) {
  // L = 2, E = 2000, nu = 0.3, rho g = 20: the top settles by 1.5 % of L, where the small-strain
  // rho g L^2 / (2 M) is 1 % off the finite-strain solution; the nodes must be within 1e-4 of it.
  const auto [cell, k] = GetParam();
  const double L = 2.0, E = 2000, nu = 0.3, rho = 2.0, g = 10.0;
  const double M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  const bool three = k == Kinematics::ThreeD;
  const auto material = create_material("linear_elastic", {{"E", E}, {"nu", nu}, {"density", rho}});
  const double r0 = k == Kinematics::Axisymmetric ? 0.5 : 0.0;  // a ring in axisymmetry
  const Vec3 size = three ? Vec3(0.2, 0.2, L) : Vec3(0.2, L, 0);
  // Tetrahedra a hexahedron's six, whose uneven split shears the column: finer.
  const int layers = cell == CellType::Tet4 ? 80 : 20;
  DeformableStructure s(
      "column", box(cell, k, size, {1, three ? 1 : layers, three ? layers : 1}, Vec3(r0, 0, 0)),
      *material, rho);
  using Kind = spec::StructureNodes::Kind;
  // Confined: the sides slide (x held; y too in 3D), the base is held.
  std::vector<spec::StructureDrive> given = {held(Kind::Left, {true, false, false}),
                                             held(Kind::Right, {true, false, false}),
                                             held(Kind::Bottom, {true, true, true})};
  if (three) {
    spec::StructureDrive front, back;
    front.nodes = spec::StructureNodes{Kind::Box, "", Vec3(-1, 0, -1), Vec3(1, 0, 3), {}};
    back.nodes = spec::StructureNodes{Kind::Box, "", Vec3(-1, 0.2, -1), Vec3(1, 0.2, 3), {}};
    front.motion[1] = back.motion[1] = "0";
    given.push_back(front);
    given.push_back(back);
  }
  std::vector<const spec::StructureDrive*> drives;
  for (const auto& d : given) drives.push_back(&d);
  const StructureDrive drive(drives, s.mesh());
  const int up = three ? 2 : 1;
  const Vec3 gravity = -g * Vec3::Unit(up);
  const DriveForces reaction = solve(s, drive, gravity);
  double worst = 0.0;
  const double top = column_settlement(M, rho * g, L, L);
  for (Index a = 0; a < s.num_nodes(); ++a) {
    const double Y = s.initial_nodes()[a](up);
    worst = std::max(worst, std::abs(s.displacement(a)(up) - column_settlement(M, rho * g, L, Y)));
  }
  // Tet4: the six tetrahedra of a hexahedron are not symmetric about its axis and shear the
  // column a little (7e-4 of the settlement on 80 layers, 3e-3 on 20, first order).
  EXPECT_LT(worst, (cell == CellType::Tet4 ? 2e-3 : 1e-4) * std::abs(top))
      << "top settles by " << top;
  std::cout << "worst node error / top settlement " << worst / std::abs(top) << "\n";
  // The small-strain closed form is 1 % off, so this test tells them apart.
  EXPECT_GT(std::abs(top + rho * g * L * L / (2 * M)), 5e-3 * std::abs(top));
  // The base carries the weight (per radian in axisymmetry).
  const double area = k == Kinematics::Axisymmetric ? 0.5 * ((r0 + 0.2) * (r0 + 0.2) - r0 * r0)
                      : three                       ? 0.04
                                                    : 0.2;
  EXPECT_NEAR(reaction.force(up), rho * g * L * area, 1e-9 * rho * g * L * area);
  ::testing::Test::RecordProperty("worst_node_error_relative",
                                  std::to_string(worst / std::abs(top)));
}

INSTANTIATE_TEST_SUITE_P(Kinematics, DeformableColumn,
                         ::testing::Values(ColumnCase{CellType::Quad4, Kinematics::PlaneStrain},
                                           ColumnCase{CellType::Tri6, Kinematics::PlaneStrain},
                                           ColumnCase{CellType::Quad4, Kinematics::Axisymmetric},
                                           ColumnCase{CellType::Hex8, Kinematics::ThreeD},
                                           ColumnCase{CellType::Tet4, Kinematics::ThreeD}),
                         [](const ::testing::TestParamInfo<ColumnCase>& info) {
                           const Kinematics k = info.param.kinematics;
                           return std::string(to_string(info.param.cell)) +
                                  (k == Kinematics::PlaneStrain    ? "_plane_strain"
                                   : k == Kinematics::Axisymmetric ? "_axisymmetric"
                                                                   : "_3d");
                         });

TEST(DeformableCantilever, BendsUnderATipLoadAsTimoshenkosBeam) {
  // L = 10, h = 1, E = 1e6, nu = 0 (plane strain is then plane stress), P = 1 shared by the tip
  // nodes, clamped at x = 0 (every node held); tri6, 40 x 4 rectangles. Timoshenko: delta =
  // P L^3 / (3 E I) + P L / (k G A), k = 5/6: 4.024e-3 (Euler-Bernoulli alone 4.000e-3, 0.6 %
  // less). Measured 4.02405e-3. The tolerance, 0.2 %, covers the fully held root, which is
  // stiffer than the beam theory's clamp (its warping held), and the mesh, and tells Timoshenko
  // from Euler-Bernoulli; delta / L = 4e-4 leaves the large-rotation terms at 1e-7.
  const double L = 10, h = 1, E = 1e6, P = 1.0;
  const auto material =
      create_material("linear_elastic", {{"E", E}, {"nu", 0.0}, {"density", 0.0}});
  DeformableStructure s("beam",
                        box(CellType::Tri6, Kinematics::PlaneStrain, Vec3(L, h, 0), {40, 4, 1}),
                        *material, 0.0);
  using Kind = spec::StructureNodes::Kind;
  spec::StructureDrive clamp = held(Kind::Left, {true, true, false}), tip;
  tip.nodes = spec::StructureNodes{Kind::Right, "", Vec3::Zero(), Vec3::Zero(), {}};
  tip.load[1] = "-1";
  const StructureDrive drive({&clamp, &tip}, s.mesh());
  const DriveForces reaction = solve(s, drive, Vec3::Zero());
  double tip_deflection = 0.0;
  int count = 0;
  for (Index a = 0; a < s.num_nodes(); ++a)
    if (std::abs(s.initial_nodes()[a].x() - L) < 1e-9) {
      tip_deflection += -s.displacement(a).y();
      ++count;
    }
  tip_deflection /= count;
  const double I = h * h * h / 12, G = E / 2, A = h;
  const double timoshenko = P * L * L * L / (3 * E * I) + P * L / (5.0 / 6.0 * G * A);
  EXPECT_NEAR(tip_deflection, timoshenko, 0.002 * timoshenko) << "delta " << tip_deflection;
  ::testing::Test::RecordProperty("tip_over_timoshenko",
                                  std::to_string(tip_deflection / timoshenko));
  // The drive's reaction, over every node: the clamp's +P and the tip's load -P balance.
  EXPECT_NEAR(reaction.force.y(), 0.0, 1e-9);
  // The section's mean normal stress: the bending stress averages out, up to the sampling of
  // the cells' mean stresses (1 % of the largest bending stress at mid-span, 6 P (L / 2) / h^2).
  const SectionStress mid = section_stress(s, Vec3(0.5 * L + 0.1, 0.5, 0), Vec3(1, 0, 0));
  EXPECT_NEAR(mid.measure, h, 1e-6);  // in the deformed configuration
  EXPECT_NEAR(mid.mean_normal_stress, 0.0, 0.01 * 3 * P * L / (h * h));
  std::cout << "tip deflection " << tip_deflection << " Timoshenko " << timoshenko << "\n";
}

// The contact patch test of examples/structures/contact_patch.yaml with the plate deformable and
// 10^4 times stiffer than the block, pressed on its top nodes by the same force.
const char* kDeformablePlate = R"m(
analysis: {kinematics: plane_strain}
mesh:
  generate: {cell: quad4, origin: [0, 0], x: {length: 1, cells: 4}, y: {length: 1.5, cells: 6}}
materials:
  soil: {model: linear_elastic, E: 10000, nu: 0.3, density: 0}
  steel: {model: linear_elastic, E: 1.0e8, nu: 0.3, density: 1}
bodies:
  block: {material: soil, region: {box: {min: [0, 0], max: [1, 1]}}, points_per_cell: 4}
structures:
  - name: plate
    shape: {type: footing, width: 1, height: 0.1, position: [0.5, 1.0], cell: quad4, cell_size: 0.05}
    deformable: {material: steel}
phases:
  - name: press
    duration: 1.0
    time_step: {initial: 0.25, min: 0.001, max: 0.25}
    structures:
      plate: {nodes: top, displacement: [0, ~], force: [~, "-100*t"]}
    fixities:
      - {boundary: left, fix: normal}
      - {boundary: right, fix: normal}
      - {boundary: bottom, fix: all}
output:
  history:
    - {quantity: displacement, structure: plate, nodes: top, component: y, name: plate_uy}
    - {quantity: contact_force, structure: plate, component: y, name: contact_fy}
    - {quantity: reaction, boundary: bottom, component: y, name: base_reaction}
    - {quantity: section_stress, structure: plate, section: {point: [0.5, 1.05], normal: [0, 1]}, name: plate_stress}
)m";

TEST(DeformableStructureContact, AVeryStiffPlateSettlesAsTheRigidOne) {
  // The rigid plate of the patch test, and the deformable one 10^4 times stiffer than the soil:
  // the same settlement within 1e-3 (the plate's own compression, F h / E = 1e-7, and its
  // bending under the soil's reaction are far below), the same contact force, and inside the
  // plate the mean vertical stress over its mid-plane is -F / B.
  const auto rigid =
      testing::run_spec(testing::read_example("structures/contact_patch.yaml"), "patch_rigid");
  const auto deformable = testing::run_spec(
      read_model_from_string(kDeformablePlate, "deformable_plate.yaml"), "patch_deformable");
  const double F = 100.0;
  const double rigid_uy = rigid.column("plate_uy").back();
  const double uy = deformable.column("plate_uy").back();
  EXPECT_NEAR(uy, rigid_uy, 1e-3 * std::abs(rigid_uy)) << "rigid " << rigid_uy;
  EXPECT_NEAR(deformable.column("contact_fy").back(), F, 1e-6 * F);
  EXPECT_NEAR(deformable.column("base_reaction").back(), F, 1e-6 * F);
  EXPECT_NEAR(deformable.column("plate_stress").back(), -F, 1e-2 * F);
  ::testing::Test::RecordProperty("settlement_ratio", std::to_string(uy / rigid_uy));
}

}  // namespace
}  // namespace geompm

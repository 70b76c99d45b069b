// The assembled tangent of the grid system against a finite difference of its internal force,
// for standard MPM, DDMP and GIMP, in plane strain, axisymmetry and 3D, with points spread over
// several cells and some held by prescribed-motion springs, in the displacement and the mixed p-u
// formulation (docs/theory.md eqs. 3.9, 5.1, 6.1, 8.2, 9.1-9.5, 11.1-11.7), and with the penalty
// contact of a smooth or rough rigid footing (eqs. 12.1-12.6). GIMP points are moved
// off their seeding positions first, so that their domains straddle cell boundaries (and the axis
// and mesh boundary, where they are clipped).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <random>

#include "geompm/boundary/rigid_footing.hpp"
#include "geompm/interpolation/gimp_weights.hpp"
#include "geompm/physics/exact_pressure_projection.hpp"
#include "grid_harness.hpp"
#include "grid_test_choices.hpp"
#include "run_model.hpp"

namespace geompm {
namespace {

using testing::MaterialChoice;
using testing::mixed_tresca;
using testing::mohr_coulomb_parameters;
using testing::scatter_points;
using testing::tresca_parameters;

enum class FootingChoice { None, Smooth, Rough };

void check_assembled_tangent(const std::string& example, GridInterpolation interpolation,
                             const MaterialChoice* choice = nullptr,
                             FootingChoice footing = FootingChoice::None,
                             std::optional<CellType> cell = std::nullopt) {
  auto spec = testing::read_example(example);
  if (cell) {  // the example's generated mesh, other cells (the model's own interpolation: the
               // settings below give the one under test)
    spec.mesh.generate->cell_type = *cell;
    spec.numerics.interpolation = spec::Interpolation::Standard;
  }
  if (choice)
    for (auto& material : spec.materials) {
      material.model = choice->model;
      material.parameters = choice->parameters;
    }
  auto model = build_model(spec);
  if (interpolation == GridInterpolation::Gimp) scatter_points(*model, 0.6);
  // A volume mismatch carried from earlier steps (eqs. 14.2 and 11.8), different at every point,
  // so that the field-pressure and incremental cases check its share of the residual and of K_pu.
  for (Index p = 0; p < model->points.size(); ++p)
    model->points.volume_mismatch[p] = 0.01 * std::sin(1.0 + p);
  GridSettings settings;
  settings.kinematics = spec.kinematics;
  settings.empty_cell_modulus = 1e-3 * model->largest_modulus();
  // The ghost penalty (eq. 6.3) couples nodes of neighbouring cells that share no cell: the
  // pattern must hold them, whatever the stencils. Every edge cell carries it, however filled.
  settings.ghost_penalty = 0.05;
  settings.ghost_penalty_fill = 1.0;
  settings.interpolation = interpolation;
  if (choice) {
    settings.mixed.assign(spec.materials.size(), choice->mixed);
    settings.volume_average.assign(spec.materials.size(), choice->volume_average);
    settings.mixed_field_pressure = choice->field_pressure;
    settings.mixed_incremental_pressure = choice->incremental_pressure;
  }
  testing::GridHarness grid(model->mesh, model->topology, model->material_pointers(), settings);
  grid.initialise(model->points);
  // Prescribed-motion springs on every fifth point (eq. 5.1), through the point's weights.
  const Index n_points = model->points.size();
  std::vector<double> stiffness(n_points, 0.0);
  std::vector<Vec3> target(n_points, Vec3(1e-3, -2e-3, 5e-4));
  std::vector<unsigned char> mask(n_points, 0);
  for (Index p = 0; p < n_points; p += 5) {
    stiffness[p] = 10 * model->largest_modulus();
    mask[p] = p % 2 ? 2 : 7;
  }
  grid.set_point_targets(stiffness, target, mask);

  // A rigid footing pressed into the top of the body (eqs. 12.1-12.6): its base half a domain
  // below the top of the highest points' domains, its footprint over the middle of the body (from
  // the axis in axisymmetry) with edges that cut through point domains, so that overlaps, their
  // derivatives and (rough) slip from offset anchors are all exercised.
  const int dim = model->mesh.dim(), v = dim - 1;
  const bool axisymmetric = spec.kinematics == Kinematics::Axisymmetric;
  std::vector<FootingContactPoint> contact(n_points);
  std::vector<Vec3> offset(n_points, Vec3::Zero());
  FootingPose pose;
  if (footing != FootingChoice::None) {
    Vec3 low = Vec3::Constant(1e30), high = Vec3::Constant(-1e30);
    double top = -1e30, half_v = 0.0;
    for (Index p = 0; p < n_points; ++p) {
      const auto& pts = model->points;
      contact[p].half =
          particle_half_lengths(pts.initial_half_size[p], pts.deformation_gradient[p], dim);
      offset[p](v) = contact[p].half(v);  // the law acts at the top of the point's domain
      offset[p](0) = 0.3 * contact[p].half(0);
      contact[p].position = pts.position[p] + offset[p];
      contact[p].half(v) = 0.0;
      contact[p].kappa = 10 * model->largest_modulus() / offset[p](v);
      contact[p].rough = footing == FootingChoice::Rough;
      contact[p].anchor = pts.position[p] + Vec3(2e-3, -1e-3, 1.5e-3) * (p % 3 - 1.0);
      // Every other point first touches within the step, from below the base (eq. 13.4a).
      contact[p].anchored = p % 2 == 0;
      if (!contact[p].anchored) contact[p].start_gap = -0.4 * offset[p](v);
      low = low.cwiseMin(pts.position[p] - contact[p].half);
      high = high.cwiseMax(pts.position[p] + contact[p].half);
      if (contact[p].position(v) > top) {
        top = contact[p].position(v);
        half_v = offset[p](v);
      }
    }
    pose.base = top - 0.5 * half_v;
    for (int t = 0; t < v; ++t) {
      const double w = high(t) - low(t);
      pose.low(t) = axisymmetric ? 0.0 : low(t) + 0.31 * w;
      pose.high(t) = low(t) + 0.57 * w;
    }
    pose.displacement = Vec3(1e-3, 2e-3, -1e-3);
    grid.set_point_force_law(
        std::vector<char>(n_points, 1), offset, [&](Index p, const Vec3& u, Vec3& f, Mat3& K) {
          const auto c = footing_contact(pose, contact[p], u, dim, axisymmetric);
          f = c.force;
          K = c.stiffness;
        });
  }
  grid.set_constraints(std::vector<char>(grid.num_dofs(), 0));

  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Vector du(grid.num_dofs());
  for (Index d = 0; d < du.size(); ++d) du(d) = 1e-3 * u(rng);
  Vector f;
  SparseMatrix K;
  ASSERT_TRUE(grid.internal_force(model->points, du, f, &K));
  const Eigen::MatrixXd dense = Eigen::MatrixXd(K);

  const double h = 1e-7;
  double worst = 0.0;
  for (Index j = 0; j < du.size(); j += 3) {  // every third column keeps the test fast
    Vector plus = du, minus = du, fp, fm;
    plus(j) += h;
    minus(j) -= h;
    ASSERT_TRUE(grid.internal_force(model->points, plus, fp, nullptr));
    ASSERT_TRUE(grid.internal_force(model->points, minus, fm, nullptr));
    const Vector column = (fp - fm) / (2 * h);
    worst = std::max(
        worst, (dense.col(grid.free_index()[j]) - column).norm() / std::max(column.norm(), 1e-12));
  }
  EXPECT_LT(worst, 1e-5) << example << " (interpolation " << int(interpolation) << ")"
                         << (choice ? " " + choice->model : "");
}

// Plastic flow and a non-zero pressure field in the mixed formulation: random increments of the
// scaled pressure unknowns as large as the displacements give pressures of the order of the
// stresses, so every block of eqs. 11.3-11.4 and the stabilisation (11.5) is exercised.
const MaterialChoice mixed_mohr_coulomb{"mohr_coulomb", mohr_coulomb_parameters, true, true};
// The material evaluated at the field's pressure (theory eqs. 14.1-14.3), with the cell's or each
// point's own volume change: the solved volume's rate enters every block.
const MaterialChoice field_pressure_mohr_coulomb{"mohr_coulomb", mohr_coulomb_parameters, true,
                                                 true, true};
const MaterialChoice field_pressure_own_mohr_coulomb{"mohr_coulomb", mohr_coulomb_parameters, true,
                                                     false, true};
const MaterialChoice field_pressure_tresca{"tresca", tresca_parameters, true, false, true};
// The pressure equation's change over the step (eqs. 11.8-11.9): the carried mismatch enters K_pu
// through the point's volume change.
const MaterialChoice incremental_tresca{"tresca", tresca_parameters, true, false, false, true};
const MaterialChoice incremental_mohr_coulomb{
    "mohr_coulomb", mohr_coulomb_parameters, true, true, false, true};
// The displacement formulation with the cell's volume change (formulation: f_bar): the tangent
// gains eq. 12.5 with the whole stress rate q, not only its deviator.
const MaterialChoice f_bar_tresca{"tresca", tresca_parameters, false, true};
const MaterialChoice f_bar_mohr_coulomb{"mohr_coulomb", mohr_coulomb_parameters, false, true};

TEST(GridSystemTangent, MixedTrescaPlaneStrain) {
  check_assembled_tangent("oedometer/oedometer.yaml", GridInterpolation::Standard, &mixed_tresca);
}
TEST(GridSystemTangent, MixedMohrCoulombPlaneStrain) {
  check_assembled_tangent("oedometer/oedometer.yaml", GridInterpolation::Standard,
                          &mixed_mohr_coulomb);
}
TEST(GridSystemTangent, MixedTrescaAxisymmetric) {
  check_assembled_tangent("column/column_axisymmetric.yaml", GridInterpolation::Standard,
                          &mixed_tresca);
}
TEST(GridSystemTangent, MixedTrescaDualDomain) {
  check_assembled_tangent("oedometer/oedometer.yaml", GridInterpolation::DualDomain, &mixed_tresca);
}
TEST(GridSystemTangent, MixedMohrCoulombGimp) {
  check_assembled_tangent("oedometer/oedometer.yaml", GridInterpolation::Gimp, &mixed_mohr_coulomb);
}
TEST(GridSystemTangent, MixedMohrCoulomb3D) {
  check_assembled_tangent("column/column_3d.yaml", GridInterpolation::Standard,
                          &mixed_mohr_coulomb);
}

TEST(GridSystemTangent, IncrementalPressureTrescaPlaneStrain) {
  check_assembled_tangent("oedometer/oedometer.yaml", GridInterpolation::Standard,
                          &incremental_tresca);
}
TEST(GridSystemTangent, IncrementalPressureTrescaAxisymmetric) {
  check_assembled_tangent("column/column_axisymmetric.yaml", GridInterpolation::Standard,
                          &incremental_tresca);
}
TEST(GridSystemTangent, IncrementalPressureMohrCoulombGimp) {
  check_assembled_tangent("oedometer/oedometer.yaml", GridInterpolation::Gimp,
                          &incremental_mohr_coulomb);
}
TEST(GridSystemTangent, IncrementalPressureMohrCoulomb3D) {
  check_assembled_tangent("column/column_3d.yaml", GridInterpolation::Standard,
                          &incremental_mohr_coulomb);
}

TEST(GridSystemTangent, FieldPressureMohrCoulombPlaneStrain) {
  check_assembled_tangent("oedometer/oedometer.yaml", GridInterpolation::Standard,
                          &field_pressure_mohr_coulomb);
}
TEST(GridSystemTangent, FieldPressureOwnVolumeMohrCoulombPlaneStrain) {
  check_assembled_tangent("oedometer/oedometer.yaml", GridInterpolation::Standard,
                          &field_pressure_own_mohr_coulomb);
}
TEST(GridSystemTangent, FieldPressureMohrCoulombGimp) {
  check_assembled_tangent("oedometer/oedometer.yaml", GridInterpolation::Gimp,
                          &field_pressure_mohr_coulomb);
}
TEST(GridSystemTangent, FieldPressureTrescaAxisymmetric) {
  check_assembled_tangent("column/column_axisymmetric.yaml", GridInterpolation::Standard,
                          &field_pressure_tresca);
}
TEST(GridSystemTangent, FieldPressureMohrCoulomb3D) {
  check_assembled_tangent("column/column_3d.yaml", GridInterpolation::Standard,
                          &field_pressure_mohr_coulomb);
}
TEST(GridSystemTangent, FBarMohrCoulombPlaneStrain) {
  check_assembled_tangent("oedometer/oedometer.yaml", GridInterpolation::Standard,
                          &f_bar_mohr_coulomb);
}
TEST(GridSystemTangent, FBarTrescaAxisymmetric) {
  check_assembled_tangent("column/column_axisymmetric.yaml", GridInterpolation::Standard,
                          &f_bar_tresca);
}
TEST(GridSystemTangent, FBarMohrCoulombDualDomain) {
  check_assembled_tangent("oedometer/oedometer.yaml", GridInterpolation::DualDomain,
                          &f_bar_mohr_coulomb);
}
TEST(GridSystemTangent, FBarTrescaGimp) {
  check_assembled_tangent("oedometer/oedometer.yaml", GridInterpolation::Gimp, &f_bar_tresca);
}
TEST(GridSystemTangent, FBarMohrCoulomb3D) {
  check_assembled_tangent("column/column_3d.yaml", GridInterpolation::Standard,
                          &f_bar_mohr_coulomb);
}
TEST(GridSystemTangent, FBarRigidFootingRoughPlaneStrain) {
  check_assembled_tangent("oedometer/oedometer.yaml", GridInterpolation::Standard, &f_bar_tresca,
                          FootingChoice::Rough);
}

TEST(GridSystemTangent, RigidFootingSmoothPlaneStrain) {
  check_assembled_tangent("oedometer/oedometer.yaml", GridInterpolation::Standard, nullptr,
                          FootingChoice::Smooth);
}
TEST(GridSystemTangent, RigidFootingRoughMixedPlaneStrain) {
  check_assembled_tangent("oedometer/oedometer.yaml", GridInterpolation::Standard, &mixed_tresca,
                          FootingChoice::Rough);
}
TEST(GridSystemTangent, RigidFootingRoughGimpPlaneStrain) {
  check_assembled_tangent("oedometer/oedometer.yaml", GridInterpolation::Gimp, nullptr,
                          FootingChoice::Rough);
}
TEST(GridSystemTangent, RigidFootingSmoothAxisymmetric) {
  check_assembled_tangent("column/column_axisymmetric.yaml", GridInterpolation::Standard,
                          &mixed_tresca, FootingChoice::Smooth);
}
TEST(GridSystemTangent, RigidFootingRoughAxisymmetric) {
  check_assembled_tangent("column/column_axisymmetric.yaml", GridInterpolation::Standard, nullptr,
                          FootingChoice::Rough);
}
TEST(GridSystemTangent, RigidFootingRoughThreeD) {
  check_assembled_tangent("column/column_3d.yaml", GridInterpolation::Standard, nullptr,
                          FootingChoice::Rough);
}

TEST(GridSystemTangent, StandardPlaneStrain) {
  check_assembled_tangent("oedometer/oedometer.yaml", GridInterpolation::Standard);
}
TEST(GridSystemTangent, DualDomainPlaneStrain) {
  check_assembled_tangent("oedometer/oedometer.yaml", GridInterpolation::DualDomain);
}
TEST(GridSystemTangent, DualDomainAxisymmetric) {
  check_assembled_tangent("column/column_axisymmetric.yaml", GridInterpolation::DualDomain);
}
// DDMP's smoothed gradients (docs/theory.md §8) on every cell type that carries points.
TEST(GridSystemTangent, DualDomainTri3) {
  check_assembled_tangent("oedometer/oedometer.yaml", GridInterpolation::DualDomain, nullptr,
                          FootingChoice::None, CellType::Tri3);
}
TEST(GridSystemTangent, DualDomainTet4) {
  check_assembled_tangent("column/column_3d.yaml", GridInterpolation::DualDomain, nullptr,
                          FootingChoice::None, CellType::Tet4);
}
TEST(GridSystemTangent, DualDomainHex8) {
  check_assembled_tangent("column/column_3d.yaml", GridInterpolation::DualDomain);
}
TEST(GridSystemTangent, DualDomainMixedMohrCoulombTri3) {
  check_assembled_tangent("oedometer/oedometer.yaml", GridInterpolation::DualDomain,
                          &mixed_mohr_coulomb, FootingChoice::None, CellType::Tri3);
}
TEST(GridSystemTangent, DualDomainFBarMohrCoulombTet4) {
  check_assembled_tangent("column/column_3d.yaml", GridInterpolation::DualDomain,
                          &f_bar_mohr_coulomb, FootingChoice::None, CellType::Tet4);
}
TEST(GridSystemTangent, GimpPlaneStrain) {
  check_assembled_tangent("oedometer/oedometer.yaml", GridInterpolation::Gimp);
}
TEST(GridSystemTangent, GimpAxisymmetric) {
  check_assembled_tangent("column/column_axisymmetric.yaml", GridInterpolation::Gimp);
}
TEST(GridSystemTangent, GimpThreeD) {
  check_assembled_tangent("column/column_3d.yaml", GridInterpolation::Gimp);
}

}  // namespace
}  // namespace geompm

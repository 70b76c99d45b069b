// The assembled tangent of the grid system against a finite difference of its internal force,
// for standard MPM, DDMP and GIMP, in plane strain, axisymmetry and 3D, with points spread over
// several cells and some held by prescribed-motion springs, in the displacement and the mixed p-u
// formulation (docs/theory.md eqs. 3.9, 5.1, 6.1, 8.2, 9.1-9.5, 11.1-11.7). GIMP points are moved
// off their seeding positions first, so that their domains straddle cell boundaries (and the axis
// and mesh boundary, where they are clipped).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <random>

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

void check_assembled_tangent(const std::string& example, GridInterpolation interpolation,
                             const MaterialChoice* choice = nullptr,
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
    settings.field_pressure.assign(spec.materials.size(), choice->field_pressure);
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
                          CellType::Tri3);
}
TEST(GridSystemTangent, DualDomainTet4) {
  check_assembled_tangent("column/column_3d.yaml", GridInterpolation::DualDomain, nullptr,
                          CellType::Tet4);
}
TEST(GridSystemTangent, DualDomainHex8) {
  check_assembled_tangent("column/column_3d.yaml", GridInterpolation::DualDomain);
}
TEST(GridSystemTangent, DualDomainMixedMohrCoulombTri3) {
  check_assembled_tangent("oedometer/oedometer.yaml", GridInterpolation::DualDomain,
                          &mixed_mohr_coulomb, CellType::Tri3);
}
TEST(GridSystemTangent, DualDomainFBarMohrCoulombTet4) {
  check_assembled_tangent("column/column_3d.yaml", GridInterpolation::DualDomain,
                          &f_bar_mohr_coulomb, CellType::Tet4);
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

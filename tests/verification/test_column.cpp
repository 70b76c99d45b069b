// Elastic column under self-weight: Coombs & Augarde (2020), AMPLE §5.1
// (docs/references.md §2), as plane strain, an axisymmetric cylinder and in 3D.
// Runs the models of examples/column/ with GIMP (column.yaml shows it; the other examples run
// standard MPM, the default), and the same models with standard MPM and DDMP for comparison.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "column_closed_form.hpp"
#include "run_model.hpp"

namespace geompm {
namespace {

struct ColumnErrors {
  double stress_error = 0.0;      // sum |sigma_p - sigma(Y_p)| V0_p / sum rho0 g l0 V0_p
  double settlement_error = 0.0;  // relative, mean of the top point set
  double total_weight = 0.0;
};

ColumnErrors column_errors(const Model& model, const testing::Column& column, int vertical) {
  const auto& p = model.points;
  ColumnErrors e;
  double numerator = 0.0, denominator = 0.0, u = 0.0, u_exact = 0.0, w = 0.0;
  for (Index i = 0; i < p.size(); ++i) {
    const double Y = p.initial_position[i](vertical);
    numerator += std::abs(p.stress[i](vertical, vertical) - column.stress(Y)) * p.initial_volume[i];
    denominator += column.density * column.gravity * column.height * p.initial_volume[i];
    e.total_weight += p.mass[i] * column.gravity;
    if (p.sets[i] & 1u) {  // the "top" point set
      u += p.mass[i] * p.displacement[i](vertical);
      u_exact += p.mass[i] * column.displacement(Y);
      w += p.mass[i];
    }
  }
  e.stress_error = numerator / denominator;
  e.settlement_error = std::abs(u / w - u_exact / w) / std::abs(u_exact / w);
  return e;
}

struct ColumnCase {
  const char* file;
  int vertical;
  const char* name;
};

class ColumnTest : public ::testing::TestWithParam<ColumnCase> {};

// Gravity in one load step: the points do not cross cells within a step, so this checks the
// finite-strain formulation (Hencky law, updated Lagrangian Newton) against the closed form.
TEST_P(ColumnTest, OneLoadStepMatchesTheHenckyClosedForm) {
  auto spec = testing::read_example(GetParam().file);
  auto& phase = spec.phases.at(0);
  phase.time_step.initial = phase.time_step.max = phase.duration;
  const auto run = testing::run_spec(spec, std::string("column_one_step_") + GetParam().name);
  ASSERT_EQ(run.summary.steps, 1);
  const testing::Column column;
  const auto e = column_errors(*run.model, column, GetParam().vertical);
  std::printf("[column %s, one step] stress error %.4f, settlement error %.4f %%\n",
              GetParam().file, e.stress_error, 100 * e.settlement_error);
  EXPECT_LT(e.settlement_error, 0.01);
  // Piecewise-constant stress in cells of height h over a linear field: the mean point error is
  // about h / (4 l0) = 2 / 200 = 0.01 of rho0 g l0 with two point rows per cell.
  EXPECT_LT(e.stress_error, 0.012);

  // Newton converges quadratically (docs/references.md §7): r_{k+1} <= 10 r_k^2 over the last
  // iterations.
  const auto& r = run.summary.residual_histories.at(0);
  ASSERT_LE(r.size(), 11u);
  ASSERT_GE(r.size(), 3u);
  std::string history;
  for (double value : r) {
    history += ' ';  // not " " + string: GCC 12 warns (-Wrestrict, wrongly) about that
    history += std::to_string(value);
  }
  // Pairs in the asymptotic range and above the round-off floor (about 1e-13 here) count.
  int checked = 0;
  for (std::size_t k = 0; k + 1 < r.size(); ++k)
    if (r[k] < 1e-2 && r[k + 1] > 1e-13) {
      EXPECT_LE(r[k + 1], 10 * r[k] * r[k]) << "iteration " << k << ", residuals" << history;
      ++checked;
    }
  EXPECT_GE(checked, 1) << "residuals" << history;
  EXPECT_LE(r.back(), 1e-9);
}

spec::Model standard_mpm(const char* file) {
  auto spec = testing::read_example(file);
  spec.numerics.interpolation = spec::Interpolation::Standard;
  return spec;
}

// Gravity ramped in 20 load steps: points cross cells. Standard MPM does not converge on this
// problem (error about 0.06 - 0.1 at every h, docs/references.md §2); the measured errors are
// reported in docs/validation.md. Equilibrium and mass conservation hold exactly.
TEST_P(ColumnTest, RampedGravityKeepsEquilibriumAndStaysInTheStandardMpmBand) {
  const auto run = testing::run_spec(standard_mpm(GetParam().file),
                                     std::string("column_ramped_") + GetParam().name);
  const testing::Column column;
  const auto e = column_errors(*run.model, column, GetParam().vertical);
  std::printf("[column %s, 20 steps] stress error %.4f, settlement error %.3f %%\n",
              GetParam().file, e.stress_error, 100 * e.settlement_error);
  const auto reaction = run.column("base_reaction");
  EXPECT_NEAR(reaction.back(), e.total_weight, 1e-8 * e.total_weight);
  EXPECT_LT(e.stress_error, 0.1);
  EXPECT_LE(run.summary.max_iterations_in_a_step, 10);
}

INSTANTIATE_TEST_SUITE_P(Column, ColumnTest,
                         ::testing::Values(ColumnCase{"column/column.yaml", 1, "plane_strain"},
                                           ColumnCase{"column/column_axisymmetric.yaml", 1,
                                                      "axisymmetric"},
                                           ColumnCase{"column/column_3d.yaml", 2, "three_d"}),
                         [](const auto& info) { return std::string(info.param.name); });

// DDMP smooths the gradients so that a point crossing a cell boundary makes no jump: the stress
// error of the ramped column drops below that of standard MPM (seed §3.6: "DDMP results show less
// pollution of gradient quantities, such as stresses").
TEST(ColumnDualDomain, StressErrorBelowStandardMpm) {
  const auto standard = standard_mpm("column/column.yaml");
  auto ddmp = standard;
  ddmp.numerics.interpolation = spec::Interpolation::DualDomain;
  const testing::Column column;
  const auto a = testing::run_spec(standard, "column_standard");
  const auto b = testing::run_spec(ddmp, "column_ddmp");
  const auto ea = column_errors(*a.model, column, 1), eb = column_errors(*b.model, column, 1);
  std::printf(
      "[column 20 steps] stress error standard %.4f, DDMP %.4f; settlement error %.2f %% vs "
      "%.2f %%\n",
      ea.stress_error, eb.stress_error, 100 * ea.settlement_error, 100 * eb.settlement_error);
  EXPECT_LT(eb.stress_error, 0.8 * ea.stress_error);
  EXPECT_LT(eb.settlement_error, ea.settlement_error);
  EXPECT_NEAR(b.column("base_reaction").back(), eb.total_weight, 1e-8 * eb.total_weight);
}

// E = 10 kPa: 52 % compression, standard MPM. The run must finish with Newton in at most 10
// iterations per step and exact equilibrium; its settlement error is reported in
// docs/validation.md.
TEST(ColumnLargeDeformation, FinishesInEquilibrium) {
  const auto run =
      testing::run_spec(standard_mpm("column/column_large_deformation.yaml"), "column_large");
  testing::Column column;
  column.youngs_modulus = 10.0;
  const auto e = column_errors(*run.model, column, 1);
  std::printf("[column E = 10 kPa, 20 steps] stress error %.4f, settlement error %.3f %%\n",
              e.stress_error, 100 * e.settlement_error);
  EXPECT_NEAR(run.column("base_reaction").back(), e.total_weight, 1e-8 * e.total_weight);
  EXPECT_LE(run.summary.max_iterations_in_a_step, 10);
  EXPECT_NEAR(column.displacement(50.0), -25.9404, 1e-3);  // docs/references.md §2 table
}

// GIMP (docs/theory.md §9) on the examples: gravity in 20 equal load steps, Hencky
// law. The targets: top settlement within 1 % of the closed form for E = 1 MPa and
// within 2 % for E = 10 kPa (52 % compression, settlement -25.94 m, docs/references.md §2), in
// plane strain, axisymmetry and 3D. Literature: GIMP converges on this problem where standard MPM
// does not (Coombs & Augarde 2020, AMPLE §5.1; docs/references.md §2).
struct GimpCase {
  const char* file;
  int vertical;
  double youngs_modulus;
  double settlement_target;
  const char* name;
};

class ColumnGimpTest : public ::testing::TestWithParam<GimpCase> {};

TEST_P(ColumnGimpTest, RampedGravityMeetsTheSettlementTarget) {
  const GimpCase& c = GetParam();
  auto spec = testing::read_example(c.file);
  spec.numerics.interpolation = spec::Interpolation::Gimp;
  spec.materials.at(0).parameters.at("E") = c.youngs_modulus;
  const auto run = testing::run_spec(spec, std::string("column_gimp_") + c.name);
  ASSERT_EQ(run.summary.steps, 20);
  testing::Column column;
  column.youngs_modulus = c.youngs_modulus;
  const auto e = column_errors(*run.model, column, c.vertical);
  std::printf(
      "[column GIMP %s, E = %g kPa, 20 steps] stress error %.4f, settlement error %.3f %%\n",
      c.name, c.youngs_modulus, e.stress_error, 100 * e.settlement_error);
  // Issue targets: 1 % (E = 1 MPa), 2 % (E = 10 kPa); docs/references.md §2 closed form.
  EXPECT_LT(e.settlement_error, c.settlement_target);
  // Far below standard MPM's 0.035 - 0.08 at this mesh (docs/validation.md §2).
  EXPECT_LT(e.stress_error, 0.01);
  EXPECT_NEAR(run.column("base_reaction").back(), e.total_weight, 1e-8 * e.total_weight);
  EXPECT_LE(run.summary.max_iterations_in_a_step, 10);
}

INSTANTIATE_TEST_SUITE_P(
    Column, ColumnGimpTest,
    ::testing::Values(
        GimpCase{"column/column.yaml", 1, 1000.0, 0.01, "plane_strain_1MPa"},
        GimpCase{"column/column_axisymmetric.yaml", 1, 1000.0, 0.01, "axisymmetric_1MPa"},
        GimpCase{"column/column_3d.yaml", 2, 1000.0, 0.01, "three_d_1MPa"},
        GimpCase{"column/column_large_deformation.yaml", 1, 10.0, 0.02, "plane_strain_10kPa"},
        GimpCase{"column/column_axisymmetric.yaml", 1, 10.0, 0.02, "axisymmetric_10kPa"},
        GimpCase{"column/column_3d.yaml", 2, 10.0, 0.02, "three_d_10kPa"}),
    [](const auto& info) { return std::string(info.param.name); });

// GIMP converges with the mesh (docs/references.md §2: stress error about 1e-3 at h = 1.56 m, rate
// about 2 on coarse meshes; Coombs & Augarde 2020, AMPLE §5.1): halving h from 2 m to 1 m divides
// the stress error by more than 2, and at h = 1 m it is within 2e-3.
TEST(ColumnGimp, StressErrorFallsWithTheMesh) {
  double previous = 0.0;
  for (int cells : {26, 52}) {
    auto spec = testing::read_example("column/column.yaml");
    spec.mesh.generate->axes[1] = {{52.0, cells, 1.0}};
    const auto run = testing::run_spec(spec, "column_gimp_h" + std::to_string(cells));
    const auto e = column_errors(*run.model, testing::Column{}, 1);
    std::printf("[column GIMP, h = %g m] stress error %.4f, settlement error %.3f %%\n",
                52.0 / cells, e.stress_error, 100 * e.settlement_error);
    if (previous > 0.0) {
      EXPECT_LT(e.stress_error, previous / 2);
      EXPECT_LT(e.stress_error, 2e-3);
    }
    previous = e.stress_error;
  }
}

}  // namespace
}  // namespace geompm

// Models written without `formulation:` take the formulation that suits their materials
// (analysis/material_formulation.hpp, docs/user-guide.md "materials"; issue 45), each checked
// here against a closed form on a model that the former default, the displacement formulation
// everywhere, locks on or stops (docs/validation.md §22):
// - Tresca clay at nu = 0.4999 on quad4 (mixed p-u by default): the rigid strips of
//   examples/structures/ within 5 % of Prandtl's 2 + pi at 0.1 B and in the mean over 0.08-0.1 B
//   (the displacement formulation carries about 8 x, validation.md §4);
// - linear elastic at nu = 0.499 (mixed p-u by default from nu = 0.45): the thick cylinder of
//   examples/thick_cylinder/ made elastic, within 1 % of Lamé's pressure (the displacement
//   formulation +77 % on its 5 cells across the wall), and at nu = 0.3 (still the displacement
//   formulation) within 1 % too;
// - Mohr-Coulomb with isochoric flow (psi = 0; F-bar by default): the stiff c-phi strip of
//   validation.md §8 levels off within 5 % of Prandtl-Reissner's N_c (the displacement
//   formulation stops at 0.00056 B).
// The three take about a minute on one core.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "example_text.hpp"
#include "footing_run.hpp"
#include "prandtl_reissner.hpp"
#include "run_model.hpp"

namespace geompm {
namespace {

using testing::prandtl_reissner_nc;
using testing::replace_once;

constexpr double kPrandtl = 2.0 + std::numbers::pi;  // Prandtl (1921)

TEST(DefaultFormulation, TrescaStripsAtNu04999CarryPrandtlsLoad) {
  // Measured: q/s_u at 0.1 B rough 5.17, smooth 5.24 (validation.md §4).
  for (const char* kind : {"rough", "smooth"}) {
    const std::string example = std::string("structures/strip_footing_") + kind + ".yaml";
    std::string text = testing::no_vtk(testing::example_text(example));
    ASSERT_EQ(text.find("formulation:"), std::string::npos) << example << " gives a formulation";
    text = replace_once(text, "nu: 0.49, density: 0}", "nu: 0.4999, density: 0}");
    const auto& f =
        testing::run_footing(text, std::string("default_tresca_") + kind, /*scale=*/2.0);
    const double q = f.q_at(0.1), mean = f.q_mean(0.08, 0.1);
    std::printf(
        "[%s rigid strip, nu 0.4999, no formulation key] q/s_u %.3f at 0.1 B, %.3f over "
        "0.08-0.1 B (2 + pi = %.3f)\n",
        kind, q, mean, kPrandtl);
    EXPECT_NEAR(q / kPrandtl, 1.0, 0.05) << kind;
    EXPECT_NEAR(mean / kPrandtl, 1.0, 0.05) << kind;
  }
}

// Lamé: a tube a < r < b in plane strain, its inner face moved out by u_a, its outer face free:
// u = A r + C / r with sigma_rr(b) = 0, so p = -sigma_rr(a) = 2 mu C (1/a^2 - 1/b^2).
double lame_pressure(double E, double nu, double a, double b, double u_a) {
  const double mu = E / (2 * (1 + nu)), lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  const double C = u_a / (mu * a / ((lambda + mu) * b * b) + 1 / a);
  return 2 * mu * C * (1 / (a * a) - 1 / (b * b));
}

TEST(DefaultFormulation, NearlyIncompressibleElasticTubeFollowsLame) {
  // The example's tube (a = 1 m, b = 2 m, a slice H = 0.1 m between rollers, axisymmetric) made
  // linear elastic, with no formulation key, 5 cells across the wall, expanded by 1e-4 m (small
  // strain). Measured: +0.22 % at nu = 0.499 (the displacement formulation +77 %), +0.48 % at 0.3.
  const double E = 5000, a = 1, b = 2, H = 0.1, u_a = 1e-4;
  for (const double nu : {0.3, 0.499}) {
    char elastic[120];
    std::snprintf(elastic, sizeof elastic,
                  "clay: {model: linear_elastic, E: %g, nu: %g, density: 0}", E, nu);
    auto text = testing::example_text("thick_cylinder/thick_cylinder.yaml");
    text = replace_once(
        text, "clay: {model: tresca, su: 1, E: 5000, nu: 0.49, density: 0, formulation: mixed}",
        elastic);
    text = replace_once(text, "x: {length: 1.2, cells: 24}", "x: {length: 1.2, cells: 6}");
    text = replace_once(text, "\"0.01*t\"", "\"0.0001*t\"");
    text = replace_once(text, "vtk: {every: 5}", "vtk: {every: 0}");
    const auto run = testing::run_spec(read_model_from_string(text, "elastic_tube.yaml"),
                                       "default_elastic_tube_" + std::to_string(nu));
    const double p = std::abs(run.column("force").back()) / (a * H);
    const double exact = lame_pressure(E, nu, a, b, u_a);
    std::printf("[elastic tube, nu %g, no formulation key] p = %.6g, Lamé %.6g (%+.2f %%)\n", nu, p,
                exact, 100 * (p / exact - 1));
    EXPECT_NEAR(p / exact, 1.0, 0.01) << "nu = " << nu;
  }
}

TEST(DefaultFormulation, IsochoricMohrCoulombStripLevelsOffAtPrandtlReissnersNc) {
  // The c-phi strip of examples/mohr_coulomb_footing/ (phi = 20 deg, h = B/20) in the
  // rigid-plastic limit of validation.md §8 (E = 5e4 c, pushed 0.002 B), with psi = 0. N_c is
  // exact for associated flow; non-associated flow can only lower the limit load, and the target
  // of issue 45 is N_c within 5 %. Measured +0.5 %, +0.16 % over the last 0.0004 B (524 steps).
  const double Nc = prandtl_reissner_nc(20.0);  // 14.83
  std::string text =
      testing::no_vtk(testing::example_text("mohr_coulomb_footing/mohr_coulomb_footing.yaml"));
  ASSERT_EQ(text.find("formulation:"), std::string::npos);
  text = replace_once(text, "psi: 20, E: 1000,", "psi: 0, E: 50000,");
  text = replace_once(text, "\"-0.05*t\"", "\"-0.002*t\"");
  // Up to 20 Newton iterations a step, as measured (the stiff soil's steps converge slowly).
  text = testing::with_newton(text, "max_iterations: 20");
  const auto& f = testing::run_footing(text, "default_mohr_coulomb_psi0", /*scale=*/-2.0);
  const double q = f.q_at(0.002), rise = q / f.q_at(0.0016) - 1.0;
  std::printf(
      "[c-phi strip, phi 20, psi 0, no formulation key] q/c = %.3f at 0.002 B (%+.1f %% "
      "of N_c = %.2f), %+.2f %% over the last 0.0004 B\n",
      q, 100 * (q / Nc - 1), Nc, 100 * rise);
  EXPECT_NEAR(q / Nc, 1.0, 0.05);
  EXPECT_LT(std::abs(rise), 0.01);  // levelled off
}

}  // namespace
}  // namespace geompm

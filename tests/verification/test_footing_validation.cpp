// Footings against bearing-capacity theory (docs/references.md §3; docs/validation.md
// §4-§8): the models of examples/strip_footing/, structures/ and mohr_coulomb_footing/ on
// their own mesh (10 cells under the footing's half-width, h = B/20) and, for the rigid-plastic
// limit, on h = B/10 and B/40 too; each run taking 2-40 s, the whole file about five minutes on
// one core. What is asserted, and why:
// - the mixed p-u answer does not depend on nu (0.49 against 0.4999, < 2 %, references §3) and
//   Newton stays at <= 10 iterations per step through plastic flow (issue 3);
// - the displacement formulation locks at nu = 0.4999 (q/s_u far above Prandtl's 2 + pi) while
//   the mixed one stays within the O(h) over-estimate the mesh study measured (docs/validation.md
//   §5);
// - Mohr-Coulomb (phi = 20, associated) against Prandtl-Reissner's N_c = 14.83: the example
//   (E = 1000 c) within the over-estimate measured on this mesh at 0.05 B, a check of the model's
//   behaviour; and in the rigid-plastic limit (E = 5e4 c, h = B/10, B/20, B/40, no point crossing
//   a cell) the bearing capacity itself: the meshes level off, the over-estimate falls with h,
//   and the Richardson extrapolation lands within 3 % of N_c (docs/validation.md §8).
// - the displacement formulation with each cell's volume change (formulation: f_bar, docs/theory.md
//   §12) does not lock: the steel block's mean over 0.08-0.1 B in the band at both nu;
// - the rigid footings (rigid structures in level-set contact, examples/structures/, docs/theory.md
//   §17-§18), whose loaded width is exactly B: q/s_u at 0.1 B and its mean over 0.08-0.1 B within
//   5 % of Prandtl's at both nu, the means < 2 % apart (docs/validation.md §4);
// - no checkerboard in the nodal pressure of the three strip footings at 0.1 B with the
//   incremental pressure equation and its fitted start (the amplitude of the checkerboard mode,
//   read back from the grid file with meshio), which the total pressure equation does show;
// - in the rigid-plastic limit (stiff clay, no point crossing a cell, §5) the rigid footings
//   level off above 2 + pi, fall with h, and smooth <= rough;
// - with the incremental pressure equation (docs/theory.md eqs. 11.8-11.9): standard MPM carrying
//   the large-deformation strip to 1 B (docs/validation.md §6). The steel block uses it started
//   from the fitted last pressure (eq. 11.11).
// Not asserted: the footings at h = B/40 (with the total pressure equation below the band with
// 2x2 points per cell, whose quadrature is too soft after cell crossings, with 3x3 points they
// converge from above; with the examples' incremental equation and fitted start the steel block
// is in the band; docs/validation.md §5) and with more points per cell at h = B/20 (above the
// band, §5).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "example_text.hpp"
#include "footing_run.hpp"
#include "measured_settings.hpp"
#include "prandtl_reissner.hpp"
#include "read_vtu.hpp"
#include "richardson.hpp"
#include "run_model.hpp"
#include "strip_mesh.hpp"

namespace geompm {
namespace {

using testing::Footing;
using testing::incremental_pressure;
using testing::no_vtk;
using testing::prandtl_reissner_nc;
using testing::run_footing;

constexpr double kPrandtl =
    2.0 + std::numbers::pi;  // q_u / s_u of a rigid strip on Tresca soil (Prandtl 1921)

// The steel-block example with the code's default pressure equation (total, eq. 11.2) and start
// (the points' rebuild, eq. 11.6) instead of its incremental one from the fitted start
// (eqs. 11.8-11.11), as the former report script did (the same edit).
std::string default_numerics(std::string text) {
  text = testing::with_numerics(text, "mixed_pressure_start", "points");
  return testing::with_numerics(text, "mixed_pressure_equation", "total");
}

// The examples' clay: the steel block's example gives `formulation: mixed` (with its pressure
// equation), the rigid structures' take it as the default for tresca.
const std::string kClay = "nu: 0.49, density: 0";

// The strip footings: the rough steel block of examples/strip_footing (driven through its points),
// and the smooth and rough rigid structures of examples/structures (level-set contact, docs/
// theory.md §17-§18).
enum class Strip { SteelBlock, RigidSmooth, RigidRough };

std::string strip(Strip kind, double nu, const char* formulation) {
  auto text =
      testing::example_text(kind == Strip::SteelBlock    ? "strip_footing/strip_footing.yaml"
                            : kind == Strip::RigidSmooth ? "structures/strip_footing_smooth.yaml"
                                                         : "structures/strip_footing_rough.yaml");
  // The steel block with the settings of the measurements below (measured_settings.hpp); the
  // rigid structures as they are, with the defaults.
  if (kind == Strip::SteelBlock) text = testing::as_measured_steel_block(text);
  char clay[100];
  std::snprintf(clay, sizeof clay, "nu: %g, density: 0, formulation: %s", nu, formulation);
  // Outside the mixed formulation without the settings of its pressure equation.
  const auto model = testing::replace_once(
      text, kClay + (kind == Strip::SteelBlock ? ", formulation: mixed" : "}"),
      clay + std::string(kind == Strip::SteelBlock ? "" : "}"));
  return no_vtk(std::string(formulation) == "mixed" ? model : default_numerics(model));
}

// q / s_u = 2 x force / (B s_u): half of a strip of width B = 1, s_u = 1 (the reaction is upward
// on the soil, negative on the steel block; the contact force on a structure is upward).
constexpr double kStripScale = -2.0;
constexpr double kContactStripScale = 2.0;
double strip_scale(Strip kind) {
  return kind == Strip::SteelBlock ? kStripScale : kContactStripScale;
}

TEST(StripFootingValidation, MixedPUDoesNotDependOnNuAndNewtonStaysAtTenIterations) {
  // The steel block only; the rigid footings are asserted in their own test below.
  for (const bool rough : {true}) {
    const auto& a = run_footing(strip(Strip::SteelBlock, 0.49, "mixed"),
                                rough ? "rough_049" : "smooth_049", kStripScale);
    const auto& b = run_footing(strip(Strip::SteelBlock, 0.4999, "mixed"),
                                rough ? "rough_04999" : "smooth_04999", kStripScale);
    const double qa = a.q_at(0.1), qb = b.q_at(0.1);
    std::printf("[%s strip, p-u, 0.1 B] q/s_u = %.3f (nu 0.49), %.3f (nu 0.4999)\n",
                rough ? "rough" : "smooth", qa, qb);
    // docs/references.md §3: a locking-free answer moves by < 2 % between nu = 0.49 and 0.4999.
    EXPECT_LT(std::abs(qb / qa - 1.0), 0.02) << (rough ? "rough" : "smooth");
    // Issue 3: Newton converges in at most 10 iterations per step through plastic flow.
    EXPECT_LE(a.max_iterations(), 10) << (rough ? "rough" : "smooth");
    EXPECT_LE(b.max_iterations(), 10) << (rough ? "rough" : "smooth");
    // Issue 3 / docs/references.md §3: q/s_u between 5.14 (Prandtl's 2 + pi, an exact limit load)
    // and 5.40 at a settlement of 0.1 B, with 10 cells under the half-width (h = B/20); measured
    // 5.35 and 5.36 with the example's incremental pressure equation and fitted start (5.19 and
    // 5.25 with the total equation; docs/validation.md §4).
    for (const double q : {qa, qb}) {
      EXPECT_GE(q, kPrandtl) << (rough ? "rough" : "smooth");
      EXPECT_LE(q, 5.40) << (rough ? "rough" : "smooth");
    }
  }
}

TEST(StripFootingValidation, RigidStructuresCarryPrandtlsLoadAtBothNu) {
  // The rigid footings touch the soil through level-set contact along their base, so the loaded
  // width is B (docs/theory.md §18) and the O(h) over-estimate of the steel block's edge is gone.
  // Their curves oscillate by about +-3 % as points cross cells, so besides the value at 0.1 B the
  // mean over 0.08-0.1 B is checked. Measured (docs/validation.md §4, §17) at 0.1 B, nu = 0.49 /
  // 0.4999: smooth 5.09 / 5.24, rough 5.17 / 5.17; means over 0.08-0.1 B: smooth 5.07 / 5.10,
  // rough 5.22 / 5.20. The smooth one's values at 0.1 B differ by 2.9 % (a cell crossing there);
  // its means agree.
  struct Pair {
    const Footing& stiff;  // nu = 0.4999
    const Footing& soft;   // nu = 0.49
  };
  const auto run = [](Strip kind, double nu, const std::string& name) -> const Footing& {
    return run_footing(strip(kind, nu, "mixed"), name, strip_scale(kind));
  };
  const Pair smooth{run(Strip::RigidSmooth, 0.4999, "rigid_smooth_04999"),
                    run(Strip::RigidSmooth, 0.49, "rigid_smooth_049")};
  const Pair rough{run(Strip::RigidRough, 0.4999, "rigid_rough_04999"),
                   run(Strip::RigidRough, 0.49, "rigid_rough_049")};
  for (const auto& [name, pair] : {std::pair{"smooth", smooth}, std::pair{"rough", rough}}) {
    const double q_soft = pair.soft.q_at(0.1), q_stiff = pair.stiff.q_at(0.1);
    const double m_soft = pair.soft.q_mean(0.08, 0.1), m_stiff = pair.stiff.q_mean(0.08, 0.1);
    std::printf(
        "[rigid strip, %s, p-u] q/s_u at 0.1 B %.3f (nu 0.49), %.3f (nu 0.4999); mean over "
        "0.08-0.1 B %.3f, %.3f\n",
        name, q_soft, q_stiff, m_soft, m_stiff);
    // Issue 42: within 5 % of Prandtl at a settlement of 0.1 B, at both nu, and in the mean.
    for (const double q : {q_soft, q_stiff, m_soft, m_stiff})
      EXPECT_NEAR(q / kPrandtl, 1.0, 0.05) << name;
    // The locking-free target: the mean moves by < 2 % between nu = 0.49 and 0.4999 (measured
    // 0.7 % smooth, 0.3 % rough); the rough one's value at 0.1 B too (0.0 %).
    EXPECT_LT(std::abs(m_stiff / m_soft - 1.0), 0.02) << name;
  }
  EXPECT_LT(std::abs(rough.stiff.q_at(0.1) / rough.soft.q_at(0.1) - 1.0), 0.02);
  // At most 10 Newton iterations a step for the rough one (measured 9-10); the smooth one takes
  // 11-15 in a few steps where points cross cells under its edge (validation.md §17: not reached).
  EXPECT_LE(rough.soft.max_iterations(), 10);
  EXPECT_LE(rough.stiff.max_iterations(), 10);
}

// The model (without VTK files, as strip() gives it) writing its grid and points at the end of
// each phase only.
std::string final_vtk_only(const std::string& text) {
  return testing::replace_once(text, "vtk: {every: 0}", "vtk: {every: 1000000}");
}

// The amplitude of the checkerboard mode in the nodal pressure a strip run ends with, over the
// uniform fine region under the footing's final base (0 <= x <= 1, 4 <= y <= 4.9, h = B/20):
// A = RMS(d2x d2y p / 16) / RMS(p) over the nodes whose 3x3 neighbourhood lies in the region,
// d2x d2y p / 16 the stencil (1, -2, 1) x (1, -2, 1) / 16, which is 1 for a pure +-1 checkerboard
// and 0 for any f(x) + g(y) (docs/validation.md §4).
double checkerboard_mode(const Footing& f) {
  std::vector<std::filesystem::path> grids;
  for (const auto& e : std::filesystem::directory_iterator(f.output / "vtk"))
    if (e.path().filename().string().rfind("grid_", 0) == 0 && e.path().extension() == ".vtu")
      grids.push_back(e.path());
  if (grids.empty()) throw std::runtime_error("no grid file in " + f.output.string());
  const auto vtu = testing::read_with_meshio(*std::max_element(grids.begin(), grids.end()));
  constexpr double h = 0.05;
  std::map<std::pair<long, long>, double> p;  // (i, j) on the h-grid -> nodal pressure
  const auto& pressure = vtu.point_data.at("pressure").rows;
  for (std::size_t n = 0; n < vtu.points.size(); ++n) {
    const double x = vtu.points[n][0], y = vtu.points[n][1];
    if (x < -1e-9 || x > 1.0 + 1e-9 || y < 4.0 - 1e-9 || y > 4.9 + 1e-9) continue;
    p[{std::lround(x / h), std::lround(y / h)}] = pressure[n][0];
  }
  double mode2 = 0.0, value2 = 0.0;
  int count = 0;
  for (const auto& [ij, value] : p) {
    double mode = 0.0;
    bool complete = true;
    for (int di = -1; di <= 1 && complete; ++di)
      for (int dj = -1; dj <= 1 && complete; ++dj) {
        const auto it = p.find({ij.first + di, ij.second + dj});
        complete = it != p.end();
        if (complete) mode += (di == 0 ? -2.0 : 1.0) * (dj == 0 ? -2.0 : 1.0) * it->second / 16.0;
      }
    if (!complete) continue;
    mode2 += mode * mode;
    value2 += value * value;
    ++count;
  }
  if (count == 0) throw std::runtime_error("no node with a complete 3x3 neighbourhood");
  return std::sqrt(mode2 / value2);
}

TEST(StripFootingValidation, ExamplesNodalPressureHasNoCheckerboardMode) {
  // Issue 3: no checkerboard pressure field. The three strip footings at nu = 0.4999 with the
  // incremental pressure equation and the fitted start (docs/theory.md eqs. 11.8-11.11; the
  // steel block's example carries them, the rigid structures are given them here) keep the
  // checkerboard mode of the nodal pressure under a tenth of the pressure at 0.1 B; measured
  // (docs/validation.md §4): steel block 0.027, smooth rigid 0.072, rough rigid 0.072 (with the
  // default total equation 0.21 and 0.33).
  for (const auto kind : {Strip::SteelBlock, Strip::RigidSmooth, Strip::RigidRough}) {
    auto text = strip(kind, 0.4999, "mixed");
    if (kind != Strip::SteelBlock)
      text = testing::with_numerics(incremental_pressure(text), "mixed_pressure_start", "fitted");
    const auto& f =
        run_footing(final_vtk_only(text), "checkerboard_" + std::to_string(static_cast<int>(kind)),
                    strip_scale(kind));
    ASSERT_TRUE(std::isfinite(f.q_at(0.1))) << static_cast<int>(kind);  // reached 0.1 B
    const double a = checkerboard_mode(f);
    std::printf("[strip example %d, nu 0.4999] checkerboard mode A = %.3f at 0.1 B\n",
                static_cast<int>(kind), a);
    EXPECT_LT(a, 0.1) << static_cast<int>(kind);
  }
  // The measure sees the checkerboard the total pressure equation (the default, eq. 11.2) grows
  // as the points cross cells: the steel block with it, measured A = 0.23. On the example's own
  // steps (at most 0.0125 of the push) the oscillation inverts a point under the footing at
  // 0.074 B; the control runs on steps twice as long, which reach 0.1 B.
  const auto& total = run_footing(
      final_vtk_only(testing::replace_once(
          default_numerics(strip(Strip::SteelBlock, 0.4999, "mixed")),
          "initial: 0.0125, min: 0.0001, max: 0.0125", "initial: 0.025, min: 0.0001, max: 0.025")),
      "checkerboard_total", kStripScale);
  ASSERT_TRUE(std::isfinite(total.q_at(0.1)));
  const double a_total = checkerboard_mode(total);
  std::printf("[strip example 0, total equation, nu 0.4999] checkerboard mode A = %.3f\n", a_total);
  EXPECT_GT(a_total, 0.1);
}

// The rigid structures of `smooth_file` and `rough_file` (examples/structures) in the
// rigid-plastic limit their references assume: the clay made stiff (E = 1e4 s_u instead of 500 s_u)
// and pushed 0.005 B (or D) forms its mechanism before any soil point crosses a cell
// (docs/validation.md §5, §7), so each mesh levels off at the limit load of its discretisation.
// Checked on h = 1/10 and 1/20 of the width against the exact limit loads (smooth, rough):
// levelled off, above them (the O(h) over-estimate of bilinear cells), falling with h, and smooth
// <= rough. With the defaults (the total pressure equation).
void check_rigid_plastic_limit(const char* smooth_file, const char* rough_file, double scale,
                               double exact_smooth, double exact_rough) {
  std::map<std::pair<int, int>, double> q;  // (rough?, n) -> q/s_u at 0.005 B
  for (const int rough : {0, 1})
    for (int n : {5, 10}) {
      auto text = testing::replace_once(
          testing::replace_once(
              testing::strip_mesh(no_vtk(testing::example_text(rough ? rough_file : smooth_file)),
                                  n),
              "E: 500,", "E: 10000,"),
          "\"-0.1*t\"", "\"-0.005*t\"");
      // The stiff clay's steps end in a slowly converging tail: the cap of 10 iterations lifted
      // to 20.
      text = text.find("max_iterations: 10,") != std::string::npos
                 ? testing::replace_once(text, "max_iterations: 10,", "max_iterations: 20,")
                 : testing::replace_once(text, "newton: {", "newton: {max_iterations: 20, ");
      std::string name =
          std::string(rough ? rough_file : smooth_file) + "_stiff_" + std::to_string(n);
      std::replace(name.begin(), name.end(), '/', '_');
      const auto& f = run_footing(text, name, scale);
      q[{rough, n}] = f.q_at(0.005);
      std::printf("[%s, E = 1e4 s_u, h = 1/%d] q/s_u = %.3f at 0.005, %.3f at 0.004\n",
                  rough ? rough_file : smooth_file, 2 * n, f.q_at(0.005), f.q_at(0.004));
      // Levelled off: the last 0.001 of the push changes the load by less than 1 %.
      EXPECT_LT(std::abs(f.q_at(0.005) / f.q_at(0.004) - 1.0), 0.01);
      EXPECT_GT((q[{rough, n}]), rough ? exact_rough : exact_smooth);
    }
  for (int rough : {0, 1}) EXPECT_LT((q[{rough, 10}]), (q[{rough, 5}]));  // falls with h
  // A discretisation that lets the smooth base slide must not carry more than the rough one.
  for (int n : {5, 10}) EXPECT_LE((q[{0, n}]), (q[{1, n}]));
}

TEST(StripFootingValidation, RigidPlasticLimitConvergesToPrandtlFromAboveSmoothBelowRough) {
  // Prandtl (1921): 2 + pi for a smooth or rough strip. Measured at 0.005 B (h = B/10, B/20):
  // smooth 5.42, 5.28; rough 5.51, 5.32 (the former penalty footings: 5.81, 5.48; 5.90, 5.53).
  check_rigid_plastic_limit("structures/strip_footing_smooth.yaml",
                            "structures/strip_footing_rough.yaml", kContactStripScale, kPrandtl,
                            kPrandtl);
}

TEST(CircularFootingValidation, RigidPlasticLimitConvergesToCoxEasonHopkinsSmoothBelowRough) {
  // Cox, Eason & Hopkins (1961), tabulated by Houlsby & Wroth (1983): N_c = 5.69 smooth, 6.05
  // rough. q = 2 pi F / (pi R^2) = 8 F per radian for R = 0.5 (axisymmetry). Measured at 0.005 D
  // (h = D/10, D/20): smooth 6.20, 5.94; rough 6.48, 6.22 (the former penalty footings: 7.04,
  // 6.26; 7.42, 6.69).
  check_rigid_plastic_limit("structures/circular_footing_smooth.yaml",
                            "structures/circular_footing_rough.yaml", 8.0, 5.69, 6.05);
}

// The model whose steps start from the last nodal pressure, fitted (docs/theory.md eq. 11.11).
TEST(StripFootingValidation, IncrementalPressureEquationCarriesStandardMpmToOneB) {
  // The large-deformation strip of docs/references.md §3 (Kardani et al. 2015 set-up) with standard
  // MPM and the incremental pressure equation: the run must finish at 1 B, the resistance start
  // near 2 + pi and rise with embedment (docs/validation.md §6: 5.03 at 0.1 B, 7.61 at 1 B; the
  // default total equation stops at 0.85 B with standard MPM).
  const std::string example = testing::replace_once(
      testing::example_text("strip_footing/strip_footing_large_deformation.yaml"),
      "vtk: {every: 20}", "vtk: {every: 0}");
  // As measured: the cell-averaged volume change (F-bar); with each point its own (the default)
  // a point turns inside out at 0.61 B.
  const auto& f = run_footing(incremental_pressure(testing::with_numerics(
                                  testing::with_numerics(example, "interpolation", "standard"),
                                  "mixed_volume", "cell_average")),
                              "large_deformation_standard_incremental", kStripScale);
  // (a run that stops throws from run_footing)
  ASSERT_GE(f.settlement.back(), 1.0 - 1e-6);
  EXPECT_NEAR(f.q_at(0.1), kPrandtl, 0.05 * kPrandtl);
  EXPECT_GT(f.q_mean(0.9, 1.0), f.q_mean(0.2, 0.3));
  EXPECT_GT(f.q_mean(0.2, 0.3), f.q_mean(0.05, 0.1));
  EXPECT_LE(f.max_iterations(), 10);
}

TEST(StripFootingValidation, DisplacementFormulationLocksWhereMixedPUDoesNot) {
  const auto& locked = run_footing(strip(Strip::SteelBlock, 0.4999, "displacement"),
                                   "rough_disp_04999", kStripScale);
  const auto& mixed =
      run_footing(strip(Strip::SteelBlock, 0.4999, "mixed"), "rough_04999", kStripScale);
  const double ql = locked.q_at(0.1), qm = mixed.q_at(0.1);
  std::printf("[rough strip, nu 0.4999, 0.1 B] q/s_u displacement %.2f, p-u %.3f (Prandtl %.3f)\n",
              ql, qm, kPrandtl);
  // Volumetric locking (Nagtegaal, Parks & Rice 1974; Sloan & Randolph 1982): the displacement
  // formulation's limit load is far above Prandtl's and grows with the bulk modulus.
  EXPECT_GT(ql, 1.5 * kPrandtl);
  EXPECT_LT(qm, 1.12 * kPrandtl);
}

TEST(StripFootingValidation, FBarDisplacementFormulationDoesNotLockEither) {
  // formulation: f_bar (docs/theory.md §12): the displacement formulation with each cell's mean
  // volume change, no pressure unknowns. Its curves swing more than the mixed ones as points
  // cross cells (docs/validation.md §4: q/s_u at 0.1 B 5.48 / 5.33 at nu = 0.49 / 0.4999, the
  // first above the band), so the mean over 0.08-0.1 B is what is asserted (measured 5.34 /
  // 5.21): in the band, where the plain displacement formulation carries 7.9 and 40 (the
  // locking test above).
  const auto& soft =
      run_footing(strip(Strip::SteelBlock, 0.49, "f_bar"), "rough_f_bar_049", kStripScale);
  const auto& stiff =
      run_footing(strip(Strip::SteelBlock, 0.4999, "f_bar"), "rough_f_bar_04999", kStripScale);
  const double m_soft = soft.q_mean(0.08, 0.1), m_stiff = stiff.q_mean(0.08, 0.1);
  std::printf("[rough strip, F-bar] mean q/s_u over 0.08-0.1 B %.3f (nu 0.49), %.3f (nu 0.4999)\n",
              m_soft, m_stiff);
  for (const double m : {m_soft, m_stiff}) {
    EXPECT_GE(m, kPrandtl);
    EXPECT_LE(m, 5.40);
  }
  // The means' change between the two nu is reported, not asserted: it moves with the steps the
  // run takes through the cell crossings (1.0 % to 2.8 % over the step rules and Newton limits
  // tried, 2.45 % with the example's; docs/validation.md §4, the 2 % target not reached).
  std::printf("[rough strip, F-bar] change of the mean between the two nu: %.2f %%\n",
              100 * std::abs(m_stiff / m_soft - 1.0));
  EXPECT_LE(soft.max_iterations(), 10);
  EXPECT_LE(stiff.max_iterations(), 10);
}

TEST(MohrCoulombFootingValidation, SmoothFootingAgainstPrandtlReissnerNc) {
  const double Nc = prandtl_reissner_nc(20.0);
  EXPECT_NEAR(Nc, 14.835, 0.001);
  const auto text = no_vtk(testing::example_text("mohr_coulomb_footing/mohr_coulomb_footing.yaml"));
  const auto& f = run_footing(text, "mohr_coulomb", kStripScale);
  const double q = f.q_at(0.05);
  std::printf("[Mohr-Coulomb strip, phi 20, h = B/20, 0.05 B] q/c = %.3f, N_c = %.3f (%+.1f %%)\n",
              q, Nc, (q / Nc - 1) * 100);
  EXPECT_LE(f.max_iterations(), 10);
  // Low-order cells over-estimate the limit load of associated (dilatant) flow — the dilatancy
  // constraint locks them as incompressibility does (Sloan & Randolph 1982). docs/validation.md
  // §8 measured, at 0.05 B, +21 % at h = B/10, +9 % at B/20 and +2.5 % at B/40, the curves still
  // rising there (the model levels off at +18-22 % near 0.09 B at B/20, so the N_c target is
  // reported as not reached). Asserted: on this mesh the value at 0.05 B lies above N_c and
  // within the over-estimate measured for it (15 %, allowing cell-crossing noise of a few %).
  EXPECT_GT(q, Nc);
  EXPECT_LT(q, 1.15 * Nc);
}

TEST(MohrCoulombFootingValidation, RigidPlasticLimitConvergesToPrandtlReissnerNc) {
  // N_c is the limit load of a rigid-plastic soil. The example's soil made stiff (E = 5e4 c
  // instead of 1000 c) and pushed 0.002 B forms its mechanism before any soil point crosses a
  // cell (h/4 = 0.006 B at h = B/40) and without the heave of a dilatant soil pushed far, so each
  // mesh levels off at its own limit load (docs/validation.md §8, the rigid-plastic limit).
  // Newton takes the plastic side's tangent at points on the yield surface (`surface_tangent:
  // plastic`, docs/materials.md §1.7): the converged loads are those of the elastic side's to
  // six digits, in fewer iterations (measured at most 7 / 9 / 10 a step on h = B/20, B/40, B/80
  // against 9 / 11 / 13).
  const double Nc = prandtl_reissner_nc(20.0);  // 14.83
  const auto example =
      no_vtk(testing::example_text("mohr_coulomb_footing/mohr_coulomb_footing.yaml"));
  std::vector<double> q, rise;
  for (int n : {5, 10, 20}) {  // h = B/10, B/20, B/40
    const auto text =
        testing::replace_once(testing::replace_once(testing::strip_mesh(example, n), "E: 1000,",
                                                    "E: 50000, surface_tangent: plastic,"),
                              "\"-0.05*t\"", "\"-0.002*t\"");
    const auto& f = run_footing(text, "mohr_coulomb_stiff_" + std::to_string(n), kStripScale);
    // Issue 3: at most 10 Newton iterations a step through plastic flow.
    EXPECT_LE(f.max_iterations(), 10) << "h = B/" << 2 * n;
    q.push_back(f.q_at(0.002));
    std::printf(
        "[Mohr-Coulomb strip, E = 5e4 c, h = B/%d] q/c = %.3f at 0.002 B (%+.1f %%), "
        "%.3f at 0.0016 B, Newton at most %d a step\n",
        2 * n, q.back(), (q.back() / Nc - 1) * 100, f.q_at(0.0016), f.max_iterations());
    rise.push_back(q.back() / f.q_at(0.0016) - 1.0);
  }
  // The meshes level off: locked cells keep creeping up after the mechanism has formed (Sloan &
  // Randolph 1982), by half as much on each finer mesh (measured over the last 0.0004 B of the
  // push: +1.9 %, +1.0 %, +0.5 %; +0.2 % at h = B/80, docs/validation.md §8).
  EXPECT_LT(rise[1], 0.75 * rise[0]);
  EXPECT_LT(rise[2], 0.75 * rise[1]);
  EXPECT_LT(std::abs(rise[2]), 0.01);
  // Low-order cells over-estimate the limit load of associated flow (dilatancy locking, Sloan &
  // Randolph 1982), and the over-estimate vanishes with h: measured +30 %, +16 %, +8.3 %.
  EXPECT_GT(q[2], Nc);
  EXPECT_LT(q[2], q[1]);
  EXPECT_LT(q[1], q[0]);
  // Richardson extrapolation h -> 0 with the observed order (measured 0.91 and 14.78, -0.3 %).
  const auto [order, extrapolated] = testing::richardson(q[0], q[1], q[2]);
  std::printf(
      "[Mohr-Coulomb strip, rigid-plastic limit] order %.2f, extrapolated q/c = %.3f "
      "(%+.1f %% of N_c = %.3f)\n",
      order, extrapolated, (extrapolated / Nc - 1) * 100, Nc);
  EXPECT_GT(order, 0.5);
  EXPECT_LT(order, 1.5);
  EXPECT_NEAR(extrapolated / Nc, 1.0, 0.03);
}

TEST(MohrCoulombFootingValidation, MixedAtTheFieldPressureDoesNotLockInTheRigidPlasticLimit) {
  // The same stiff footing in the mixed p-u formulation with the material evaluated at the
  // field's pressure (numerics.mixed_material_pressure: field, docs/theory.md §14): the
  // dilatancy of associated flow is tied to the kinematics only in the mean over each node's
  // support, not at every point, so the bilinear cells no longer lock. At h = B/20 the
  // displacement formulation carries +16 % over N_c (previous test); measured here +4.2 %, level
  // after the mechanism has formed (docs/validation.md §8).
  const double Nc = prandtl_reissner_nc(20.0);  // 14.83
  std::string text = testing::replace_once(
      testing::replace_once(
          testing::strip_mesh(
              no_vtk(testing::example_text("mohr_coulomb_footing/mohr_coulomb_footing.yaml")), 10),
          "E: 1000,", "E: 50000,"),
      "\"-0.05*t\"", "\"-0.002*t\"");
  text = testing::replace_once(text, "density: 0}", "density: 0, formulation: mixed}");
  text = testing::with_numerics(text, "mixed_material_pressure", "field");
  // As measured: the cell-averaged volume change (F-bar); each point its own, the default,
  // carries +5.7 % (docs/validation.md §8).
  text = testing::with_numerics(text, "mixed_volume", "cell_average");
  const auto& f = run_footing(text, "mohr_coulomb_stiff_field_pressure", kStripScale);
  const double q = f.q_at(0.002), creep = q / f.q_at(0.0016) - 1.0;
  std::printf(
      "[Mohr-Coulomb strip, mixed at the field pressure, E = 5e4 c, h = B/20] q/c = %.3f at "
      "0.002 B (%+.1f %% of N_c), %+.2f %% over the last 0.0004 B, Newton at most %d a step\n",
      q, (q / Nc - 1) * 100, creep * 100, f.max_iterations());
  EXPECT_NEAR(q / Nc, 1.0, 0.05);
  EXPECT_LT(std::abs(creep), 0.005);
}

}  // namespace
}  // namespace geompm

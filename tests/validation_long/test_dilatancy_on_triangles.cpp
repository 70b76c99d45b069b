// Dilatant plastic flow on constant-strain triangles with crossed diagonals (docs/validation.md
// §13): the weightless surcharge footing of examples/frictional_footing/frictional_footing_nq.yaml
// in the rigid-plastic limit, on h = B/10, B/20, B/40, converges to Prandtl's (1921) and
// Reissner's (1924) exact N_q = e^(pi tan phi) tan^2(45 + phi/2) = 18.40 (associated flow,
// phi = psi = 30 deg, smooth or rough alike in weightless soil). The same meshes, material and
// Newton settings carry the self-weight footing of §11 to an extrapolated 16.8, 11.8 % above
// Martin's N_gamma plus the token cohesion's share (15.05), so that error is not the triangles'
// treatment of dilatant flow; and the same footing on Tresca clay with self-weight gains only the
// overburden of its embedment, so the self-weight is consistent where the strength does not follow
// it. About 100 s per N_q footing on one core, most of it on h = B/40; the Tresca case a few
// seconds.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "example_text.hpp"
#include "frictional_footing.hpp"
#include "richardson.hpp"
#include "strip_mesh.hpp"

namespace geompm {
namespace {

using namespace testing::frictional_footing;

/// The N_q example in the rigid-plastic limit of §9 (nq_rigid_plastic_model) as validation.md §13
/// runs it: the apex rounded (a = 1.5 c,
/// docs/materials.md §3.6) and Newton started from the last step's increment, as the N_gamma rows
/// of §11; on crossed triangles with n cells under the half-width.
std::string nq_on_crossed_triangles(int n, bool rough) {
  using testing::replace_once;
  auto t =
      replace_once(nq_rigid_plastic_model(n), "newton: {line_search: 6,",
                   "newton: {predictor: extrapolated, extrapolated_patience: 20, line_search: 6,");
  t = replace_once(t, "c: 0.01, phi: 30, psi: 30,",
                   "c: 0.01, phi: 30, psi: 30, apex_rounding: 0.015, lode_transition: 29,");
  if (rough) t = replace_once(t, "displacement: [~, ", "displacement: [0, ");
  return testing::on_triangles(t, true);
}

/// N_q on h = B/10, B/20, B/40: the mean over 0.001-0.0015 B, where the curves have levelled
/// off, less the tiny cohesion's exact share c N_c / q0.
void check_converges_to_prandtl_reissner(bool rough, const char* name) {
  std::vector<double> nq;
  for (int n : {5, 10, 20}) {
    const auto push = run_push(nq_on_crossed_triangles(n, rough),
                               std::string(name) + "_b" + std::to_string(2 * n), kSurchargeScale);
    ASSERT_FALSE(push.stopped) << "h = B/" << 2 * n;
    ASSERT_NEAR(push.s.back(), 0.0015, 1e-6);
    nq.push_back(push.mean(0.001, 0.0015) - kCohesionShare);
    std::printf("[N_q, %s, crossed triangles, h = B/%d] %.3f (%+.1f %%)\n", name, 2 * n, nq.back(),
                (nq.back() / kNq - 1) * 100);
    EXPECT_GT(nq.back(), kNq);  // from above, as measured on every mesh (validation.md §13)
  }
  EXPECT_LT(nq[1], nq[0]);
  EXPECT_LT(nq[2], nq[1]);
  const auto [order, extrapolated] = testing::richardson(nq[0], nq[1], nq[2]);
  std::printf("[N_q, %s, crossed triangles] order %.2f, extrapolated %.3f (%+.2f %% of N_q)\n",
              name, order, extrapolated, (extrapolated / kNq - 1) * 100);
  EXPECT_GT(order, 0.7);
  EXPECT_LT(order, 1.3);
  EXPECT_NEAR(extrapolated / kNq, 1.0, 0.02);
}

TEST(DilatancyOnTriangles, SmoothSurchargeFootingConvergesToPrandtlReissner) {
  // Measured: 21.74, 20.07, 19.23 (+18.1, +9.1, +4.5 %), order 1.00, extrapolated 18.39.
  check_converges_to_prandtl_reissner(false, "smooth");
}

TEST(DilatancyOnTriangles, RoughSurchargeFootingConvergesToPrandtlReissner) {
  // Measured: 22.26, 20.39, 19.43 (+21.0, +10.8, +5.6 %), order 0.95, extrapolated 18.40.
  check_converges_to_prandtl_reissner(true, "rough");
}

/// The self-weight footing of examples/frictional_footing/frictional_footing_ngamma.yaml with its
/// soil as Tresca clay (s_u = 1 kPa, E = 1e4 s_u, nu = 0.49, K0 = 1) of unit weight gamma (B = 1 m)
/// on crossed triangles (h = B/10), pushed 0.005 B (validation.md §13, tresca_weight_text).
std::string tresca_with_weight(double gamma) {
  using testing::replace_once;
  char density[32];
  std::snprintf(density, sizeof density, "%g", gamma / 10);  // g = 10 m/s2
  auto t = replace_once(testing::example_text("frictional_footing/frictional_footing_ngamma.yaml"),
                        "vtk: {every: 10}", "vtk: {every: 0}");
  t = replace_once(
      t,
      "sand: {model: mohr_coulomb, c: 0.01, phi: 30, psi: 30, E: 50000, nu: 0.3, "
      "density: 2}",
      std::string("sand: {model: tresca, su: 1, E: 10000, nu: 0.49, density: ") + density + "}");
  t = replace_once(t, "E: 10000000, nu: 0.2", "E: 2000000, nu: 0.2");
  t = replace_once(t, "k0_procedure: {bodies: [soil]}", "k0_procedure: {bodies: [soil], K0: 1.0}");
  t = replace_once(t, "\"-0.007*t\"", "\"-0.005*t\"");
  t = replace_once(t, "newton: {predictor: extrapolated, max_iterations: 20,",
                   "newton: {predictor: extrapolated, line_search: 6, max_iterations: 20,");
  return testing::on_triangles(testing::strip_mesh(t, 5), true);
}

TEST(DilatancyOnTriangles, SelfWeightAddsOnlyTheOverburdenInAnIsochoricMechanism) {
  // With a flat surface gravity does no work in an isochoric mechanism, so the rigid-plastic
  // Tresca footing carries the same whatever gamma; embedded by s it gains about the overburden
  // gamma s (q_u = N_c s_u + gamma D: N_q = 1 at phi = 0), a little more for the heave beside it.
  // Measured with gamma B / s_u = 100: 1.11, 1.20, 1.38 times gamma s at 0.001, 0.002, 0.005 B.
  constexpr double kGamma = 100.0;
  const auto weightless = run_push(tresca_with_weight(0.0), "tresca_weightless", kSurchargeScale);
  const auto heavy = run_push(tresca_with_weight(kGamma), "tresca_weight_100", kSurchargeScale);
  ASSERT_FALSE(weightless.stopped);
  ASSERT_FALSE(heavy.stopped);
  for (const double s : {0.001, 0.002, 0.005}) {
    const double gained = (heavy.at(s) - weightless.at(s)) / (kGamma * s);
    std::printf(
        "[Tresca, gamma B / s_u = 100, h = B/10] at %.3f B: %.3f against %.3f, %.2f gamma s\n", s,
        heavy.at(s), weightless.at(s), gained);
    EXPECT_GT(gained, 1.0);
    EXPECT_LT(gained, 1.5);
  }
}

}  // namespace
}  // namespace geompm

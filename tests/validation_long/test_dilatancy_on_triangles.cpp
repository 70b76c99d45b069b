// Dilatant plastic flow on constant-strain triangles with crossed diagonals (docs/validation.md
// §13): the weightless surcharge footing of examples/frictional_footing/frictional_footing_nq.yaml
// in the rigid-plastic limit, on h = B/10, B/20, B/40, converges to Prandtl's (1921) and
// Reissner's (1924) exact N_q = e^(pi tan phi) tan^2(45 + phi/2) = 18.40 (associated flow,
// phi = psi = 30 deg, smooth or rough alike in weightless soil). The same meshes, material and
// Newton settings carry the self-weight footing of §11 to about 12 % above Martin's N_gamma, so
// that error is not the triangles' treatment of dilatant flow.
// About 100 s per footing on one core, most of it on h = B/40.
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

/// The N_q example as validation.md §13 runs it (scripts/validation_report.py,
/// nq_triangle_text): sand 20 times stiffer (E = 1e5 q0) pushed 0.0015 B, before any point
/// crosses a cell, so standard MPM instead of the example's GIMP; the apex rounded (a = 1.5 c,
/// docs/materials.md §3.6) and Newton started from the last step's increment with backtracking,
/// as the N_gamma rows of §11; on crossed triangles with n cells under the half-width.
std::string nq_on_crossed_triangles(int n, bool rough) {
  using testing::replace_once;
  auto t = replace_once(testing::example_text("frictional_footing/frictional_footing_nq.yaml"),
                        "vtk: {every: 10}", "vtk: {every: 0}");
  t = replace_once(t, "E: 5000,", "E: 100000,");
  t = replace_once(t, "interpolation: gimp, ", "");
  t = replace_once(t, "newton: {line_search: 6, max_iterations: 10,",
                   "newton: {predictor: extrapolated, extrapolated_patience: 20, line_search: 6, "
                   "max_iterations: 20,");
  t = replace_once(t, "\"-0.01*t\"", "\"-0.0015*t\"");
  t = replace_once(t, "c: 0.01, phi: 30, psi: 30,",
                   "c: 0.01, phi: 30, psi: 30, apex_rounding: 0.015, lode_transition: 29,");
  if (rough) t = replace_once(t, "displacement: [~, ", "displacement: [0, ");
  return testing::on_triangles(testing::strip_mesh(t, n), true);
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
    EXPECT_GT(nq.back(), kNq);  // associated flow on low-order cells: an upper bound
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

}  // namespace
}  // namespace geompm

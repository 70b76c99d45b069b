// The long validation cases (ctest label validation_long, run by CI besides the suite): each
// takes longer than the suite's other tests together would allow on a 2-core machine.
// - N_q on the finest strip mesh of docs/validation.md §9 (h = B/80): within +5 % of
//   Prandtl-Reissner's 18.40 at a settlement of 0.01 B, with at most 10 Newton iterations a step
//   (about 17 minutes on one core beside another test).
#include <gtest/gtest.h>

#include "frictional_footing.hpp"

namespace geompm {
namespace {

using namespace testing::frictional_footing;

TEST(FrictionalFootingValidation, SurchargeNqWithinFivePercentOfPrandtlReissnerAtBOver80) {
  // The finest mesh of docs/validation.md §9 (h = B/80, 40 cells under the half-width): 4.1 %
  // above N_q = 18.40 at 0.01 B. The target, as for the Tresca strip: within +5 %. Pushed only to
  // 0.0105 B (the report's run goes on to where Newton fails at the smallest step, about 0.011 B),
  // so the Newton count below is of the steps up to there.
  const NqReading finest = nq_at_one_percent(40, "nq_b80");
  EXPECT_GT(finest.nq, kNq);  // an upper bound: associated flow on low-order cells
  EXPECT_LT(finest.nq, 1.05 * kNq);
  EXPECT_LE(finest.most_newton_iterations, 10);
}

}  // namespace
}  // namespace geompm

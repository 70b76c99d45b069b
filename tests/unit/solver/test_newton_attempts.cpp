// A step's Newton attempts joined for the log (solver/newton_attempts.hpp): newton.csv pairs
// residual k with the correction that led to it (index k - 1 of every per-correction record), so
// after the join each record must line up with the residuals, the second attempt's first row
// showing no correction.
#include <gtest/gtest.h>

#include "geompm/solver/newton_attempts.hpp"

namespace geompm {
namespace {

// An attempt of `solves` corrections: residuals r0 ... r_solves, each correction numbered from
// `first` (its length, size, and moved unknown carry the number).
NewtonResult attempt(int solves, double first) {
  NewtonResult r;
  r.iterations = solves;
  for (int k = 0; k <= solves; ++k) r.residuals.push_back(first + k);
  for (int k = 0; k < solves; ++k) {
    r.corrections.push_back(first + k);
    r.step_lengths.push_back(1.0 / (first + k));
    r.largest_correction.push_back(static_cast<Index>(first + k));
  }
  r.largest.assign(r.residuals.size(), 7);
  r.active.assign(r.residuals.size(), ActiveSet{});
  return r;
}

TEST(NewtonAttempts, EveryPerCorrectionRecordLinesUpWithTheResiduals) {
  const NewtonResult joined = join_attempts(attempt(3, 10.0), attempt(2, 20.0));
  EXPECT_EQ(joined.iterations, 5);
  ASSERT_EQ(joined.residuals.size(), 7u);  // 4 of the failed attempt, 3 of the second
  // Row k shows the correction that led to it: none at rows 0 and 4, the attempts' starts.
  const std::vector<double> corrections = {10, 11, 12, 0, 20, 21};
  const std::vector<double> lengths = {1 / 10., 1 / 11., 1 / 12., 0, 1 / 20., 1 / 21.};
  const std::vector<Index> moved = {10, 11, 12, -1, 20, 21};
  EXPECT_EQ(joined.corrections, corrections);
  EXPECT_EQ(joined.step_lengths, lengths);
  EXPECT_EQ(joined.largest_correction, moved);
  EXPECT_EQ(joined.largest.size(), joined.residuals.size());
  EXPECT_EQ(joined.active.size(), joined.residuals.size());
}

TEST(NewtonAttempts, AFailedAttemptsUnloggedLastCorrectionIsDropped) {
  // Stopped at an inadmissible iterate: its last correction led to no logged residual.
  NewtonResult failed = attempt(2, 10.0);
  failed.residuals.pop_back();
  failed.largest.pop_back();
  failed.active.pop_back();
  const NewtonResult joined = join_attempts(failed, attempt(1, 20.0));
  ASSERT_EQ(joined.residuals.size(), 4u);
  EXPECT_EQ(joined.step_lengths, (std::vector<double>{1 / 10., 0, 1 / 20.}));
  EXPECT_EQ(joined.largest_correction, (std::vector<Index>{10, -1, 20}));
}

}  // namespace
}  // namespace geompm

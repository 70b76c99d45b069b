// A step's Newton attempts joined into one record for the log (newton.csv): an extrapolated start
// that failed and the solve from zero that followed it in the same step (analysis/step.cpp,
// docs/theory.md §4.5).
#pragma once

#include "geompm/solver/newton.hpp"

namespace geompm {

/// `second`, a Newton solve that followed the failed one `failed` in the same step, with the
/// failed one's iterations in front: the counts include both, and the log shows both in turn. The
/// log pairs residual k with corrections[k - 1], step_lengths[k - 1] and largest_correction[k - 1]
/// (the correction that led to it) and tangent_errors[k], so those are padded to the failed
/// attempt's residuals (0, or -1 for an unknown, where the second attempt starts). A failed
/// attempt that ended on an inadmissible iterate has one correction more than it logged residuals
/// after the first (the one that led there): it is dropped, so that the second attempt's first
/// row shows no correction.
NewtonResult join_attempts(const NewtonResult& failed, NewtonResult second);

}  // namespace geompm

#include "geompm/solver/newton_attempts.hpp"

#include <algorithm>

namespace geompm {

namespace {

// `later` with `earlier` in front, `earlier` padded with `pad` to `size` entries.
template <typename T>
void put_in_front(std::vector<T>& later, std::vector<T> earlier, std::size_t size, T pad = T{}) {
  if (earlier.size() < size) earlier.resize(size, pad);
  earlier.insert(earlier.end(), later.begin(), later.end());
  later = std::move(earlier);
}

}  // namespace

NewtonResult join_attempts(const NewtonResult& failed, NewtonResult second) {
  const std::size_t n = failed.residuals.size();
  second.iterations += failed.iterations;
  second.halvings += failed.halvings;
  second.searches += failed.searches;
  second.linear_iterations += failed.linear_iterations;
  second.linear_seconds += failed.linear_seconds;
  put_in_front(second.residuals, failed.residuals, n);
  put_in_front(second.largest, failed.largest, n);
  put_in_front(second.active, failed.active, n);
  // Per correction: the failed attempt's logged ones only, padded to its residuals.
  const auto logged = [n](auto per_correction) {
    per_correction.resize(std::min(per_correction.size(), n > 0 ? n - 1 : 0));
    return per_correction;
  };
  put_in_front(second.corrections, logged(failed.corrections), n);
  put_in_front(second.step_lengths, logged(failed.step_lengths), n);
  put_in_front(second.largest_correction, logged(failed.largest_correction), n, Index{-1});
  if (!second.tangent_errors.empty() || !failed.tangent_errors.empty())
    put_in_front(second.tangent_errors, failed.tangent_errors, n);
  return second;
}

}  // namespace geompm

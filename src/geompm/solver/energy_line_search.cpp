#include "geompm/solver/energy_line_search.hpp"

#include <algorithm>
#include <cmath>

namespace geompm {

double energy_line_search(NonlinearProblem& problem, const Vector& start, const Vector& dx,
                          double s_start, double s_full, double tolerance) {
  double below = 0.0, s_below = s_start, beyond = 1.0, s_beyond = s_full;
  double best = 1.0, s_best = std::abs(s_full);
  int kept = 0;  // +1: `below` was moved last, -1: `beyond`
  Vector residual;
  double force_scale = 0.0;
  for (int m = 0; m < energy_search_evaluations; ++m) {
    const double margin = 0.05 * (beyond - below);
    const double eta = std::clamp(below + (beyond - below) * s_below / (s_below - s_beyond),
                                  below + margin, beyond - margin);
    const bool admissible = problem.evaluate(start + eta * dx, residual, force_scale, nullptr);
    // An inadmissible trial lies beyond the minimum as far as the search is concerned.
    const double s = admissible ? dx.dot(residual) : -s_start;
    if (admissible && std::abs(s) < s_best) {
      best = eta;
      s_best = std::abs(s);
      if (s_best <= tolerance * s_start) break;
    }
    if (s > 0.0) {
      below = eta;
      s_below = s;
      if (kept == 1) s_beyond *= 0.5;
      kept = 1;
    } else {
      beyond = eta;
      s_beyond = s;
      if (kept == -1) s_below *= 0.5;
      kept = -1;
    }
  }
  return best;
}

double EnergyLineSearch::shorten(NonlinearProblem& problem, Vector& x, Vector& dx,
                                 const Vector& residual) {
  // A point's returned stress that sweeps across a straight side of the yield surface's section
  // between the iterates makes such an overshoot (theory §4.4).
  if (tolerance_ <= 0.0 || searched_ || along_start_ <= 0.0) return 1.0;
  const double along_full = dx.dot(residual);
  if (!(along_full < -tolerance_ * along_start_)) return 1.0;
  searched_ = true;
  const Vector start = x - dx;
  const double eta = energy_line_search(problem, start, dx, along_start_, along_full, tolerance_);
  if (eta < 1.0) {
    dx *= eta;
    x = start + dx;
  }
  return eta;
}

}  // namespace geompm

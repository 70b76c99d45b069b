#include "geompm/solver/backtracking.hpp"

#include <algorithm>
#include <cmath>

namespace geompm {

Backtracking::Overshoot Backtracking::overshoot(bool admissible, double relative,
                                                double last_accepted, bool length_searched) {
  if (!admissible || !std::isfinite(relative)) return Overshoot::Inadmissible;
  if (!length_searched && relative > last_accepted) return Overshoot::Grown;
  return Overshoot::None;
}

bool Backtracking::retreat(Overshoot overshoot, Vector& x, Vector& dx) {
  if (overshoot == Overshoot::None) return false;
  const int limit = overshoot == Overshoot::Inadmissible
                        ? std::max(max_halvings_, inadmissible_halvings_)
                        : max_halvings_;
  if (halvings_ >= limit) return false;
  dx *= 0.5;
  x -= dx;
  ++halvings_;
  return true;
}

}  // namespace geompm

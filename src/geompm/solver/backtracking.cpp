#include "geompm/solver/backtracking.hpp"

#include <cmath>

namespace geompm {

bool Backtracking::overshot(bool admissible, double relative, double last_accepted,
                            bool length_searched) {
  return !admissible || !std::isfinite(relative) || (!length_searched && relative > last_accepted);
}

bool Backtracking::retreat(bool overshot, Vector& x, Vector& dx) {
  if (!overshot || halvings_ >= max_halvings_) return false;
  dx *= 0.5;
  x -= dx;
  ++halvings_;
  return true;
}

}  // namespace geompm

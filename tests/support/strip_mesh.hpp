// The strip footings' mesh (examples/strip_footing, mohr_coulomb_footing, frictional_footing)
// refined for convergence studies.
#pragma once

#include <algorithm>
#include <cstdio>
#include <string>

#include "example_text.hpp"

namespace geompm::testing {

/// `text` (an example on the strip mesh: 10 cells under the footing's half-width, h = B/20) on
/// the mesh with n cells under the half-width, the graded region refined in proportion; the top
/// row of soil points that a driven smooth footing names (y > 5 - h/4) follows the finer cells.
inline std::string strip_mesh(std::string text, int n) {
  if (n == 10) return text;
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "x: [{length: 1.0, cells: %d}, {length: 4.0, cells: %d, ratio: 4}]", 2 * n,
                6 * n / 5);
  text =
      replace_once(text, "x: [{length: 1.0, cells: 20}, {length: 4.0, cells: 12, ratio: 4}]", buf);
  std::snprintf(buf, sizeof buf,
                "y: [{length: 4.0, cells: %d, ratio: 0.25}, {length: 1.0, cells: %d}, "
                "{length: 0.2, cells: %d}]",
                6 * n / 5, 2 * n, std::max(2, 2 * n / 5));
  text = replace_once(text,
                      "y: [{length: 4.0, cells: 12, ratio: 0.25}, {length: 1.0, cells: 20}, "
                      "{length: 0.2, cells: 4}]",
                      buf);
  std::snprintf(buf, sizeof buf, "%g]", 5 - 0.25 / n);
  for (const char* x : {"min: [0, ", "min: [0.5, "})
    if (text.find(std::string(x) + "4.975]") != std::string::npos)
      text = replace_once(text, std::string(x) + "4.975]", x + std::string(buf));
  return text;
}

/// `text` (a model on a generated quad4 mesh, 4 points per cell) on tri3 cells with 3 points each:
/// one diagonal per rectangle, alternating (the generator's default), or both crossed
/// (docs/theory.md §15).
inline std::string on_triangles(std::string text, bool crossed) {
  text = replace_once(text, "cell: quad4",
                      crossed ? "cell: tri3\n    diagonals: crossed" : "cell: tri3");
  for (std::size_t at; (at = text.find("points_per_cell: 4")) != std::string::npos;)
    text.replace(at, 18, "points_per_cell: 3");
  return text;
}

}  // namespace geompm::testing

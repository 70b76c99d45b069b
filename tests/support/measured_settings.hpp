// The numerics with which the steel-block strip footing studies of docs/validation.md §4-§5 were
// measured, when the example still carried them (until 2026-12-07). A test that asserts one of
// those measurements sets them, so that it checks the option it was measured with;
// docs/validation.md gives the defaults' numbers beside them.
#pragma once

#include <string>

#include "example_text.hpp"

namespace geompm::testing {

/// The steel block of examples/strip_footing/strip_footing.yaml as measured: the cell-averaged
/// volume change (F-bar) and 1e-6 of the steel's E (2e-4 of the clay's) in the empty cells, at
/// most 10 Newton iterations a step (cut back otherwise) to a relative residual of 1e-7; its
/// incremental pressure equation with the fitted start it still carries.
inline std::string as_measured_steel_block(std::string text) {
  text = with_numerics(text, "mixed_volume", "cell_average");
  text = with_newton(text, "max_iterations: 10, residual_tolerance: 1.0e-7");
  return with_numerics(text, "empty_cell_stiffness", "2.0e-4");
}

}  // namespace geompm::testing

// The text of a plot: axis labels that say what is drawn, and the ASCII the built-in fonts of
// libgd can draw (they have no Greek letters or typographic dashes).
#pragma once

#include <string>
#include <vector>

namespace geompm {

/// The label of an axis the user gave no label: the column names as drawn, each with the
/// scale applied to it, e.g. "-settlement" for a scale of -1, "2 * force" for 2.
std::string default_axis_label(const std::vector<std::string>& columns, double scale);

/// `text` in ASCII: the Greek letters and signs of engineering labels spelt out (π -> pi,
/// γ -> gamma, − and – -> -, × -> x, ² -> ^2), any other non-ASCII character as '?'.
std::string plot_ascii(const std::string& text);

}  // namespace geompm

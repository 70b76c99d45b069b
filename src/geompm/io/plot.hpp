// PNG line plots of history columns (libgd): axes with ticks and labels, one line per y column,
// a legend. For the curves an engineer looks at first: load against displacement, energy in time.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace geompm {

/// A horizontal reference line (lo == hi) or band (lo < hi) at values of the plotted (scaled) y
/// axis, e.g. Prandtl's 2 + pi under a load-settlement curve; named in the legend.
struct PlotReference {
  double lo = 0, hi = 0;
  std::string label;
};

struct PlotRequest {
  std::filesystem::path csv;
  std::string x;
  std::vector<std::string> y;
  double x_scale = 1.0;
  double y_scale = 1.0;
  std::string title;
  std::string x_label;  // defaults to the column name, with its scale ("-settlement")
  std::string y_label;  // defaults to the y column names, with their scale
  std::vector<PlotReference> references;
  int width = 900, height = 600;
};

/// Reads the CSV and writes `png` (atomically). Throws InputError for a missing file or column.
void plot_history(const PlotRequest& request, const std::filesystem::path& png);

/// The colour (0xRRGGBB) of the curve of the i-th y column, also shown in the legend.
unsigned plot_line_colour(std::size_t column_index);

}  // namespace geompm

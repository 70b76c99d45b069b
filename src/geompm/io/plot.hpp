// PNG line plots of history columns (libgd): axes with ticks and labels, one line per y column,
// a legend. For the curves an engineer looks at first: load against displacement, energy in time.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace geompm {

struct PlotRequest {
  std::filesystem::path csv;
  std::string x;
  std::vector<std::string> y;
  double x_scale = 1.0;
  double y_scale = 1.0;
  std::string title;
  std::string x_label;  // defaults to the column name
  std::string y_label;
  int width = 900, height = 600;
};

/// Reads the CSV and writes `png` (atomically). Throws InputError for a missing file or column.
void plot_history(const PlotRequest& request, const std::filesystem::path& png);

/// The colour (0xRRGGBB) of the curve of the i-th y column, also shown in the legend.
unsigned plot_line_colour(std::size_t column_index);

}  // namespace geompm

// PNG line plots drawn with libgd. The layout, from the outside in: a title on top; tick labels
// and axis labels below and left of the frame; the legend right of the frame, where it never
// hides a curve; inside the frame, a light grid at the ticks and the curves, clipped to it.
#include "geompm/io/plot.hpp"

#include <fmt/format.h>
#include <gd.h>
#include <gdfontg.h>
#include <gdfontmb.h>
#include <gdfonts.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

#include "geompm/core/error.hpp"
#include "geompm/io/history_writer.hpp"
#include "geompm/io/vtk_writer.hpp"  // write_file_atomically

namespace geompm {

namespace {

// Matplotlib's "tab10": ten colours that stay distinct on white and for most colour-blind
// readers. Beyond ten curves they repeat.
constexpr unsigned kLineColours[] = {0x1f77b4, 0xff7f0e, 0x2ca02c, 0xd62728, 0x9467bd,
                                     0x8c564b, 0xe377c2, 0x7f7f7f, 0xbcbd22, 0x17becf};

constexpr int kTickLength = 5;
constexpr int kInset = 6;  // gap between the frame and the first/last tick, so that a curve on
                           // the edge of its range is not hidden under the frame

using Image = std::unique_ptr<gdImage, decltype(&gdImageDestroy)>;

/// A pixel coordinate; clamped so that a far-off value cannot overflow the conversion to int.
int pixel(double coordinate) {
  if (std::isnan(coordinate)) return -1000000;
  return static_cast<int>(std::lround(std::clamp(coordinate, -1e6, 1e6)));
}

int text_width(gdFontPtr font, const std::string& text) {
  return static_cast<int>(text.size()) * font->w;
}

void draw_text(gdImagePtr image, gdFontPtr font, int x, int y, const std::string& text,
               int colour) {
  std::string copy = text;  // gdImageString takes a non-const pointer
  gdImageString(image, font, x, y, reinterpret_cast<unsigned char*>(copy.data()), colour);
}

/// Text reading upwards, its centre at height `centre_y`, its left edge at `x`.
void draw_text_up(gdImagePtr image, gdFontPtr font, int x, int centre_y, const std::string& text,
                  int colour) {
  std::string copy = text;
  gdImageStringUp(image, font, x, centre_y + text_width(font, text) / 2,
                  reinterpret_cast<unsigned char*>(copy.data()), colour);
}

int allocate(gdImagePtr image, unsigned rgb) {
  return gdImageColorAllocate(image, (rgb >> 16) & 0xff, (rgb >> 8) & 0xff, rgb & 0xff);
}

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();

  void include(double v) {
    if (!std::isfinite(v)) return;  // NaN and inf are gaps in a curve, not part of its range
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  /// A range that can be divided: an empty one becomes [0, 1]; a constant one (or one whose
  /// width is lost in rounding) is widened around its value so the curve shows as a flat line
  /// in the middle.
  Range usable() const {
    if (!(lo <= hi)) return {0.0, 1.0};
    const double magnitude = std::max(std::abs(lo), std::abs(hi));
    if (hi - lo > 1e-9 * magnitude) return *this;
    const double half = magnitude > 0 ? 0.1 * magnitude : 1.0;
    return {lo - half, hi + half};
  }
};

/// The smallest 1, 2 or 5 x 10^k not below `raw` (> 0): ticks a reader can add up in the head.
double nice_step(double raw) {
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * decade >= raw * (1 - 1e-12)) return m * decade;
  return 10.0 * decade;
}

/// A tick value as text, with as many digits as the step needs and no more (0.1, not
/// 0.10000000000000001); scientific when fixed notation would be long.
std::string tick_label(double value, double step, double largest) {
  if (std::abs(value) < 1e-9 * step) return "0";
  const int step_exponent = static_cast<int>(std::floor(std::log10(step) + 1e-9));
  if (largest >= 1e6 || step < 1e-4) {
    const int value_exponent = static_cast<int>(std::floor(std::log10(std::abs(value)) + 1e-9));
    return fmt::format("{:.{}e}", value, std::clamp(value_exponent - step_exponent, 0, 12));
  }
  return fmt::format("{:.{}f}", value, std::max(0, -step_exponent));
}

/// An axis: the drawn range (whole steps, so the ends carry ticks), its ticks and their labels.
struct Axis {
  double lo = 0, hi = 1;
  std::vector<double> ticks;
  std::vector<std::string> labels;

  int widest_label(gdFontPtr font) const {
    int w = 0;
    for (const auto& l : labels) w = std::max(w, text_width(font, l));
    return w;
  }
};

Axis make_axis(Range data, double step) {
  Axis axis;
  axis.lo = std::floor(data.lo / step) * step;
  axis.hi = std::ceil(data.hi / step) * step;
  if (axis.hi <= axis.lo) axis.hi = axis.lo + step;
  const double count_real = std::round((axis.hi - axis.lo) / step);
  // Only values near the limits of double (width overflowing to inf) get here; plot the data
  // range with its two ends as ticks rather than fail.
  if (!(count_real >= 1 && count_real <= 1000)) {
    axis.lo = data.lo;
    axis.hi = data.hi;
    axis.ticks = {data.lo, data.hi};
    axis.labels = {fmt::format("{:.3g}", data.lo), fmt::format("{:.3g}", data.hi)};
    return axis;
  }
  const long count = static_cast<long>(count_real);
  const double largest = std::max(std::abs(axis.lo), std::abs(axis.hi));
  for (long i = 0; i <= count; ++i) {
    const double value = axis.lo + static_cast<double>(i) * step;
    axis.ticks.push_back(value);
    axis.labels.push_back(tick_label(value, step, largest));
  }
  return axis;
}

/// Ticks at least `min_spacing` pixels apart along `pixels`; on the horizontal axis, where the
/// labels stand side by side, further apart if the labels would otherwise touch.
Axis choose_axis(Range data, int pixels, int min_spacing, gdFontPtr label_font,
                 bool labels_side_by_side) {
  const int max_intervals = std::max(1, pixels / min_spacing);
  double step = nice_step((data.hi - data.lo) / max_intervals);
  Axis axis = make_axis(data, step);
  // Each round moves to the next 1-2-5 step (the tick count falls by 2 to 2.5 times); the bound
  // only guards against labels too wide ever to fit.
  for (int round = 0; round < 30; ++round) {
    const double spacing = pixels * step / (axis.hi - axis.lo);
    const int needed = labels_side_by_side ? axis.widest_label(label_font) + 12 : min_spacing;
    if (spacing >= needed || axis.ticks.size() <= 2) break;
    step = nice_step(step * 1.5);
    axis = make_axis(data, step);
  }
  return axis;
}

struct Curve {
  std::string name;
  std::vector<double> x, y;  // scaled; non-finite entries are gaps
};

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

}  // namespace

unsigned plot_line_colour(std::size_t column_index) {
  return kLineColours[column_index % std::size(kLineColours)];
}

void plot_history(const PlotRequest& request, const std::filesystem::path& png) {
  const std::string csv_name = request.csv.string();
  if (request.y.empty()) throw InputError(csv_name + ": a plot needs at least one y column");
  if (request.width < 200 || request.height < 150)
    throw InputError(fmt::format("plot {}: size {}x{} is too small (at least 200x150 pixels)",
                                 png.string(), request.width, request.height));

  const CsvTable table = read_csv(request.csv);
  const std::size_t x_column = table.column(request.x, csv_name);
  std::vector<Curve> curves;
  Range x_range, y_range;
  for (const auto& name : request.y) {
    const std::size_t y_column = table.column(name, csv_name);
    Curve curve{name, {}, {}};
    for (const auto& row : table.rows) {
      curve.x.push_back(row[x_column] * request.x_scale);
      curve.y.push_back(row[y_column] * request.y_scale);
      // A point counts for the range only if it can be drawn, i.e. both coordinates are finite.
      if (std::isfinite(curve.x.back()) && std::isfinite(curve.y.back())) {
        x_range.include(curve.x.back());
        y_range.include(curve.y.back());
      }
    }
    curves.push_back(std::move(curve));
  }

  const std::string title = request.title.empty() ? request.csv.filename().string() : request.title;
  const std::string x_label = request.x_label.empty() ? request.x : request.x_label;
  const std::string y_label = request.y_label.empty() ? joined(request.y) : request.y_label;

  gdFontPtr title_font = gdFontGetGiant();
  gdFontPtr label_font = gdFontGetMediumBold();
  gdFontPtr small_font = gdFontGetSmall();

  // Layout. Vertical first: it fixes the height of the frame, hence the y ticks, whose labels
  // fix the left margin, hence the width of the frame and the x ticks.
  const int width = request.width, height = request.height;
  const int top = 12 + title_font->h + 12;
  const int bottom = height - (kTickLength + 4 + small_font->h + 8 + label_font->h + 10);
  const Axis y_axis = choose_axis(y_range.usable(), bottom - top - 2 * kInset, 40, small_font,
                                  /*labels_side_by_side=*/false);
  const int left = 10 + label_font->h + 10 + y_axis.widest_label(small_font) + 4 + kTickLength;
  int legend_width = 0;
  for (const auto& c : curves)
    legend_width = std::max(legend_width, text_width(small_font, c.name));
  const int legend_sample = 24;
  const int right = width - std::min(width / 3, 16 + legend_sample + 6 + legend_width + 10);
  const Axis x_axis = choose_axis(x_range.usable(), right - left - 2 * kInset, 70, small_font,
                                  /*labels_side_by_side=*/true);

  const double inner_left = left + kInset, inner_right = right - kInset;
  const double inner_top = top + kInset, inner_bottom = bottom - kInset;
  auto to_px = [&](double x) {
    return inner_left + (x - x_axis.lo) / (x_axis.hi - x_axis.lo) * (inner_right - inner_left);
  };
  auto to_py = [&](double y) {
    return inner_bottom - (y - y_axis.lo) / (y_axis.hi - y_axis.lo) * (inner_bottom - inner_top);
  };

  Image image(gdImageCreateTrueColor(width, height), gdImageDestroy);
  if (!image)
    throw RunError("cannot create a " + std::to_string(width) + "x" + std::to_string(height) +
                   " image for " + png.string());
  gdImagePtr im = image.get();
  const int white = allocate(im, 0xffffff), black = allocate(im, 0x000000);
  const int grid = allocate(im, 0xe6e6e6);
  gdImageFilledRectangle(im, 0, 0, width - 1, height - 1, white);

  // Grid, ticks and tick labels.
  for (std::size_t i = 0; i < x_axis.ticks.size(); ++i) {
    const int px = pixel(to_px(x_axis.ticks[i]));
    gdImageLine(im, px, top + 1, px, bottom - 1, grid);
    gdImageLine(im, px, bottom, px, bottom + kTickLength, black);
    draw_text(im, small_font, px - text_width(small_font, x_axis.labels[i]) / 2,
              bottom + kTickLength + 4, x_axis.labels[i], black);
  }
  for (std::size_t i = 0; i < y_axis.ticks.size(); ++i) {
    const int py = pixel(to_py(y_axis.ticks[i]));
    gdImageLine(im, left + 1, py, right - 1, py, grid);
    gdImageLine(im, left - kTickLength, py, left, py, black);
    draw_text(im, small_font, left - kTickLength - 4 - text_width(small_font, y_axis.labels[i]),
              py - small_font->h / 2, y_axis.labels[i], black);
  }

  // Curves, clipped to the inside of the frame. A point with no drawable neighbour (a single
  // row, or one between gaps) would draw nothing as a line, so it gets a small square.
  gdImageSetClip(im, left + 1, top + 1, right - 1, bottom - 1);
  gdImageSetThickness(im, 2);
  for (std::size_t c = 0; c < curves.size(); ++c) {
    const Curve& curve = curves[c];
    const int colour = allocate(im, plot_line_colour(c));
    auto drawable = [&](std::size_t i) {
      return i < curve.x.size() && std::isfinite(curve.x[i]) && std::isfinite(curve.y[i]);
    };
    for (std::size_t i = 0; i < curve.x.size(); ++i) {
      if (!drawable(i)) continue;
      const int px = pixel(to_px(curve.x[i]));
      const int py = pixel(to_py(curve.y[i]));
      if (drawable(i + 1)) {
        gdImageLine(im, px, py, pixel(to_px(curve.x[i + 1])), pixel(to_py(curve.y[i + 1])), colour);
      } else if (i == 0 || !drawable(i - 1)) {
        gdImageFilledRectangle(im, px - 2, py - 2, px + 2, py + 2, colour);
      }
    }
  }
  gdImageSetThickness(im, 1);
  gdImageSetClip(im, 0, 0, width - 1, height - 1);
  gdImageRectangle(im, left, top, right, bottom, black);

  // Title, axis labels, legend.
  draw_text(im, title_font, std::max(4, (left + right - text_width(title_font, title)) / 2), 12,
            title, black);
  draw_text(im, label_font, std::max(4, (left + right - text_width(label_font, x_label)) / 2),
            height - 10 - label_font->h, x_label, black);
  draw_text_up(im, label_font, 10, (top + bottom) / 2, y_label, black);
  gdImageSetThickness(im, 2);
  for (std::size_t c = 0; c < curves.size(); ++c) {
    const int y = top + 8 + static_cast<int>(c) * (small_font->h + 6);
    const int colour = allocate(im, plot_line_colour(c));
    gdImageLine(im, right + 16, y + small_font->h / 2, right + 16 + legend_sample,
                y + small_font->h / 2, colour);
    gdImageSetThickness(im, 1);
    draw_text(im, small_font, right + 16 + legend_sample + 6, y, curves[c].name, black);
    gdImageSetThickness(im, 2);
  }
  gdImageSetThickness(im, 1);

  int size = 0;
  void* bytes = gdImagePngPtr(im, &size);
  if (!bytes) throw RunError("cannot encode the plot " + png.string() + " as PNG");
  const std::string content(static_cast<const char*>(bytes), static_cast<std::size_t>(size));
  gdFree(bytes);
  write_file_atomically(png, content);
}

}  // namespace geompm

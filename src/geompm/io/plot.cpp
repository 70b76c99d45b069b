// PNG line plots drawn with libgd. The layout, from the outside in: a title on top; tick labels
// and axis labels below and left of the frame; the legend right of the frame, where it never
// hides a curve; inside the frame, a light grid at the ticks, the reference bands and lines, and
// the curves, clipped to it. Text is drawn in ASCII (plot_text.hpp).
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
#include "geompm/io/plot_text.hpp"
#include "geompm/io/vtk_writer.hpp"  // write_file_atomically

namespace geompm {

namespace {

// Matplotlib's "tab10": ten colours that stay distinct on white and for most colour-blind
// readers. Beyond ten curves they repeat.
constexpr unsigned kLineColours[] = {0x1f77b4, 0xff7f0e, 0x2ca02c, 0xd62728, 0x9467bd,
                                     0x8c564b, 0xe377c2, 0x7f7f7f, 0xbcbd22, 0x17becf};

// Reference lines in dark grey, dashed; bands filled in a light sand colour under the curves.
constexpr unsigned kReferenceColour = 0x404040;
constexpr unsigned kBandColour = 0xf6e3c4;

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
  std::string copy = text;  // gdImageString takes a non-const pointer; text is ASCII already
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

/// The curves to draw, and the ranges of their drawable points.
struct PlotData {
  std::vector<Curve> curves;
  Range x_range, y_range;
};

// The request's y columns against its x column, scaled.
PlotData read_curves(const PlotRequest& request, const std::string& csv_name) {
  const CsvTable table = read_csv(request.csv);
  const std::size_t x_column = table.column(request.x, csv_name);
  PlotData data;
  for (const auto& name : request.y) {
    const std::size_t y_column = table.column(name, csv_name);
    Curve curve{plot_ascii(name), {}, {}};
    for (const auto& row : table.rows) {
      curve.x.push_back(row[x_column] * request.x_scale);
      curve.y.push_back(row[y_column] * request.y_scale);
      // A point counts for the range only if it can be drawn, i.e. both coordinates are finite.
      if (std::isfinite(curve.x.back()) && std::isfinite(curve.y.back())) {
        data.x_range.include(curve.x.back());
        data.y_range.include(curve.y.back());
      }
    }
    data.curves.push_back(std::move(curve));
  }
  for (const PlotReference& reference : request.references) {
    data.y_range.include(reference.lo);
    data.y_range.include(reference.hi);
  }
  return data;
}

struct Fonts {
  gdFontPtr title = gdFontGetGiant();
  gdFontPtr label = gdFontGetMediumBold();
  gdFontPtr small = gdFontGetSmall();
};

/// Where everything goes: the image's size, the frame's edges, the axes and the legend's sample
/// line, and the map from data to pixels.
struct Layout {
  int width = 0, height = 0;
  int top = 0, bottom = 0, left = 0, right = 0;
  int legend_sample = 24;
  Axis x_axis, y_axis;

  double to_px(double x) const {
    const double inner_left = left + kInset, inner_right = right - kInset;
    return inner_left + (x - x_axis.lo) / (x_axis.hi - x_axis.lo) * (inner_right - inner_left);
  }
  double to_py(double y) const {
    const double inner_top = top + kInset, inner_bottom = bottom - kInset;
    return inner_bottom - (y - y_axis.lo) / (y_axis.hi - y_axis.lo) * (inner_bottom - inner_top);
  }
};

// Layout. Vertical first: it fixes the height of the frame, hence the y ticks, whose labels
// fix the left margin, hence the width of the frame and the x ticks.
Layout lay_out(const PlotRequest& request, const PlotData& data, const Fonts& fonts) {
  Layout l;
  l.width = request.width;
  l.height = request.height;
  l.top = 12 + fonts.title->h + 12;
  l.bottom = l.height - (kTickLength + 4 + fonts.small->h + 8 + fonts.label->h + 10);
  l.y_axis = choose_axis(data.y_range.usable(), l.bottom - l.top - 2 * kInset, 40, fonts.small,
                         /*labels_side_by_side=*/false);
  l.left = 10 + fonts.label->h + 10 + l.y_axis.widest_label(fonts.small) + 4 + kTickLength;
  int legend_width = 0;
  for (const auto& c : data.curves)
    legend_width = std::max(legend_width, text_width(fonts.small, c.name));
  for (const auto& r : request.references)
    legend_width = std::max(legend_width, text_width(fonts.small, plot_ascii(r.label)));
  l.right = l.width - std::min(l.width / 3, 16 + l.legend_sample + 6 + legend_width + 10);
  l.x_axis = choose_axis(data.x_range.usable(), l.right - l.left - 2 * kInset, 70, fonts.small,
                         /*labels_side_by_side=*/true);
  return l;
}

// Grid, ticks and tick labels.
void draw_grid_and_ticks(gdImagePtr im, const Layout& l, const Fonts& fonts, int black, int grid) {
  for (std::size_t i = 0; i < l.x_axis.ticks.size(); ++i) {
    const int px = pixel(l.to_px(l.x_axis.ticks[i]));
    gdImageLine(im, px, l.top + 1, px, l.bottom - 1, grid);
    gdImageLine(im, px, l.bottom, px, l.bottom + kTickLength, black);
    draw_text(im, fonts.small, px - text_width(fonts.small, l.x_axis.labels[i]) / 2,
              l.bottom + kTickLength + 4, l.x_axis.labels[i], black);
  }
  for (std::size_t i = 0; i < l.y_axis.ticks.size(); ++i) {
    const int py = pixel(l.to_py(l.y_axis.ticks[i]));
    gdImageLine(im, l.left + 1, py, l.right - 1, py, grid);
    gdImageLine(im, l.left - kTickLength, py, l.left, py, black);
    draw_text(im, fonts.small,
              l.left - kTickLength - 4 - text_width(fonts.small, l.y_axis.labels[i]),
              py - fonts.small->h / 2, l.y_axis.labels[i], black);
  }
}

// gdStyled then draws dashes of 8 pixels, 4 apart, in the reference colour.
void use_dashed_reference_style(gdImagePtr im) {
  const int line = allocate(im, kReferenceColour);
  int dash[12];
  for (int i = 0; i < 12; ++i) dash[i] = i < 8 ? line : gdTransparent;
  gdImageSetStyle(im, dash, 12);
}

// Reference bands (filled) and lines (dashed), across the frame, under the curves.
void draw_references(gdImagePtr im, const Layout& l, const std::vector<PlotReference>& references) {
  gdImageSetClip(im, l.left + 1, l.top + 1, l.right - 1, l.bottom - 1);
  const int band = allocate(im, kBandColour);
  for (const PlotReference& r : references)
    if (r.hi > r.lo)
      gdImageFilledRectangle(im, l.left + 1, pixel(l.to_py(r.hi)), l.right - 1,
                             pixel(l.to_py(r.lo)), band);
  use_dashed_reference_style(im);
  for (const PlotReference& r : references)
    for (const double y : {r.lo, r.hi}) {
      const int py = pixel(l.to_py(y));
      gdImageLine(im, l.left + 1, py, l.right - 1, py, gdStyled);
    }
  gdImageSetClip(im, 0, 0, l.width - 1, l.height - 1);
}

// Curves, clipped to the inside of the frame. A point with no drawable neighbour (a single
// row, or one between gaps) would draw nothing as a line, so it gets a small square.
void draw_curves(gdImagePtr im, const Layout& l, const std::vector<Curve>& curves) {
  gdImageSetClip(im, l.left + 1, l.top + 1, l.right - 1, l.bottom - 1);
  gdImageSetThickness(im, 2);
  for (std::size_t c = 0; c < curves.size(); ++c) {
    const Curve& curve = curves[c];
    const int colour = allocate(im, plot_line_colour(c));
    auto drawable = [&](std::size_t i) {
      return i < curve.x.size() && std::isfinite(curve.x[i]) && std::isfinite(curve.y[i]);
    };
    for (std::size_t i = 0; i < curve.x.size(); ++i) {
      if (!drawable(i)) continue;
      const int px = pixel(l.to_px(curve.x[i]));
      const int py = pixel(l.to_py(curve.y[i]));
      if (drawable(i + 1)) {
        gdImageLine(im, px, py, pixel(l.to_px(curve.x[i + 1])), pixel(l.to_py(curve.y[i + 1])),
                    colour);
      } else if (i == 0 || !drawable(i - 1)) {
        gdImageFilledRectangle(im, px - 2, py - 2, px + 2, py + 2, colour);
      }
    }
  }
  gdImageSetThickness(im, 1);
  gdImageSetClip(im, 0, 0, l.width - 1, l.height - 1);
}

// The references' entries of the legend, below the curves': a dashed line, or a filled box with
// dashed edges for a band, and the label.
void draw_reference_legend(gdImagePtr im, const Layout& l, const Fonts& fonts,
                           const std::vector<PlotReference>& references, std::size_t curves,
                           int black) {
  const int band = allocate(im, kBandColour);
  use_dashed_reference_style(im);
  for (std::size_t r = 0; r < references.size(); ++r) {
    const int y = l.top + 8 + static_cast<int>(curves + r) * (fonts.small->h + 6);
    const int x0 = l.right + 16, x1 = x0 + l.legend_sample, mid = y + fonts.small->h / 2;
    if (references[r].hi > references[r].lo) {
      gdImageFilledRectangle(im, x0, y + 1, x1, y + fonts.small->h - 1, band);
      gdImageLine(im, x0, y + 1, x1, y + 1, gdStyled);
      gdImageLine(im, x0, y + fonts.small->h - 1, x1, y + fonts.small->h - 1, gdStyled);
    } else {
      gdImageLine(im, x0, mid, x1, mid, gdStyled);
    }
    draw_text(im, fonts.small, x1 + 6, y, plot_ascii(references[r].label), black);
  }
}

// Title, axis labels, legend.
void draw_labels_and_legend(gdImagePtr im, const Layout& l, const Fonts& fonts,
                            const PlotRequest& request, const std::vector<Curve>& curves,
                            int black) {
  const std::string title =
      plot_ascii(request.title.empty() ? request.csv.filename().string() : request.title);
  const std::string x_label = plot_ascii(
      request.x_label.empty() ? default_axis_label({request.x}, request.x_scale) : request.x_label);
  const std::string y_label = plot_ascii(
      request.y_label.empty() ? default_axis_label(request.y, request.y_scale) : request.y_label);
  draw_text(im, fonts.title, std::max(4, (l.left + l.right - text_width(fonts.title, title)) / 2),
            12, title, black);
  draw_text(im, fonts.label, std::max(4, (l.left + l.right - text_width(fonts.label, x_label)) / 2),
            l.height - 10 - fonts.label->h, x_label, black);
  draw_text_up(im, fonts.label, 10, (l.top + l.bottom) / 2, y_label, black);
  gdImageSetThickness(im, 2);
  for (std::size_t c = 0; c < curves.size(); ++c) {
    const int y = l.top + 8 + static_cast<int>(c) * (fonts.small->h + 6);
    const int colour = allocate(im, plot_line_colour(c));
    gdImageLine(im, l.right + 16, y + fonts.small->h / 2, l.right + 16 + l.legend_sample,
                y + fonts.small->h / 2, colour);
    gdImageSetThickness(im, 1);
    draw_text(im, fonts.small, l.right + 16 + l.legend_sample + 6, y, curves[c].name, black);
    gdImageSetThickness(im, 2);
  }
  gdImageSetThickness(im, 1);
  draw_reference_legend(im, l, fonts, request.references, curves.size(), black);
}

void write_png(gdImagePtr im, const std::filesystem::path& png) {
  int size = 0;
  void* bytes = gdImagePngPtr(im, &size);
  if (!bytes) throw RunError("cannot encode the plot " + png.string() + " as PNG");
  const std::string content(static_cast<const char*>(bytes), static_cast<std::size_t>(size));
  gdFree(bytes);
  write_file_atomically(png, content);
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

  const PlotData data = read_curves(request, csv_name);
  const Fonts fonts;
  const Layout layout = lay_out(request, data, fonts);
  const int width = layout.width, height = layout.height;

  Image image(gdImageCreateTrueColor(width, height), gdImageDestroy);
  if (!image)
    throw RunError("cannot create a " + std::to_string(width) + "x" + std::to_string(height) +
                   " image for " + png.string());
  gdImagePtr im = image.get();
  const int white = allocate(im, 0xffffff), black = allocate(im, 0x000000);
  const int grid = allocate(im, 0xe6e6e6);
  gdImageFilledRectangle(im, 0, 0, width - 1, height - 1, white);

  draw_grid_and_ticks(im, layout, fonts, black, grid);
  draw_references(im, layout, request.references);
  draw_curves(im, layout, data.curves);
  gdImageRectangle(im, layout.left, layout.top, layout.right, layout.bottom, black);
  draw_labels_and_legend(im, layout, fonts, request, data.curves, black);
  write_png(im, png);
}

}  // namespace geompm

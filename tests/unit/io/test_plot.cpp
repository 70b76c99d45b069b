// The plots are checked as images: read back with libgd, the frame found as the two long
// horizontal and two long vertical black lines, and each curve found by its colour.
#include <gd.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "geompm/core/error.hpp"
#include "geompm/io/plot.hpp"
#include "geompm/io/plot_text.hpp"

namespace geompm {
namespace {

namespace fs = std::filesystem;

class PlotTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           (std::string("geompm_plot_") + info->name() + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }

  fs::path write_csv(const std::string& text) const {
    const fs::path file = dir_ / "history.csv";
    std::ofstream(file) << text;
    return file;
  }

  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename());
    std::sort(names.begin(), names.end());
    return names;
  }

  fs::path dir_;
};

std::string read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

using Image = std::unique_ptr<gdImage, decltype(&gdImageDestroy)>;

Image load_png(const fs::path& file) {
  std::string bytes = read_bytes(file);
  gdImagePtr image = gdImageCreateFromPngPtr(static_cast<int>(bytes.size()), bytes.data());
  if (!image) throw std::runtime_error("libgd cannot read " + file.string());
  return Image(image, gdImageDestroy);
}

unsigned rgb_at(gdImagePtr image, int x, int y) {
  const int c = gdImageGetTrueColorPixel(image, x, y);
  return (static_cast<unsigned>(gdTrueColorGetRed(c)) << 16) |
         (static_cast<unsigned>(gdTrueColorGetGreen(c)) << 8) |
         static_cast<unsigned>(gdTrueColorGetBlue(c));
}

struct Frame {
  int left = -1, right = -1, top = -1, bottom = -1;
};

/// The frame: the outermost rows and columns that are black over more than half the image.
Frame find_frame(gdImagePtr image) {
  const int w = gdImageSX(image), h = gdImageSY(image);
  Frame f;
  for (int y = 0; y < h; ++y) {
    int black = 0;
    for (int x = 0; x < w; ++x) black += rgb_at(image, x, y) == 0;
    if (black > w / 2) {
      if (f.top < 0) f.top = y;
      f.bottom = y;
    }
  }
  for (int x = 0; x < w; ++x) {
    int black = 0;
    for (int y = 0; y < h; ++y) black += rgb_at(image, x, y) == 0;
    if (black > h / 2) {
      if (f.left < 0) f.left = x;
      f.right = x;
    }
  }
  return f;
}

/// The pixels of one colour, split into those strictly inside the frame and the others.
struct ColourPixels {
  std::vector<std::pair<int, int>> inside, outside;

  std::pair<int, int> leftmost() const { return *std::min_element(inside.begin(), inside.end()); }
  std::pair<int, int> rightmost() const { return *std::max_element(inside.begin(), inside.end()); }
  int min_y() const {
    int m = 1 << 30;
    for (auto [x, y] : inside) m = std::min(m, y);
    return m;
  }
  int max_y() const {
    int m = -1;
    for (auto [x, y] : inside) m = std::max(m, y);
    return m;
  }
};

ColourPixels pixels_of(gdImagePtr image, unsigned rgb, const Frame& f) {
  ColourPixels found;
  for (int y = 0; y < gdImageSY(image); ++y)
    for (int x = 0; x < gdImageSX(image); ++x)
      if (rgb_at(image, x, y) == rgb) {
        const bool in = x > f.left && x < f.right && y > f.top && y < f.bottom;
        (in ? found.inside : found.outside).emplace_back(x, y);
      }
  return found;
}

/// Every pixel of a curve's colour is inside the frame, except the legend's short sample line,
/// which stands right of the frame.
void expect_curve_inside_frame(const ColourPixels& curve, const Frame& f) {
  EXPECT_GT(curve.inside.size(), 0u) << "the curve is not drawn";
  EXPECT_GT(curve.outside.size(), 0u) << "no legend sample";
  EXPECT_LT(curve.outside.size(), 100u) << "too much of the curve outside the frame";
  for (auto [x, y] : curve.outside) {
    EXPECT_GT(x, f.right) << "pixel (" << x << "," << y << ") left of or on the frame";
    EXPECT_GT(y, f.top) << "legend above the frame";
    EXPECT_LT(y, f.bottom) << "legend below the frame";
  }
}

/// A request for `y` against `x` from `csv`, the other settings left at their defaults.
PlotRequest request_for(const fs::path& csv, const std::string& x, std::vector<std::string> y) {
  PlotRequest request;
  request.csv = csv;
  request.x = x;
  request.y = std::move(y);
  return request;
}

constexpr const char* kPngSignature = "\x89PNG\r\n\x1a\n";

TEST_F(PlotTest, WritesAPngOfTheRequestedSizeAndNoTemporary) {
  const fs::path csv = write_csv("time,force\n0,0\n1,2\n2,3\n");
  PlotRequest request = request_for(csv, "time", {"force"});
  request.width = 640;
  request.height = 480;
  const fs::path png = dir_ / "force.png";
  plot_history(request, png);
  const std::string bytes = read_bytes(png);
  ASSERT_GE(bytes.size(), 8u);
  EXPECT_EQ(bytes.substr(0, 8), std::string(kPngSignature, 8));
  const Image image = load_png(png);
  EXPECT_EQ(gdImageSX(image.get()), 640);
  EXPECT_EQ(gdImageSY(image.get()), 480);
  EXPECT_EQ(entries(), (std::vector<std::string>{"force.png", "history.csv"}));
}

TEST_F(PlotTest, EachColumnIsACurveOfItsOwnColourInsideTheFrame) {
  std::string text = "displacement,load,unload\n";
  for (int i = 0; i <= 20; ++i)
    text += std::to_string(0.05 * i) + "," + std::to_string(i * i * 0.5) + "," +
            std::to_string(100.0 - 4.0 * i) + "\n";
  const fs::path csv = write_csv(text);
  const fs::path png = dir_ / "p.png";
  PlotRequest request = request_for(csv, "displacement", {"load", "unload"});
  request.title = "Load";
  plot_history(request, png);
  const Image image = load_png(png);
  const Frame f = find_frame(image.get());
  ASSERT_GE(f.top, 0);
  ASSERT_GE(f.left, 0);
  ASSERT_GT(f.right - f.left, 300);
  ASSERT_GT(f.bottom - f.top, 200);

  ASSERT_NE(plot_line_colour(0), plot_line_colour(1));
  const ColourPixels load = pixels_of(image.get(), plot_line_colour(0), f);
  const ColourPixels unload = pixels_of(image.get(), plot_line_colour(1), f);
  expect_curve_inside_frame(load, f);
  expect_curve_inside_frame(unload, f);
  EXPECT_GT(load.inside.size(), 300u);
  EXPECT_GT(unload.inside.size(), 300u);

  // Both curves span the x range, which fills the frame up to the margin of the end ticks.
  const int frame_width = f.right - f.left, frame_height = f.bottom - f.top;
  for (const ColourPixels* curve : {&load, &unload}) {
    EXPECT_LT(curve->leftmost().first - f.left, frame_width / 10);
    EXPECT_LT(f.right - curve->rightmost().first, frame_width / 10);
  }
  // "load" rises (image y shrinks to the right), "unload" falls; y axis points up.
  EXPECT_GT(load.leftmost().second, load.rightmost().second);
  EXPECT_LT(unload.leftmost().second, unload.rightmost().second);
  // The y range covers both curves: 0..200 for load, 20..100 for unload.
  EXPECT_LT(load.min_y() - f.top, frame_height / 10);
  EXPECT_LT(f.bottom - load.max_y(), frame_height / 10);

  // Text: tick labels left of and below the frame, a title above it.
  int left_text = 0, below_text = 0, above_text = 0;
  for (int y = 0; y < gdImageSY(image.get()); ++y)
    for (int x = 0; x < gdImageSX(image.get()); ++x) {
      if (rgb_at(image.get(), x, y) != 0) continue;
      left_text += x < f.left - 6;
      below_text += y > f.bottom + 6;
      above_text += y < f.top;
    }
  EXPECT_GT(left_text, 100);
  EXPECT_GT(below_text, 100);
  EXPECT_GT(above_text, 20);
}

TEST_F(PlotTest, ScaleFactorsAreApplied) {
  const fs::path csv = write_csv("u,f\n0,0\n1,1\n2,2\n3,3\n");
  // Negative y scale: the rising column is drawn falling.
  PlotRequest request = request_for(csv, "u", {"f"});
  request.y_scale = -1.0;
  plot_history(request, dir_ / "y.png");
  Image image = load_png(dir_ / "y.png");
  Frame f = find_frame(image.get());
  ColourPixels curve = pixels_of(image.get(), plot_line_colour(0), f);
  expect_curve_inside_frame(curve, f);
  EXPECT_LT(curve.leftmost().second, curve.rightmost().second);

  // Negative x scale: rising again, mirrored.
  request.x_scale = -1.0;
  plot_history(request, dir_ / "xy.png");
  image = load_png(dir_ / "xy.png");
  f = find_frame(image.get());
  curve = pixels_of(image.get(), plot_line_colour(0), f);
  expect_curve_inside_frame(curve, f);
  EXPECT_GT(curve.leftmost().second, curve.rightmost().second);

  // A large positive scale changes the numbers, not the shape: the curve still fills the frame.
  request.x_scale = 1e3;
  request.y_scale = 1e-3;
  plot_history(request, dir_ / "big.png");
  image = load_png(dir_ / "big.png");
  f = find_frame(image.get());
  curve = pixels_of(image.get(), plot_line_colour(0), f);
  expect_curve_inside_frame(curve, f);
  EXPECT_LT(curve.leftmost().first - f.left, (f.right - f.left) / 10);
  EXPECT_LT(f.right - curve.rightmost().first, (f.right - f.left) / 10);
}

TEST_F(PlotTest, ASingleRowIsDrawnAsAMark) {
  const fs::path csv = write_csv("time,force\n0.5,42\n");
  plot_history(request_for(csv, "time", {"force"}), dir_ / "one.png");
  const Image image = load_png(dir_ / "one.png");
  const Frame f = find_frame(image.get());
  const ColourPixels mark = pixels_of(image.get(), plot_line_colour(0), f);
  expect_curve_inside_frame(mark, f);
  EXPECT_GE(mark.inside.size(), 9u);
}

TEST_F(PlotTest, AConstantColumnIsAFlatLineInTheMiddle) {
  const fs::path csv = write_csv("time,force\n0,5\n1,5\n2,5\n3,5\n");
  plot_history(request_for(csv, "time", {"force"}), dir_ / "flat.png");
  const Image image = load_png(dir_ / "flat.png");
  const Frame f = find_frame(image.get());
  const ColourPixels line = pixels_of(image.get(), plot_line_colour(0), f);
  expect_curve_inside_frame(line, f);
  EXPECT_LE(line.max_y() - line.min_y(), 3);
  const int middle = (f.top + f.bottom) / 2;
  EXPECT_LT(std::abs(line.min_y() - middle), (f.bottom - f.top) / 10);
  EXPECT_GT(line.inside.size(), static_cast<std::size_t>(f.right - f.left));
}

TEST_F(PlotTest, NonFiniteValuesAreGapsNotRange) {
  const fs::path csv =
      write_csv("x,y\n0,0\n1,1\n2,nan\n3,3\n4,inf\n5,5\n6,-inf\n7,7\n8,8\n9,9\n10,10\n");
  plot_history(request_for(csv, "x", {"y"}), dir_ / "gaps.png");
  const Image image = load_png(dir_ / "gaps.png");
  const Frame f = find_frame(image.get());
  const ColourPixels curve = pixels_of(image.get(), plot_line_colour(0), f);
  expect_curve_inside_frame(curve, f);
  // The finite values 0..10 fill the frame in both directions: inf did not stretch the range.
  const int frame_width = f.right - f.left, frame_height = f.bottom - f.top;
  EXPECT_LT(curve.leftmost().first - f.left, frame_width / 10);
  EXPECT_LT(f.right - curve.rightmost().first, frame_width / 10);
  EXPECT_LT(curve.min_y() - f.top, frame_height / 10);
  EXPECT_LT(f.bottom - curve.max_y(), frame_height / 10);
  // The curve has gaps: the column of x = 2 (between 1 and 3, whose neighbours are missing) has
  // no pixel of the curve. Rows 3 and 5 are isolated and drawn as marks.
  const double x2 =
      curve.leftmost().first + 0.2 * (curve.rightmost().first - curve.leftmost().first);
  int at_gap = 0;
  for (auto [x, y] : curve.inside) at_gap += std::abs(x - x2) < 2;
  EXPECT_EQ(at_gap, 0);
}

TEST_F(PlotTest, AMissingColumnIsAnInputErrorListingTheColumns) {
  const fs::path csv = write_csv("time,force,displacement\n0,1,2\n");
  try {
    plot_history(request_for(csv, "time", {"force", "energy"}), dir_ / "p.png");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    for (const char* word : {"energy", "time", "force", "displacement", "history.csv"})
      EXPECT_NE(message.find(word), std::string::npos) << word << " not in: " << message;
  }
  EXPECT_THROW(plot_history(request_for(csv, "t", {"force"}), dir_ / "p.png"), InputError);
  EXPECT_FALSE(fs::exists(dir_ / "p.png"));
}

TEST_F(PlotTest, AMisspeltColumnSuggestsTheNearestOne) {
  const fs::path csv = write_csv("time,settlement,force\n0,1,2\n");
  try {
    plot_history(request_for(csv, "settlemnt", {"force"}), dir_ / "p.png");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean 'settlement'?"), std::string::npos)
        << e.what();
  }
}

// The reference colours of plot.cpp: dashed lines 0x404040, bands filled 0xf6e3c4.
constexpr unsigned kReferenceLine = 0x404040, kReferenceBand = 0xf6e3c4;

TEST_F(PlotTest, AReferenceLineIsDashedAcrossTheFrameAtItsValueAndWidensTheRange) {
  // The curve rises from 0 to 4; the reference at 5.14 lies above it, so the range grows to
  // show it.
  const fs::path csv = write_csv("u,q\n0,0\n1,2\n2,3\n3,4\n");
  PlotRequest request = request_for(csv, "u", {"q"});
  request.references = {{5.14, 5.14, "Prandtl"}};
  plot_history(request, dir_ / "p.png");
  const Image image = load_png(dir_ / "p.png");
  const Frame f = find_frame(image.get());
  const ColourPixels line = pixels_of(image.get(), kReferenceLine, f);
  const ColourPixels curve = pixels_of(image.get(), plot_line_colour(0), f);
  ASSERT_GT(line.inside.size(), 0u);
  // One row, above every pixel of the curve, dashed over most of the frame's width.
  EXPECT_EQ(line.min_y(), line.max_y());
  EXPECT_LT(line.min_y(), curve.min_y());
  EXPECT_GT(line.inside.size(), static_cast<std::size_t>((f.right - f.left) / 2));
  EXPECT_LT(line.inside.size(), static_cast<std::size_t>(f.right - f.left));
  EXPECT_GT(line.outside.size(), 0u) << "no legend sample";
}

TEST_F(PlotTest, AReferenceBandIsFilledBetweenItsValues) {
  const fs::path csv = write_csv("u,q\n0,0\n1,10\n");
  PlotRequest request = request_for(csv, "u", {"q"});
  request.references = {{4.0, 6.0, "band"}};
  plot_history(request, dir_ / "p.png");
  const Image image = load_png(dir_ / "p.png");
  const Frame f = find_frame(image.get());
  const ColourPixels band = pixels_of(image.get(), kReferenceBand, f);
  ASSERT_GT(band.inside.size(), 0u);
  // A fifth of the height of the 0..10 axis, give or take the insets and the curve over it.
  const double share = static_cast<double>(band.max_y() - band.min_y()) / (f.bottom - f.top);
  EXPECT_NEAR(share, 0.2, 0.03);
}

TEST(PlotText, DefaultLabelsShowTheScale) {
  EXPECT_EQ(default_axis_label({"settlement"}, 1.0), "settlement");
  EXPECT_EQ(default_axis_label({"settlement"}, -1.0), "-settlement");
  EXPECT_EQ(default_axis_label({"force"}, 2.0), "2 * force");
  EXPECT_EQ(default_axis_label({"a", "b"}, 0.5), "0.5 * a, 0.5 * b");
}

TEST(PlotText, NonAsciiTextIsSpeltInAscii) {
  EXPECT_EQ(plot_ascii("q/s_u against 2 + π"), "q/s_u against 2 + pi");
  EXPECT_EQ(plot_ascii("N_γ, φ = 30°"), "N_gamma, phi = 30 deg");
  EXPECT_EQ(plot_ascii("σ − σ₀ × 10"), "sigma - sigma? x 10");
  EXPECT_EQ(plot_ascii("plain"), "plain");
  EXPECT_EQ(plot_ascii(std::string("bad \xff byte")), "bad ? byte");
}

TEST_F(PlotTest, AMissingCsvIsAnInputErrorNamingTheFile) {
  const fs::path csv = dir_ / "no_such_history.csv";
  try {
    plot_history(request_for(csv, "time", {"force"}), dir_ / "p.png");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(csv.string()), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir_ / "p.png"));
}

}  // namespace
}  // namespace geompm

// The seed paper's pipe (§4.3) pushed into soft clay and left under its own weight:
// examples/structures/pipe_embedment.yaml (docs/validation.md §17). The example tier runs it and
// proves that it reproduces its committed reference history to 1e-10; what that history says is
// checked here against DNV-RP-F114's model 2 for the vertical penetration resistance and the
// self-weight embedment (docs/references.md §6), as issue 42 asks, and against the balance of
// the last phase (the pipe held by the soil alone carries exactly its weight, and rebounds little,
// as in the paper's Fig. 10).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "geompm/io/history_writer.hpp"
#include "reference_history.hpp"

namespace geompm {
namespace {

constexpr double kDiameter = 0.8, kWeight = 6.0, kUnitWeight = 6.5;

double strength_at_invert(double w) { return 2.3 + 3.6 * w; }

/// The area of the pipe's section below the mudline at embedment w (a circular segment).
double penetrated_area(double w) {
  const double r = kDiameter / 2;
  return r * r * std::acos((r - w) / r) - (r - w) * std::sqrt(2 * r * w - w * w);
}

/// DNV-RP-F114 model 2 (docs/references.md §6): Q_v = [min(6 (w/D)^0.25, 3.4 (10 w/D)^0.5)
/// + 1.5 gamma' A / (D s_u)] D s_u, s_u at the invert. 7.24 kN/m at w/D = 0.1 (the table there).
double dnv_resistance(double w) {
  const double su = strength_at_invert(w), ratio = w / kDiameter;
  const double bearing = std::min(6 * std::pow(ratio, 0.25), 3.4 * std::sqrt(10 * ratio));
  return (bearing + 1.5 * kUnitWeight * penetrated_area(w) / (kDiameter * su)) * kDiameter * su;
}

struct History {
  std::vector<double> time, w, q;  // w the embedment (m), q = 2 x contact force (kN/m)
  /// Mean of q, and of DNV's Q_v, over the push-in steps with w/D in [a, b].
  std::pair<double, double> means(double a, double b) const {
    double sum = 0, reference = 0;
    int n = 0;
    for (std::size_t k = 0; k < w.size(); ++k)
      if (time[k] > 1 && time[k] <= 2 + 1e-9 && w[k] >= a * kDiameter - 1e-12 &&
          w[k] <= b * kDiameter + 1e-12) {
        sum += q[k], reference += dnv_resistance(w[k]), ++n;
      }
    EXPECT_GT(n, 3) << "steps in w/D [" << a << ", " << b << "]";
    return {sum / n, reference / n};
  }
};

History reference_history() {
  const auto path = testing::reference_history_path("structures/pipe_embedment.yaml");
  const CsvTable table = read_csv(path);
  const std::size_t t = table.column("time", path.string()),
                    w = table.column("embedment", path.string()),
                    f = table.column("force", path.string());
  History h;
  for (const auto& row : table.rows) {
    h.time.push_back(row[t]);
    h.w.push_back(-row[w]);
    h.q.push_back(2 * row[f]);
  }
  return h;
}

TEST(PipeEmbedment, DnvsModelGivesTheFormulasTable) {
  // docs/references.md §6: Q_v = 4.79, 7.24, 9.93, 12.48 kN/m at w/D = 0.05, 0.1, 0.2, 0.3.
  EXPECT_NEAR(dnv_resistance(0.05 * kDiameter), 4.79, 0.01);
  EXPECT_NEAR(dnv_resistance(0.1 * kDiameter), 7.24, 0.01);
  EXPECT_NEAR(dnv_resistance(0.2 * kDiameter), 9.93, 0.01);
  EXPECT_NEAR(dnv_resistance(0.3 * kDiameter), 12.48, 0.01);
}

TEST(PipeEmbedment, PenetrationResistanceFollowsDnv) {
  // The curve swings by up to about 20 % around its trend as the pipe's surface crosses cells
  // (docs/validation.md §17), so it is compared over windows of 0.05 D: measured -4.0 to +1.3 %
  // of DNV, within the +-25 % band of docs/references.md §6.
  const History h = reference_history();
  ASSERT_NEAR(*std::max_element(h.w.begin(), h.w.end()), 0.2 * kDiameter, 1e-9);
  for (const double centre : {0.05, 0.1, 0.15}) {
    const auto [q, reference] = h.means(centre - 0.025, centre + 0.025);
    EXPECT_NEAR(q, reference, 0.25 * reference) << "w/D around " << centre;
  }
  const auto [q, reference] = h.means(0.175, 0.2);
  EXPECT_NEAR(q, reference, 0.25 * reference) << "w/D 0.175-0.2";
}

TEST(PipeEmbedment, SelfWeightEmbedmentIsInTheBands) {
  // Where the pushed pipe's resistance first reaches its weight: the embedment it would sink to
  // under its weight alone. DNV model 2: w/D = 0.073, and the plasticity fits about 0.09, each
  // used as a +-25 % band (references §6, §8).
  // Measured 0.074 (also within the band of the plasticity fits of §8: 0.09 +- 25 %).
  const History h = reference_history();
  std::size_t k = 0;
  while (k < h.q.size() && !(h.time[k] > 1 && h.q[k] >= kWeight)) ++k;
  ASSERT_LT(k, h.q.size()) << "the resistance never reached the pipe's weight";
  const double a = (kWeight - h.q[k - 1]) / (h.q[k] - h.q[k - 1]);
  const double embedment = (h.w[k - 1] + a * (h.w[k] - h.w[k - 1])) / kDiameter;
  EXPECT_GE(embedment, 0.75 * 0.073);
  EXPECT_LE(embedment, 1.25 * 0.073);
  EXPECT_GE(embedment, 0.75 * 0.09);
  EXPECT_LE(embedment, 1.25 * 0.09);
}

TEST(PipeEmbedment, LeftUnderItsWeightThePipeIsCarriedByTheSoilAndReboundsLittle) {
  // The last phase leaves the pipe's vertical motion free: the soil's contact force balances its
  // weight (6 kN/m) to Newton's tolerance, and it rebounds elastically by a small fraction of
  // its embedment (the paper's Fig. 10: "very little rebound"; measured 0.0019 D).
  const History h = reference_history();
  ASSERT_NEAR(h.time.back(), 3.0, 1e-9);
  EXPECT_NEAR(h.q.back(), kWeight, 1e-6 * kWeight);
  const double rebound = (0.2 * kDiameter - h.w.back()) / kDiameter;
  EXPECT_GE(rebound, 0.0);
  EXPECT_LE(rebound, 0.01);
}

}  // namespace
}  // namespace geompm

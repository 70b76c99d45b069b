// Axial vibration of an elastic bar: Bardenhagen (2002), J. Comput. Phys. 180, §4.2
// (docs/references.md §1). Runs examples/vibrating_bar/vibrating_bar.yaml.
#include <gtest/gtest.h>

#include <cmath>

#include "run_model.hpp"

namespace geompm {
namespace {

TEST(VibratingBar, PeriodAmplitudeAndEnergyMatchTheClosedForm) {
  const auto run =
      testing::run_spec(testing::read_example("vibrating_bar/vibrating_bar.yaml"), "vibrating_bar");
  const auto t = run.column("time");
  const auto v = run.column("v_cm");
  const auto kinetic = run.column("kinetic_energy");
  const auto strain = run.column("strain_energy");

  // Period from the zero crossings of the centre-of-mass velocity (linear interpolation).
  std::vector<double> crossings;
  for (std::size_t i = 0; i + 1 < v.size(); ++i)
    if (v[i] * v[i + 1] < 0)
      crossings.push_back(t[i] - v[i] * (t[i + 1] - t[i]) / (v[i + 1] - v[i]));
  ASSERT_GE(crossings.size(), 9u);  // five periods
  const double period = 2.0 * (crossings.back() - crossings.front()) / (crossings.size() - 1);
  const double exact_period = 10.0;  // T1 = 4L / sqrt(E/rho) = 100 / 10
  EXPECT_NEAR(period, exact_period, 0.01 * exact_period);

  double amplitude = 0.0;
  for (double value : v) amplitude = std::max(amplitude, std::abs(value));
  const double exact_amplitude = 2.0 * 0.1 / M_PI;  // 2 v0 / pi = 0.0636620
  EXPECT_NEAR(amplitude, exact_amplitude, 0.02 * exact_amplitude);

  // Total energy: rho v0^2 L / 4 per unit section, times the section 25/13 of the model.
  const double section = 25.0 / 13.0;
  const double exact_energy = 1.0 * 0.01 * 25.0 / 4.0 * section;
  const double e0 = kinetic.front() + strain.front();
  EXPECT_NEAR(e0, exact_energy, 1e-3 * exact_energy);  // the seeded state (quadrature of sin^2)
  double worst = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i)
    worst = std::max(worst, std::abs(kinetic[i] + strain[i] - e0) / e0);
  EXPECT_LT(worst, 0.01) << "energy drift over five periods";
  EXPECT_GT(t.back(), 5 * exact_period - 1e-9);
}

}  // namespace
}  // namespace geompm

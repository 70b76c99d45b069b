// Time integration of dynamic phases (docs/theory.md §4.7):
// - a dynamic phase starts from the acceleration in balance with its loads (eq. 4.7e): a block
//   falling freely under suddenly applied gravity follows u = g t^2 / 2 and v = g t exactly, which
//   the trapezoidal rule integrates without error for a constant acceleration;
// - Bossak's scheme (the `damped` preset) damps the vibrating bar's first mode by the scheme's own
//   spectral radius and lengthens its period by the scheme's own period error, both worked out
//   here from its amplification matrix, independently of the code's Newmark struct.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "run_model.hpp"

namespace geompm {
namespace {

constexpr const char* falling_block = R"(
title: Free fall
analysis: {kinematics: plane_strain}
mesh:
  generate: {cell: quad4, origin: [0, 0], x: {length: 4, cells: 4}, y: {length: 12, cells: 12}}
materials:
  block: {model: linear_elastic, E: 1.0e4, nu: 0.3, density: 2}
bodies:
  block: {material: block, region: {box: {min: [1, 9], max: [3, 11]}}, points_per_cell: 4}
point_sets:
  all: {body: block, region: all}
phases:
  - name: fall
    duration: 1.0
    time_step: 0.05
    dynamics: newmark
    gravity: {acceleration: [0, -10]}
output:
  vtk: {every: 0}
  history:
    - {quantity: displacement, point_set: all, component: y, name: uy}
    - {quantity: velocity, point_set: all, component: y, name: vy}
)";

TEST(TimeIntegration, AFreelyFallingBlockFollowsTheExactMotionFromItsFirstStep) {
  const auto run = testing::run_spec(read_model_from_string(falling_block, "fall.yaml"), "fall");
  const auto t = run.column("time");
  const auto uy = run.column("uy");
  const auto vy = run.column("vy");
  ASSERT_GE(t.size(), 20u);
  for (std::size_t i = 0; i < t.size(); ++i) {
    // Without the consistent start a0 = 0, the velocity lags by g dt / 2 = 0.25 for ever.
    EXPECT_NEAR(vy[i], -10.0 * t[i], 1e-8) << "at t = " << t[i];
    EXPECT_NEAR(uy[i], -5.0 * t[i] * t[i], 1e-8) << "at t = " << t[i];
  }
}

// A column on a fixed base under suddenly applied gravity, small strain (E = 10^5 kPa: the top
// moves 0.5 % of a cell): the closed form of the 1D wave equation has the top oscillate between 0
// and twice the static settlement rho g H^2 / 2E = 0.01 m with the period 4 H / c of the first
// mode, c = sqrt(E / rho), and a mean of the static settlement over whole periods. Standard and
// GIMP interpolation alike (GIMP once showed a bias of 1-2.5 % here).
constexpr const char* suddenly_loaded_column = R"(
title: Column under suddenly applied gravity
analysis: {kinematics: plane_strain}
mesh:
  generate: {cell: quad4, origin: [0, 0], x: {length: 1, cells: 1}, y: {length: 52, cells: 26}}
materials:
  soil: {model: linear_elastic, E: 1.0e5, nu: 0.0, density: 0.08}
bodies:
  column: {material: soil, region: {box: {min: [0, 0], max: [1, 50]}}, points_per_cell: 4}
point_sets:
  top: {body: column, region: {box: {min: [0, 49.4], max: [1, 50]}}}
phases:
  - name: gravity
    duration: 0.53666
    time_step: 0.0017889
    dynamics: newmark
    newton: {max_iterations: 10, residual_tolerance: 1.0e-9, displacement_tolerance: 1.0e-9}
    gravity: {acceleration: [0, -10]}
    fixities:
      - {boundary: left, fix: normal}
      - {boundary: right, fix: normal}
      - {boundary: bottom, fix: all}
output:
  vtk: {every: 0}
  history:
    - {quantity: displacement, point_set: top, component: y, name: top}
numerics: {interpolation: INTERPOLATION}
)";

TEST(TimeIntegration, AColumnUnderSuddenlyAppliedGravityOscillatesAboutItsStaticSettlement) {
  const double H = 50.0, E = 1.0e5, rho = 0.08, g = 10.0;
  const double settlement = rho * g * H * H / (2 * E);  // 0.01 m
  const double period = 4 * H / std::sqrt(E / rho);     // 0.17889 s; the phase is three
  for (const std::string interpolation : {"standard", "gimp"}) {
    std::string text = suddenly_loaded_column;
    text.replace(text.find("INTERPOLATION"), 13, interpolation);
    const auto run = testing::run_spec(read_model_from_string(text, "column.yaml"),
                                       "sudden_column_" + interpolation);
    const auto t = run.column("time");
    const auto top = run.column("top");
    double sum = 0.0, lowest = 0.0;
    for (double u : top) sum += u, lowest = std::min(lowest, u);
    const double mean = sum / double(top.size());
    std::vector<double> crossings;
    for (std::size_t i = 0; i + 1 < top.size(); ++i)
      if ((top[i] - mean) * (top[i + 1] - mean) < 0)
        crossings.push_back(t[i] + (mean - top[i]) * (t[i + 1] - t[i]) / (top[i + 1] - top[i]));
    ASSERT_GE(crossings.size(), 5u) << interpolation;
    const double measured =
        2.0 * (crossings.back() - crossings.front()) / double(crossings.size() - 1);
    EXPECT_NEAR(mean, -settlement, 0.01 * settlement) << interpolation;
    EXPECT_NEAR(lowest, -2 * settlement, 0.01 * settlement) << interpolation;
    EXPECT_NEAR(measured, period, 0.01 * period) << interpolation;
  }
}

// The amplification matrix of Bossak's scheme on m x'' + k x = 0 with Omega = omega dt, on the
// state (x, dt v, dt^2 a) (Wood, Bossak & Zienkiewicz 1980): its complex eigenvalue gives the
// decay per step |lambda| and the period 2 pi / arg(lambda) steps.
std::complex<double> principal_root(double omega_dt, double alpha_m) {
  const double beta = 0.25 * (1 - alpha_m) * (1 - alpha_m), gamma = 0.5 - alpha_m;
  const double w2 = omega_dt * omega_dt;
  Eigen::Matrix3d A;
  for (int j = 0; j < 3; ++j) {
    Eigen::Vector3d s = Eigen::Vector3d::Unit(j);
    // (1 - alpha_m) a1 + alpha_m a0 + omega^2 x1 = 0 with x1 from Newmark's update.
    const double a1 =
        -(alpha_m * s(2) + w2 * (s(0) + s(1) + (0.5 - beta) * s(2))) / ((1 - alpha_m) + w2 * beta);
    A.col(j) << s(0) + s(1) + (0.5 - beta) * s(2) + beta * a1,
        s(1) + (1 - gamma) * s(2) + gamma * a1, a1;
  }
  const Eigen::Vector3cd roots = A.eigenvalues();
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(roots(i).imag()) > std::abs(roots(k).imag())) k = i;
  return roots(k);
}

struct Oscillation {
  double period = 0.0;
  double decay_per_period = 0.0;  // ratio of successive amplitudes
};

// The centre-of-mass velocity's period (zero crossings) and its amplitude decay (a log-linear fit
// of the extremes between crossings).
Oscillation measure(const testing::ModelRun& run) {
  const auto t = run.column("time");
  const auto v = run.column("v_cm");
  std::vector<double> crossings, peak_time, peak_log;
  double extreme = 0.0, extreme_time = 0.0;
  for (std::size_t i = 0; i + 1 < v.size(); ++i) {
    if (std::abs(v[i]) > std::abs(extreme)) extreme = v[i], extreme_time = t[i];
    if (v[i] * v[i + 1] < 0) {
      crossings.push_back(t[i] - v[i] * (t[i + 1] - t[i]) / (v[i + 1] - v[i]));
      if (crossings.size() > 1)
        peak_time.push_back(extreme_time), peak_log.push_back(std::log(std::abs(extreme)));
      extreme = 0.0;
    }
  }
  Oscillation o;
  if (crossings.size() < 3 || peak_time.size() < 2) return o;
  o.period = 2.0 * (crossings.back() - crossings.front()) / double(crossings.size() - 1);
  double st = 0, sl = 0, stt = 0, stl = 0;
  const double n = double(peak_time.size());
  for (std::size_t i = 0; i < peak_time.size(); ++i) {
    st += peak_time[i], sl += peak_log[i], stt += peak_time[i] * peak_time[i];
    stl += peak_time[i] * peak_log[i];
  }
  const double slope = (n * stl - st * sl) / (n * stt - st * st);
  o.decay_per_period = std::exp(slope * o.period);
  return o;
}

TEST(TimeIntegration, TheDampedPresetDampsAndSlowsTheBarAsBossaksSchemeSays) {
  // Ten steps a period: Omega = 0.63, where the damped preset (alpha_m = -0.1) takes 1.8 % of the
  // amplitude a period and the trapezoidal rule none.
  auto spec = testing::read_example("vibrating_bar/vibrating_bar.yaml");
  spec.phases[0].time_step = {1.0, 0.01, 1.0};
  const auto trapezoidal = measure(testing::run_spec(spec, "bar_trapezoidal"));
  spec.phases[0].dynamics.alpha_m = spec::damped_alpha_m;
  spec.phases[0].dynamics.beta = 0.25 * 1.1 * 1.1;
  spec.phases[0].dynamics.gamma = 0.6;
  const auto damped = measure(testing::run_spec(spec, "bar_damped"));
  ASSERT_GT(trapezoidal.period, 0.0);
  ASSERT_GT(damped.period, 0.0);

  // The mesh's own first mode: its frequency from the trapezoidal run, whose period error
  // (Omega^2 / 12 to leading order) is known exactly from its root.
  const double dt = 1.0;
  const double measured_arg = 2 * M_PI * dt / trapezoidal.period;  // phase advance per step
  double omega_dt = measured_arg;  // fixed point: the mesh's frequency times dt
  for (int i = 0; i < 50; ++i) omega_dt *= measured_arg / std::arg(principal_root(omega_dt, 0.0));
  const std::complex<double> root = principal_root(omega_dt, spec::damped_alpha_m);
  const double steps_per_period = 2 * M_PI / std::arg(root);
  const double expected_decay = std::pow(std::abs(root), steps_per_period);
  // The grid's own mapping loses a little of the amplitude too (the points' accelerations are
  // projected on the grid at each step, which smooths them): 0.7 % a period at this step.
  EXPECT_GT(trapezoidal.decay_per_period, 0.99);
  // What the scheme takes on top of it, against its amplification matrix. The scheme's old
  // acceleration (eq. 4.7c) is the projected one, not the grid's own, so the two agree to 15 %.
  const double scheme_decay = damped.decay_per_period / trapezoidal.decay_per_period;
  EXPECT_NEAR(1.0 - scheme_decay, 1.0 - expected_decay, 0.15 * (1.0 - expected_decay));
  const double expected_ratio =
      (2 * M_PI / std::arg(root)) / (2 * M_PI / std::arg(principal_root(omega_dt, 0.0)));
  EXPECT_NEAR(damped.period / trapezoidal.period, expected_ratio, 0.002);
}

}  // namespace
}  // namespace geompm

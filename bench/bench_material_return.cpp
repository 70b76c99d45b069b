// Times one stress update of the Mohr-Coulomb model per material point: the exact return to the
// cone's planes (docs/materials.md §3.2-3.3) against the Newton return to the smooth hyperbolic
// surface (`apex_rounding`, §3.6), on the same trial strains. The states are drawn once: plastic
// trial states along the cone (the bulk of a plastic zone) and beyond the apex (the points at a
// free surface, where the rounded return may fall back to continuation). Each benchmark updates
// all of them; the time per update is the reported time / states (counter `states`).
// bench/run_benchmarks.sh runs it (5 repetitions) and bench/material_return_table.py puts the
// medians into docs/performance.md.
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <vector>

#include "geompm/materials/mohr_coulomb.hpp"
#include "geompm/materials/parameters.hpp"

namespace geompm::bench {
namespace {

constexpr int states = 4096;
constexpr double c = 10, phi = 30, psi = 30, E = 1e4, nu = 0.3;

// Through the model file's parameters, as a model file sets them (the cone with its default
// cut-off at the apex, or the rounded surface).
std::unique_ptr<Material> soil(double rounding) {
  ParameterMap p{{"c", c}, {"phi", phi}, {"psi", psi}, {"E", E}, {"nu", nu}};
  if (rounding > 0) p["apex_rounding"] = rounding;
  return MohrCoulomb::create(p);
}

// Trial strains of random orientation whose stresses lie around `mean` (kPa) with a deviator of
// `spread`: far beyond the surface at p = -100, or around the apex (17.3 kPa) at p = +20.
std::vector<Mat3> trial_strains(double mean, double spread) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  const Mat3 compliance = principal_elasticity(lame_lambda(E, nu), shear_modulus(E, nu)).inverse();
  std::vector<Mat3> out;
  for (int k = 0; k < states; ++k) {
    const Vec3 stress = Vec3::Constant(mean) + spread * Vec3(u(rng), u(rng), u(rng));
    const Vec3 principal = compliance * stress;
    const Eigen::Quaterniond q(u(rng), u(rng), u(rng), u(rng));
    const Mat3 r = q.normalized().toRotationMatrix();
    out.push_back(r * principal.asDiagonal() * r.transpose());
  }
  return out;
}

void update_all(benchmark::State& state, double rounding, double mean, double spread) {
  const std::unique_ptr<Material> model = soil(rounding);
  const std::vector<Mat3> strains = trial_strains(mean, spread);
  StressUpdate out;
  for (auto _ : state)
    for (const Mat3& eps : strains) {
      model->update(eps, {}, out);
      benchmark::DoNotOptimize(out.kirchhoff);
    }
  state.SetItemsProcessed(state.iterations() * states);
  state.counters["states"] = states;
}

BENCHMARK_CAPTURE(update_all, cone_along, 0.0, -100.0, 80.0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(update_all, rounded_along, 2.0, -100.0, 80.0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(update_all, cone_apex, 0.0, 20.0, 10.0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(update_all, rounded_apex, 2.0, 20.0, 10.0)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace geompm::bench

BENCHMARK_MAIN();

// The linear solvers on whole steps of the benchmark block (step_case.hpp; issue 44): for each
// size and solver, the median over repeated steps from the same state of the step's wall time,
// the linear solver's share of it (setups and solves), Newton iterations, Krylov iterations per
// Newton solve and the step's peak resident memory per point; one line of a markdown table per
// case (bench/solver_timings.md, docs/performance.md note 17).
//
//   build/bench/bench_solvers                      50,160 cells; umfpack, petsc_gamg, petsc_hypre
//   GEOMPM_BENCH_CELLS=500 GEOMPM_BENCH_SOLVERS=petsc_gamg GEOMPM_BENCH_REPETITIONS=3
//     build/bench/bench_solvers                    (one line)
//   GEOMPM_BENCH_FORMULATION=mixed ...             the mixed p-u block (nu = 0.49)
//   GEOMPM_BENCH_DIMENSION=3 GEOMPM_BENCH_CELLS=24,50 ...   the 3D block (cells^3 Hex8 cells)
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "process_memory.hpp"
#include "step_case.hpp"

namespace {

using geompm::bench::Formulation;
using geompm::bench::StepCase;

std::vector<std::string> list_from_environment(const char* name, const char* fallback) {
  const char* text = std::getenv(name);
  std::stringstream in(text ? text : fallback);
  std::vector<std::string> items;
  for (std::string item; std::getline(in, item, ',');) items.push_back(item);
  return items;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct Row {
  double step = 0, linear = 0, newton = 0, krylov_per_solve = 0, peak_per_point = 0;
};

// `repetitions` whole steps from the same state; the first, which also pays the solver's
// one-off costs (PETSc's initialisation, first allocations), is left out.
Row measure(int cells, Formulation formulation, bool three_d, const std::string& solver,
            int repetitions) {
  StepCase c(cells, formulation, three_d);
  c.model().spec.numerics.linear_solver = solver;
  c.save_points();
  geompm::bench::reset_peak_resident();
  std::vector<double> step, linear, newton, krylov;
  for (int r = 0; r <= repetitions; ++r) {
    c.restore_points();
    const auto start = std::chrono::steady_clock::now();
    c.full_step();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (r == 0) continue;
    const auto& n = c.last_step().newton;
    step.push_back(seconds);
    linear.push_back(n.linear_seconds);
    newton.push_back(n.iterations);
    krylov.push_back(double(n.linear_iterations) / std::max(1, n.iterations));
  }
  const double peak = double(geompm::bench::peak_resident_bytes()) - double(c.baseline_resident()) -
                      c.saved_points_bytes();
  return {median(step), median(linear), median(newton), median(krylov), peak / double(c.points())};
}

}  // namespace

int main() {
  const auto cells = list_from_environment("GEOMPM_BENCH_CELLS", "50,160");
  const auto solvers =
      list_from_environment("GEOMPM_BENCH_SOLVERS", "umfpack,petsc_gamg,petsc_hypre");
  const char* reps = std::getenv("GEOMPM_BENCH_REPETITIONS");
  const int repetitions = reps ? std::max(1, std::atoi(reps)) : 5;
  const char* form = std::getenv("GEOMPM_BENCH_FORMULATION");
  const bool mixed = form && std::string(form) == "mixed";
  const Formulation formulation = mixed ? Formulation::MixedCellAverage : Formulation::Displacement;
  const char* dimension = std::getenv("GEOMPM_BENCH_DIMENSION");
  const bool three_d = dimension && std::string(dimension) == "3";
  std::cout << "| cells | points | formulation | solver | step (s) | linear solver (s) | "
               "Newton iterations | Krylov iterations per solve | step peak (B/point) |\n"
               "|---|---|---|---|---|---|---|---|---|\n";
  for (const std::string& size : cells)
    for (const std::string& solver : solvers) {
      const int n = std::stoi(size);
      const Row row = measure(n, formulation, three_d, solver, repetitions);
      const long points = three_d ? 8L * n * n * (n - 1) : 4L * n * (n - 1);
      std::cout << fmt::format("| {} | {} | {} | {} | {:.3f} | {:.3f} | {:g} | {:.1f} | {:.0f} |\n",
                               three_d ? fmt::format("{}^3", n) : std::to_string(n), points,
                               mixed ? "mixed" : "displacement", solver, row.step, row.linear,
                               row.newton, row.krylov_per_solve, row.peak_per_point)
                << std::flush;
    }
}

// Times one implicit step of geompm split into its phases, at sizes from 10^4 to 10^6 material
// points in 2D, and measures the memory a point costs (docs/performance.md, written from this
// program's JSON output by bench/make_performance_doc.py).
//
//   map              phase 1: GridSystem::initialise + external_force
//   constraints      fixities -> constrained dofs, StepSystem::build_pattern (numbering, pattern,
//   scatter maps) internal_force   one Newton iteration's non-solve work: stress update, f_int,
//   tangent
//                    assembly; on 1 thread (the per-core rate) and on every core
//   analyze          UMFPACK symbolic analysis (once per step)
//   factorize_solve  UMFPACK numeric factorisation + one solve (once per Newton iteration)
//   convect          phase 3: GridSystem::convect + relocation with the model's PointLocator
//   step             StepSolver::advance, the whole step, from the same state every time; also
//                    the memory per point: heap held by each stage, peak resident set of a step
//
// internal_force (1 thread), factorize_solve and step also run with the soil in the mixed p-u
// formulation, with per-point and cell-averaged volume change, with the material at the field's
// pressure, and with the incremental pressure equation started from the fitted last pressure
// (".../formulation:<name>"), at the sizes below 300 cells per side.
//
// Benchmarks are registered size by size, so one model is in memory at a time. Every timing is
// wall-clock (the loops are OpenMP-parallel) and repeated; the doc reports the medians. The CPU
// time is the whole process's (all threads): on a machine shared with other work it is the
// better measure of the work done, since wall-clock time then includes time spent waiting for
// a core.
//
// Environment: GEOMPM_BENCH_CELLS="50,160,500" (cells per side; 4 (cells - 1) cells points),
// GEOMPM_BENCH_REPETITIONS=5.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "process_memory.hpp"
#include "step_case.hpp"

namespace geompm::bench {
namespace {

std::vector<int> sizes_from_environment() {
  std::vector<int> sizes;
  const char* text = std::getenv("GEOMPM_BENCH_CELLS");
  std::stringstream list(text ? text : "50,160,500");
  for (std::string item; std::getline(list, item, ',');)
    if (!item.empty()) sizes.push_back(std::stoi(item));
  return sizes;
}

int repetitions_from_environment() {
  const char* text = std::getenv("GEOMPM_BENCH_REPETITIONS");
  return text ? std::max(1, std::atoi(text)) : 5;
}

int all_cores() { return omp_get_num_procs(); }

// Sets the OpenMP thread count for one benchmark and puts the default back afterwards, so a
// single-threaded variant cannot leak into the next benchmark.
class Threads {
 public:
  explicit Threads(int n) { omp_set_num_threads(n); }
  ~Threads() { omp_set_num_threads(all_cores()); }
};

void count_points(benchmark::State& state, StepCase& c, int threads) {
  const double points = double(c.points());
  state.counters["points"] = points;
  state.counters["threads"] = threads;
  state.counters["points_per_s"] =
      benchmark::Counter(points, benchmark::Counter::kIsIterationInvariantRate);
}

void map(benchmark::State& state, int cells) {
  StepCase& c = step_case(cells);
  Threads threads(all_cores());
  c.map();  // first call sorts and allocates; later ones are what a step does
  for (auto _ : state) c.map();
  count_points(state, c, all_cores());
  state.counters["active_nodes"] = double(c.grid().active_nodes().size());
  state.counters["active_cells"] = double(c.grid().grid().cell_fill().size());
}

void constraints(benchmark::State& state, int cells) {
  StepCase& c = step_case(cells);
  Threads threads(all_cores());
  c.constrain();
  for (auto _ : state) c.constrain();
  count_points(state, c, all_cores());
  state.counters["free_dofs"] = double(c.grid().system().dofs().num_free());
  state.counters["nnz"] = double(c.grid().system().tangent().nonZeros());
}

void internal_force(benchmark::State& state, int cells, int n_threads, Formulation formulation) {
  StepCase& c = step_case(cells, formulation);
  Threads threads(n_threads);
  c.evaluate();
  for (auto _ : state) c.evaluate();
  count_points(state, c, n_threads);
  // The target is per core: the rate divided by the threads that produced it.
  state.counters["points_per_s_per_core"] = benchmark::Counter(
      double(c.points()) / n_threads, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["nnz"] = double(c.tangent().nonZeros());
}

void analyze(benchmark::State& state, int cells) {
  StepCase& c = step_case(cells);
  Threads threads(all_cores());
  c.analyse();
  for (auto _ : state) c.analyse();
  count_points(state, c, all_cores());
  state.counters["free_dofs"] = double(c.tangent().rows());
  state.counters["nnz"] = double(c.tangent().nonZeros());
}

void factorize_solve(benchmark::State& state, int cells, Formulation formulation) {
  StepCase& c = step_case(cells, formulation);
  Threads threads(all_cores());
  c.analyse();
  c.factorize_and_solve();  // the solver's symbolic analysis, at its first setup, untimed
  for (auto _ : state) c.factorize_and_solve();
  count_points(state, c, all_cores());
  state.counters["free_dofs"] = double(c.tangent().rows());
  state.counters["nnz"] = double(c.tangent().nonZeros());
}

void convect(benchmark::State& state, int cells) {
  StepCase& c = step_case(cells);
  Threads threads(all_cores());
  c.evaluate();
  for (auto _ : state) {
    c.convect_and_relocate();
    state.PauseTiming();
    c.undo_convect();
    state.ResumeTiming();
  }
  count_points(state, c, all_cores());
}

void step(benchmark::State& state, int cells, Formulation formulation) {
  StepCase& c = step_case(cells, formulation);
  Threads threads(all_cores());
  // Memory: the heap each stage holds (measured when the stages were first built), then the
  // peak resident set of whole steps on their own, with the stage-by-stage state dropped.
  c.build_all_stages();
  const StageMemory held = c.memory();
  const double point_store = c.model().points.bytes_per_point();
  c.release_stages();  // the step solver has a grid of its own
  c.save_points();
  const bool peak_known = reset_peak_resident();
  int iterations = 0;
  for (auto _ : state) {
    state.PauseTiming();
    c.restore_points();  // every timed step starts from the same state
    state.ResumeTiming();
    iterations = c.full_step();
  }
  // Above the process before the model was built, less the saved copy of the points, which
  // only the benchmark needs.
  const double peak =
      double(peak_resident_bytes()) - double(c.baseline_resident()) - c.saved_points_bytes();

  count_points(state, c, all_cores());
  const double n = double(c.points());
  state.counters["newton_iterations"] = iterations;
  state.counters["point_store_B_per_point"] = point_store;
  state.counters["model_B_per_point"] = held.model / n;
  state.counters["grid_B_per_point"] = held.grid / n;
  state.counters["solver_B_per_point"] = held.solver / n;
  state.counters["step_peak_B_per_point"] = peak_known ? peak / n : -1.0;
}

void register_all() {
  const int repetitions = repetitions_from_environment();
  // A run of factorize_solve or of a whole step at 10^6 points takes 5 to 25 s with OpenBLAS
  // under UMFPACK, and minutes with the reference BLAS: those repeat fewer times so the suite
  // stays within ten minutes on two cores. Three repetitions still give a median.
  const auto timed = [&](benchmark::internal::Benchmark* b, bool heavy = false) {
    b->Repetitions(heavy ? std::min(repetitions, 3) : repetitions)
        ->ReportAggregatesOnly(true)
        ->UseRealTime()
        ->MeasureProcessCPUTime()
        ->MinTime(0.2)
        ->Unit(benchmark::kMillisecond);
  };
  for (int cells : sizes_from_environment()) {
    const bool heavy = cells >= 300;
    const std::string size = "/cells:" + std::to_string(cells);
    timed(benchmark::RegisterBenchmark(("map" + size).c_str(), map, cells));
    timed(benchmark::RegisterBenchmark(("constraints" + size).c_str(), constraints, cells));
    for (int t : {1, all_cores()}) {
      timed(benchmark::RegisterBenchmark(
          ("internal_force" + size + "/threads:" + std::to_string(t)).c_str(), internal_force,
          cells, t, Formulation::Displacement));
      if (all_cores() == 1) break;
    }
    timed(benchmark::RegisterBenchmark(("analyze" + size).c_str(), analyze, cells));
    timed(benchmark::RegisterBenchmark(("factorize_solve" + size).c_str(), factorize_solve, cells,
                                       Formulation::Displacement),
          heavy);
    timed(benchmark::RegisterBenchmark(("convect" + size).c_str(), convect, cells));
    timed(benchmark::RegisterBenchmark(("step" + size).c_str(), step, cells,
                                       Formulation::Displacement),
          heavy);
  }
  // The mixed p-u formulation against the displacement one, at the sizes below 10^6 points: one
  // more unknown per node, the pressure blocks of the kernel and, with the cell's average volume
  // change (F-bar), every mixed point's dF and B computed twice (once for the average). And the
  // displacement formulation on crossed triangles: four cells and twice the nodes per square.
  for (int cells : sizes_from_environment()) {
    if (cells >= 300) continue;
    const std::string size = "/cells:" + std::to_string(cells);
    for (Formulation f : {Formulation::MixedPerPoint, Formulation::MixedCellAverage,
                          Formulation::MixedFieldPressure, Formulation::MixedIncrementalFitted,
                          Formulation::DisplacementCrossedTriangles}) {
      const std::string tag = std::string("/formulation:") + formulation_name(f);
      timed(benchmark::RegisterBenchmark(("internal_force" + size + "/threads:1" + tag).c_str(),
                                         internal_force, cells, 1, f));
      timed(benchmark::RegisterBenchmark(("factorize_solve" + size + tag).c_str(), factorize_solve,
                                         cells, f));
      timed(benchmark::RegisterBenchmark(("step" + size + tag).c_str(), step, cells, f));
    }
  }
}

// The BLAS libraries mapped into this process: UMFPACK's speed depends on them more than on
// anything in geompm, and which one the system resolves can change between runs.
std::string loaded_blas() {
  std::ifstream maps("/proc/self/maps");
  std::vector<std::string> found;
  for (std::string line; std::getline(maps, line);) {
    const auto slash = line.find('/');
    if (slash == std::string::npos) continue;
    const std::string path = line.substr(slash);
    if (path.find("blas") != std::string::npos &&
        std::find(found.begin(), found.end(), path) == found.end())
      found.push_back(path);
  }
  std::string out;
  for (const auto& path : found) out += (out.empty() ? "" : ", ") + path;
  return out.empty() ? "none" : out;
}

}  // namespace
}  // namespace geompm::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  geompm::bench::register_all();
  benchmark::AddCustomContext("omp_max_threads", std::to_string(omp_get_max_threads()));
  benchmark::AddCustomContext("linear_solver", "umfpack");
  benchmark::AddCustomContext("blas", geompm::bench::loaded_blas());
  const char* wait_policy = std::getenv("OMP_WAIT_POLICY");
  benchmark::AddCustomContext("omp_wait_policy", wait_policy ? wait_policy : "(default)");
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

#!/usr/bin/env bash
# Builds bench_step and bench_material_return, runs them and writes docs/performance.md from their
# JSON output.
#
#   BUILD_DIR=build bench/run_benchmarks.sh
#
# Environment:
#   BUILD_DIR                 CMake build directory (default: build; configured if missing)
#   GEOMPM_BENCH_CELLS        cells per side of the sizes (default 50,160,500: 10^4 to 10^6 points)
#   GEOMPM_BENCH_REPETITIONS  repetitions per benchmark, the doc reports medians (default 5)
#   OMP_WAIT_POLICY           default passive: see below
#   DOC                       where to write the doc (default docs/performance.md)
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BUILD_DIR:-build}"
[[ "$build" = /* ]] || build="$root/$build"
results="$root/bench/results"
doc="${DOC:-$root/docs/performance.md}"

# Threads that wait at a barrier passively (sleep) instead of spinning: each internal-force
# evaluation crosses one barrier per cell colour, and on a machine shared with other work a
# spinning thread that is descheduled costs a whole scheduler slice per barrier, so with the
# default policy the timings measure the scheduler, not geompm. The doc records the policy.
export OMP_WAIT_POLICY="${OMP_WAIT_POLICY:-passive}"
export OMP_PROC_BIND="${OMP_PROC_BIND:-false}"

if [[ ! -f "$build/CMakeCache.txt" ]]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release
fi
build_type="$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$build/CMakeCache.txt")"
if [[ "$build_type" != "Release" ]]; then
  echo "warning: $build is a '$build_type' build; benchmark a Release build" >&2
fi
# The commit as it is built (the tree may change while the benchmarks run).
commit="$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)"
if [[ -n "$(git -C "$root" status --porcelain -- src 2>/dev/null)" ]]; then
  commit="$commit (src/ modified)"
fi
cmake --build "$build" --target bench_step bench_material_return -j"$(nproc)"

mkdir -p "$results"
json="$results/bench_step.json"
start=$(date +%s)
"$build/bench/bench_step" --benchmark_out="$json" --benchmark_out_format=json \
  | tee "$results/bench_step.txt"
end=$(date +%s)
# One stress update of the cone against the rounded surface (performance note 12): its table
# goes into the doc through the notes.
"$build/bench/bench_material_return" --benchmark_repetitions="${GEOMPM_BENCH_REPETITIONS:-5}" \
  --benchmark_report_aggregates_only=true --benchmark_out="$results/bench_material_return.json" \
  --benchmark_out_format=json | tee "$results/bench_material_return.txt"
/usr/bin/python3 "$root/bench/material_return_table.py" "$results/bench_material_return.json" \
  "$root/bench/material_return_timings.md"
load_after="$(cut -d' ' -f1-3 /proc/loadavg)"

/usr/bin/python3 "$root/bench/make_performance_doc.py" "$json" "$doc" \
  --build-dir "$build" --load-after "$load_after" --wall-seconds $((end - start)) \
  --commit "$commit" \
  --notes "$root/bench/performance_notes.md"
echo "wrote $doc"

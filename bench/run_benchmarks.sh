#!/usr/bin/env bash
# Builds bench_step, runs it and writes docs/performance.md from its JSON output.
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
cmake --build "$build" --target bench_step -j"$(nproc)"

mkdir -p "$results"
json="$results/bench_step.json"
start=$(date +%s)
"$build/bench/bench_step" --benchmark_out="$json" --benchmark_out_format=json \
  | tee "$results/bench_step.txt"
end=$(date +%s)
load_after="$(cut -d' ' -f1-3 /proc/loadavg)"

/usr/bin/python3 "$root/bench/make_performance_doc.py" "$json" "$doc" \
  --build-dir "$build" --load-after "$load_after" --wall-seconds $((end - start)) \
  --commit "$commit" \
  --notes "$root/bench/performance_notes.md"
echo "wrote $doc"

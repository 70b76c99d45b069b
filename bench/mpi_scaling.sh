#!/usr/bin/env bash
# Distributed runs against one process (docs/performance.md, note 23; issue 44): the wall time of
# a step of an elastic block under its own weight on 1 and on 2 processes (mpirun), one OpenMP
# thread per process, the same linear solver on both (MUMPS through PETSc by default), median of
# GEOMPM_BENCH_REPETITIONS runs each, with the linear solver's share. Appends a table to
# bench/mpi_timings.md.
#
#   BUILD_DIR=build bench/mpi_scaling.sh
#
# Environment:
#   BUILD_DIR                 the build with bin geompm (default: build)
#   GEOMPM_BENCH_MPI_CELLS    2D cells per side (default 500: 10^6 points)
#   GEOMPM_BENCH_MPI_CELLS_3D 3D cells per side (default 24: 1.1·10^5 points)
#   GEOMPM_BENCH_REPETITIONS  runs per case (default 3)
#   GEOMPM_BENCH_STEPS        steps per run (default 2: the second has points that moved)
#   GEOMPM_BENCH_SOLVER       numerics.linear_solver of both runs (default petsc_mumps)
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BUILD_DIR:-build}"
[[ "$build" = /* ]] || build="$root/$build"
geompm="$build/geompm"
cells="${GEOMPM_BENCH_MPI_CELLS:-500}"
cells3d="${GEOMPM_BENCH_MPI_CELLS_3D:-24}"
repetitions="${GEOMPM_BENCH_REPETITIONS:-3}"
steps="${GEOMPM_BENCH_STEPS:-2}"
solver="${GEOMPM_BENCH_SOLVER:-petsc_mumps}"
out="$root/bench/mpi_timings.md"

source "$root/bench/block_model.sh"

# The run's stepping time (summary.json wall_seconds: from the first step to the end) and the
# linear solver's seconds in it.
run_once() {  # processes file
  local processes=$1 file=$2 dir="$work/out"
  rm -rf "$dir"
  if [[ $processes == 1 ]]; then
    "$geompm" run "$file" -o "$dir" --quiet >/dev/null 2>&1
  else
    mpirun --oversubscribe -np "$processes" "$geompm" run "$file" -o "$dir" --quiet >/dev/null 2>&1
  fi
  /usr/bin/python3 -c "import json; s = json.load(open('$dir/summary.json')); print(s['wall_seconds'], s['linear_solves']['seconds'])"
}

# The run with the median wall time: "wall linear".
median() { /usr/bin/python3 -c "import statistics, sys; runs = sorted((float(a), float(b)) for a, b in zip(sys.argv[1::2], sys.argv[2::2])); print(*runs[len(runs) // 2])" "$@"; }

{
  echo "| model | points | solver | 1 process: step s (linear s) | 2 processes: step s (linear s) | speed-up |"
  echo "|---|---|---|---|---|---|"
} >"$work/table"
load_before="$(cut -d' ' -f1-3 /proc/loadavg)"
for dim in 2 3; do
  n=$cells
  [[ $dim == 3 ]] && n=$cells3d
  file="$work/block${dim}d.yaml"
  model "$dim" "$n" "$file"
  declare -A wall=() linear=()
  for processes in 1 2; do
    times=()
    for ((k = 0; k < repetitions; ++k)); do times+=($(run_once "$processes" "$file")); done
    read -r wall[$processes] linear[$processes] <<<"$(median "${times[@]}")"
    echo "${dim}D ${n} cells/side, $solver, $processes process(es): ${times[*]} -> ${wall[$processes]} s" >&2
  done
  if [[ $dim == 2 ]]; then points=$((4 * n * (n - 1))); else points=$((8 * n * n * (n - 1))); fi
  speedup=$(/usr/bin/python3 -c "print(f'{${wall[1]} / ${wall[2]}:.2f}')")
  printf '| %dD block, %d cells per side, %d steps | %d | %s | %.2f (%.2f) | %.2f (%.2f) | %s |\n' \
    "$dim" "$n" "$steps" "$points" "$solver" "${wall[1]}" "${linear[1]}" "${wall[2]}" "${linear[2]}" \
    "$speedup" >>"$work/table"
done
{
  echo
  echo "Written by bench/mpi_scaling.sh on $(date -u '+%Y-%m-%d %H:%M UTC'), geompm $(git -C "$root" rev-parse --short HEAD), load average at start $load_before, at end $(cut -d' ' -f1-3 /proc/loadavg); medians of $repetitions runs."
  echo
  cat "$work/table"
} >>"$out"
cat "$out"

#!/usr/bin/env bash
# The peak memory of each process of a distributed run against one process (docs/performance.md,
# note 23; issue 44): the 2D block of bench/mpi_scaling.sh on 1 and on 2 processes (mpirun), one
# OpenMP thread per process, each process's peak resident set over the whole run (GNU time's
# maximum resident set size: the model build, the steps, the output), median of
# GEOMPM_BENCH_REPETITIONS runs each. With GEOMPM_BENCH_BEFORE, the same for another geompm
# executable (an earlier commit's) beside it. Appends a table to bench/mpi_memory.md.
#
#   BUILD_DIR=build GEOMPM_BENCH_BEFORE=/tmp/geompm_a59de02 bench/mpi_memory.sh
#
# Environment:
#   BUILD_DIR                 the build with bin geompm (default: build)
#   GEOMPM_BENCH_BEFORE       another geompm executable to measure alike (default: none)
#   GEOMPM_BENCH_MPI_CELLS    2D cells per side (default 500: 10^6 points)
#   GEOMPM_BENCH_REPETITIONS  runs per case (default 3)
#   GEOMPM_BENCH_STEPS        steps per run (default 2)
#   GEOMPM_BENCH_SOLVER       numerics.linear_solver (default petsc_mumps)
#   GEOMPM_BENCH_CHECKPOINT_EVERY  a checkpoint every N steps (--checkpoint-every; default 0: none,
#                             as the block model's output says)
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BUILD_DIR:-build}"
[[ "$build" = /* ]] || build="$root/$build"
cells="${GEOMPM_BENCH_MPI_CELLS:-500}"
repetitions="${GEOMPM_BENCH_REPETITIONS:-3}"
steps="${GEOMPM_BENCH_STEPS:-2}"
solver="${GEOMPM_BENCH_SOLVER:-petsc_mumps}"
checkpoint_every="${GEOMPM_BENCH_CHECKPOINT_EVERY:-0}"
checkpoints=()
((checkpoint_every > 0)) && checkpoints=(--checkpoint-every "$checkpoint_every")
out="$root/bench/mpi_memory.md"

source "$root/bench/block_model.sh"

# Each process's peak resident set in MiB, in rank order.
peaks_once() {  # geompm processes file
  local geompm=$1 processes=$2 file=$3 dir="$work/out"
  rm -rf "$dir" "$work"/rss.*
  mpirun --oversubscribe -np "$processes" bash -c \
    '/usr/bin/time -f %M -o "$0.${OMPI_COMM_WORLD_RANK:-0}" "$@"' "$work/rss" \
    "$geompm" run "$file" -o "$dir" --quiet "${checkpoints[@]}" >/dev/null 2>&1
  for ((r = 0; r < processes; ++r)); do echo $(($(tail -1 "$work/rss.$r") / 1024)); done
}

# Per rank, the median over the runs: "peak0 peak1 ...".
medians() {  # processes runs...
  /usr/bin/python3 -c "
import statistics, sys
n = int(sys.argv[1]); runs = [sys.argv[2 + k * n:2 + (k + 1) * n] for k in range((len(sys.argv) - 2) // n)]
print(*(int(statistics.median(int(run[r]) for run in runs)) for r in range(n)))" "$@"
}

file="$work/block2d.yaml"
model 2 "$cells" "$file"
executables=("$build/geompm")
[[ -n "${GEOMPM_BENCH_BEFORE:-}" ]] && executables=("$GEOMPM_BENCH_BEFORE" "${executables[@]}")
{
  echo "| geompm | 1 process: peak MiB | 2 processes: peak MiB of rank 0 / rank 1 |"
  echo "|---|---|---|"
} >"$work/table"
load_before="$(cut -d' ' -f1-3 /proc/loadavg)"
for geompm in "${executables[@]}"; do
  declare -A peak=()
  for processes in 1 2; do
    runs=()
    for ((k = 0; k < repetitions; ++k)); do runs+=($(peaks_once "$geompm" "$processes" "$file")); done
    peak[$processes]="$(medians "$processes" "${runs[@]}")"
    echo "$geompm, $processes process(es): ${runs[*]} -> ${peak[$processes]} MiB" >&2
  done
  printf '| %s | %s | %s |\n' "$geompm" "${peak[1]}" "${peak[2]// / \/ }" >>"$work/table"
done
{
  echo
  echo "Written by bench/mpi_memory.sh on $(date -u '+%Y-%m-%d %H:%M UTC'), geompm $(git -C "$root" rev-parse --short HEAD), 2D block of $cells cells per side ($((4 * cells * (cells - 1))) points), $steps steps, $solver, $( ((checkpoint_every > 0)) && echo "a checkpoint every $checkpoint_every steps" || echo "no checkpoint"), load average at start $load_before, at end $(cut -d' ' -f1-3 /proc/loadavg); medians of $repetitions runs."
  echo
  cat "$work/table"
} >>"$out"
cat "$out"

#!/usr/bin/env bash
# What the FEM region costs (docs/performance.md, note 18): the coupled strip footing of
# examples/coupling/ (MPM near the footing, FEM beyond) against its all-MPM twin, whole runs on
# `threads` threads without VTK output, each repeated; the medians of the wall time and of the linear
# solves' time (summary.json), and the time outside the solves.
# Usage: bash bench/coupling_cost.sh [build/geompm] [repetitions, default 5] [threads, default 1]
set -euo pipefail
cd "$(dirname "$0")/.."
geompm="${1:-build/geompm}"
repetitions="${2:-5}"
threads="${3:-1}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
for case in strip_footing_all_mpm strip_footing_coupled; do
  sed -e 's/vtk: {every: 10}/vtk: {every: 0}/' "examples/coupling/$case.yaml" > "$work/$case.yaml"
  : > "$work/$case.wall"
  : > "$work/$case.solve"
  for ((k = 0; k < repetitions; ++k)); do
    OMP_NUM_THREADS=$threads OMP_WAIT_POLICY=passive "$geompm" run -q -t "$threads" "$work/$case.yaml" \
      -o "$work/$case" > /dev/null 2>&1
    /usr/bin/python3 -c "import json, sys; s = json.load(open(sys.argv[1])); \
print(s['wall_seconds'], file=open(sys.argv[2], 'a')); \
print(s['linear_solves']['seconds'], file=open(sys.argv[3], 'a'))" \
      "$work/$case/summary.json" "$work/$case.wall" "$work/$case.solve"
  done
  wall=$(median < "$work/$case.wall")
  solve=$(median < "$work/$case.solve")
  echo "$case: wall $wall s, linear solves $solve s, the rest $(echo "$wall - $solve" | bc -l | cut -c1-6) s (medians of $repetitions)"
done

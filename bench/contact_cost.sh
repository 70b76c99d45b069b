#!/usr/bin/env bash
# What level-set contact costs against the penalty rigid footing (docs/performance.md, note 16):
# the smooth rigid strip of examples/strip_footing/ and the same footing as a structure in
# contact (examples/structures/), both with the structure example's numerics and Newton settings,
# pushed three steps (0.0075 B) on one thread under callgrind. Instruction counts do not depend
# on what else the machine runs; the report is instructions per Newton iteration.
# Usage: bash bench/contact_cost.sh [build/geompm]
set -euo pipefail
cd "$(dirname "$0")/.."
geompm="${1:-build/geompm}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
numerics='numerics: {mixed_pressure_start: fitted, mixed_pressure_equation: incremental, empty_cell_stiffness: 1.0e-4, buffer_layers: 1, mixed_volume: per_point}'
sed -e 's/duration: 1.0/duration: 0.075/' -e 's/vtk: {every: 10}/vtk: {every: 0}/' \
  -e 's/line_search: 6, energy_line_search: 0.1,/line_search: 6,/' -e "s/^numerics:.*/$numerics/" \
  examples/strip_footing/strip_footing_smooth.yaml > "$work/penalty.yaml"
sed -e 's/duration: 1.0/duration: 0.075/' -e 's/vtk: {every: 10}/vtk: {every: 0}/' \
  examples/structures/strip_footing_smooth.yaml > "$work/contact.yaml"
for case in penalty contact; do
  OMP_NUM_THREADS=1 valgrind --tool=callgrind --callgrind-out-file="$work/$case.out" \
    "$geompm" run -q -t 1 "$work/$case.yaml" -o "$work/$case" > "$work/$case.log" 2>&1
  instructions=$(grep -o 'Collected : [0-9]*' "$work/$case.log" | awk '{print $3}')
  iterations=$(awk -F, 'NR > 1 {s += $NF} END {print s}' "$work/$case/history.csv")
  echo "$case: $instructions instructions, $iterations Newton iterations," \
    "$((instructions / iterations)) per iteration"
done

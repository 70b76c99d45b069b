#!/usr/bin/env bash
# Fresh machine -> installed dependencies, built geompm, and the main example run with its plot.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
echo "Building the geompm executable only (no tests or benchmarks): the first build takes about" \
  "4 minutes on two cores, a rebuild seconds."
bash scripts/build.sh geompm
example=examples/strip_footing/strip_footing.yaml
echo "Running the main example (about 10 seconds)."
./build/geompm check "$example"
./build/geompm run "$example" --output results/strip_footing
echo "ParaView: results/strip_footing/points.pvd (plastic zone: colour by 'plastic' or" \
  "'equivalent_plastic_strain'; grid.pvd: nodal pressure);" \
  "plot: results/strip_footing/load_settlement.png"

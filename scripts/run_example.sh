#!/usr/bin/env bash
# Fresh machine -> installed dependencies, built geompm, and the main example run with its plot.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
example=examples/strip_footing/strip_footing.yaml
./build/geompm check "$example"
./build/geompm run "$example" --output results/strip_footing
echo "ParaView: results/strip_footing/points.pvd (grid.pvd: nodal pressure);" \
  "plot: results/strip_footing/load_settlement.png"

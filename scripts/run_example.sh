#!/usr/bin/env bash
# Fresh machine -> installed dependencies, built geompm, and the main example run with its plot.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
example=examples/column/column.yaml
./build/geompm check "$example"
./build/geompm run "$example" --output results/column
echo "ParaView: results/column/points.pvd; plot: results/column/settlement.png"

#!/usr/bin/env bash
# Fresh machine -> installed dependencies, built geompm, and the whole test suite run
# (unit, verification and example tiers; ctest -L unit runs the fast tier alone).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
cd build
ctest --output-on-failure -j "$(nproc)" --timeout 1200 "$@"

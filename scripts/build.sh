#!/usr/bin/env bash
# Configures and builds geompm (Release, Ninja, ccache) into build/.
#   bash scripts/build.sh           everything: geompm, the tests and the benchmarks
#   bash scripts/build.sh geompm    only the geompm executable (and the libraries it needs)
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release > build-configure.log 2>&1 || {
  cat build-configure.log; exit 1; }
rm -f build-configure.log
if [ $# -gt 0 ]; then
  cmake --build build -j "$(nproc)" --target "$@"
else
  cmake --build build -j "$(nproc)"
fi

#!/usr/bin/env bash
# The code checks CI runs after the test suite (.ci/run):
#  1. the libraries and the unit tier built with clang, AddressSanitizer and UndefinedBehavior-
#     Sanitizer (build-sanitize/), and the unit tier run under them: any report fails it;
#  2. the fuzz targets of fuzz/ (the model reader with the model's validation and build, and the
#     Gmsh mesh reader), each run for FUZZ_SECONDS (default 60) from the examples' files; a crash,
#     a sanitizer report, a hang or an exception other than an input error fails it, and the
#     input that did it is left in build-sanitize/fuzz/ (crash-*, timeout-*, leak-*).
# About 25 minutes on 2 cores from nothing built (docs/performance.md).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --checks
seconds="${FUZZ_SECONDS:-60}"
# -O1 with line tables only: the checks want speed of building more than of running.
CC=clang CXX=clang++ cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DGEOMPM_SANITIZE=ON -DGEOMPM_FUZZ=ON > build-sanitize.log 2>&1 || {
  cat build-sanitize.log; exit 1; }
rm -f build-sanitize.log
mapfile -t unit_targets < <(ninja -C build-sanitize -t targets all |
                            sed -n 's/^\(test_unit_[a-z_]*\): phony$/\1/p')
cmake --build build-sanitize -j "$(nproc)" --target geompm "${unit_targets[@]}" \
  fuzz_model_reader fuzz_mesh_reader

# No leak check: OpenMPI's plugins (PETSc initialises MPI) leak from modules they have unloaded
# by the time LeakSanitizer looks, which no suppression can name (first run, 2026-11-28). ASan's
# other checks (out of bounds, use after free) and UBSan stay on.
export ASAN_OPTIONS="detect_leaks=0:detect_odr_violation=0:abort_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export OMP_WAIT_POLICY=passive
(cd build-sanitize && ctest -L unit --output-on-failure -j "$(nproc)" --timeout 1800)

mkdir -p build-sanitize/fuzz
for target in fuzz_model_reader fuzz_mesh_reader; do
  corpus="build-sanitize/fuzz/${target#fuzz_}_corpus"
  mkdir -p "$corpus"
  case "$target" in
    fuzz_model_reader) pattern="*.yaml" ;;
    fuzz_mesh_reader) pattern="*.msh" ;;
  esac
  # Named by folder and file: two examples' files may share a name.
  for file in examples/*/$pattern; do
    cp "$file" "$corpus/$(basename "$(dirname "$file")")__$(basename "$file")"
  done
  echo "fuzzing ${target#fuzz_} for ${seconds} s"
  (cd build-sanitize/fuzz &&
   ../fuzz/"$target" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=4096 \
     -max_len=16384 -print_final_stats=1 "${corpus#build-sanitize/fuzz/}" 2>&1 | tail -25)
done
echo "sanitizer and fuzzing checks: clean"

#!/usr/bin/env bash
# Installs everything geompm needs on Debian 12 (idempotent, non-interactive).
#   bash scripts/setup.sh            build, tests, examples and the validation report's runner
#   bash scripts/setup.sh --report   and matplotlib for scripts/plot_regions.py
#   bash scripts/setup.sh --checks   and clang with its sanitizer and fuzzer runtimes and OpenMP
#                                    (scripts/check_sanitized.sh)
set -euo pipefail
packages=(
  build-essential cmake ninja-build ccache pkg-config
  libeigen3-dev          # small dense tensors and the sparse matrix type
  libsuitesparse-dev     # UMFPACK sparse direct solver
  libpetsc-real-dev      # Krylov solvers with GAMG, hypre BoomerAMG and MUMPS for large models (issue 44);
                         # brings OpenMPI
  openmpi-bin            # mpirun: distributed runs and their tests (ctest -L mpi)
  libptscotch-dev        # PT-Scotch, against which bench/bench_partition measures the mesh's cut
  libopenblas0-openmp    # optimised BLAS under UMFPACK (x2.5-7 on the factorisation, docs/performance.md);
                         # the OpenMP build shares our threads instead of spinning its own
  libyaml-cpp-dev        # model files (YAML, with line numbers for errors)
  libmuparser-dev        # expressions of x, y, z, t in model files
  libcli11-dev           # command line
  nlohmann-json3-dev     # summary.json (header-only JSON writer and reader)
  libfmt-dev             # formatting
  libgmsh-dev            # Gmsh .msh import and unstructured mesh generation
  libgd-dev              # PNG plots of histories
  libgtest-dev libgmock-dev libbenchmark-dev
  python3-meshio         # independent VTU reader used by the output test
  python3-yaml           # the validation cases' model overrides (scripts/validation/run_cases.py)
)
case "${1:-}" in
  --report) packages+=(python3-matplotlib) ;;  # scripts/plot_regions.py
  --checks) packages+=(clang libclang-rt-dev libomp-dev) ;;
  "") ;;
  *) echo "setup.sh: unknown option '$1' (expected --report, --checks or nothing)" >&2; exit 1 ;;
esac
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

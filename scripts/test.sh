#!/usr/bin/env bash
# Installs, builds and runs argine's tests.
#   scripts/test.sh               the test suite (everything but the slow labels below)
#   scripts/test.sh verification  the verification cases (V1, V2, ...) with error norms and plots
#   scripts/test.sh benchmark     the throughput benchmarks
#   scripts/test.sh paraview      opens the results in ParaView's pvpython (installs ParaView)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
label=${1:-suite}
"$root/scripts/build.sh"
build_dir=${ARGINE_BUILD_DIR:-$root/build}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$build_dir"
case "$label" in
  suite) ctest --output-on-failure -j "$(nproc)" -LE 'verification|benchmark|paraview' ;;
  benchmark) ctest --verbose -L '^benchmark$' ;;  # verbose: the throughput is the result
  verification | paraview) ctest --output-on-failure -L "^$label\$" ;;
  *) echo "usage: scripts/test.sh [verification|benchmark|paraview]" >&2; exit 2 ;;
esac

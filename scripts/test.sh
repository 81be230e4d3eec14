#!/usr/bin/env bash
# Installs, builds and runs argine's tests.
#   scripts/test.sh               the test suite (everything but the slow labels below)
#   scripts/test.sh verification  the verification cases (V1, V2, ...) with error norms and plots
#   scripts/test.sh benchmark     the throughput benchmarks
#   scripts/test.sh paraview      opens the results in ParaView's pvpython (installs ParaView)
#   scripts/test.sh sanitize      the unit suite built with ASan + UBSan (preset asan-ubsan,
#                                 build-asan/; a second full build, debug info, -O1)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
label=${1:-suite}
if [[ $label == sanitize ]]; then
  "$root/scripts/setup.sh"
  build_dir=$root/build-asan
  launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  (cd "$root" && cmake --preset asan-ubsan "${launcher[@]}" >/dev/null)
  cmake --build "$build_dir" -j "${ARGINE_JOBS:-$(nproc)}"
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  # Any report stops the test process (-fno-sanitize-recover, halt_on_error) and fails it.
  # Leaks of Open MPI's and Trilinos' globals are suppressed (the file says which). The
  # suppressions match frames of the allocation stack; the fast (frame-pointer) unwinder stops
  # at the first frame inside these libraries (built without frame pointers), so the slow
  # unwinder is needed for the stack to reach the library a suppression names.
  export ASAN_OPTIONS=detect_leaks=1:halt_on_error=1:abort_on_error=0:fast_unwind_on_malloc=0
  export LSAN_OPTIONS=suppressions=$root/scripts/sanitizer-suppressions/lsan.supp:print_suppressions=0
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  cd "$build_dir"
  exec ctest --output-on-failure -j "$(nproc)" -LE 'verification|benchmark|paraview|fuzz'
fi
"$root/scripts/build.sh"
build_dir=${ARGINE_BUILD_DIR:-$root/build}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$build_dir"
case "$label" in
  suite) ctest --output-on-failure -j "$(nproc)" -LE 'verification|benchmark|paraview' ;;
  benchmark) ctest --verbose -L '^benchmark$' ;;  # verbose: the throughput is the result
  verification | paraview) ctest --output-on-failure -L "^$label\$" ;;
  *) echo "usage: scripts/test.sh [verification|benchmark|paraview|sanitize]" >&2; exit 2 ;;
esac

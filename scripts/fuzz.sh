#!/usr/bin/env bash
# Builds argine's libFuzzer targets (Clang, ASan + UBSan, in build-fuzz/) and runs them.
#   scripts/fuzz.sh [SECONDS [TARGET...]]   run each target SECONDS (default 120) on its corpus
#   scripts/fuzz.sh build                  only build
# TARGET: deck (fuzz_deck_reader), exodus (fuzz_exodus_reader) or gmsh (fuzz_gmsh_reader);
# default all three.
# A crash, hang (an input taking over 10 s), out-of-memory, leak, uncaught exception or
# sanitizer report stops the fuzzer with exit code != 0 and leaves the input in
# build-fuzz/artifacts/<target>/ (reproduce: build-fuzz/fuzz/fuzz_<target>_reader FILE).
# New inputs found are kept in build-fuzz/corpus/<target>/ (seeds: fuzz/corpus/<target>/).
# ARGINE_FUZZ_RUNS=N makes a run reproducible (the test suite's fuzz tests): N inputs from
# the fixed random seed ARGINE_FUZZ_SEED (default 1), starting from the committed seeds
# only (a fresh corpus), with SECONDS as a time limit on top.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${ARGINE_FUZZ_BUILD_DIR:-$root/build-fuzz}
jobs=${ARGINE_JOBS:-$(nproc)}

build() {
  local launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  cmake -S "$root" -B "$build_dir" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" -DARGINE_FUZZ=ON -DARGINE_BUILD_TESTS=OFF \
    -DARGINE_WERROR=ON "${launcher[@]}" >/dev/null
  cmake --build "$build_dir" -j "$jobs" --target fuzz_deck_reader fuzz_exodus_reader fuzz_gmsh_reader
}

run() {  # run TARGET SECONDS
  local target=$1 seconds=$2
  local binary="$build_dir/fuzz/fuzz_${target}_reader"
  local corpus="$build_dir/corpus/$target" artifacts="$build_dir/artifacts/$target/"
  local work="$build_dir/work/$target"
  local bounds=(-max_total_time="$seconds")
  if [[ -n ${ARGINE_FUZZ_RUNS:-} ]]; then
    corpus="$build_dir/corpus-reproducible/$target"
    rm -rf "$corpus"
    bounds+=(-runs="$ARGINE_FUZZ_RUNS" -seed="${ARGINE_FUZZ_SEED:-1}")
  fi
  mkdir -p "$corpus" "$artifacts" "$work"
  echo "fuzz: $target, ${bounds[*]} (seeds fuzz/corpus/$target, corpus $corpus)"
  # Open MPI and Trilinos are not instrumented; LeakSanitizer suppressions only for them.
  ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1} \
  LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$root/scripts/sanitizer-suppressions/lsan.supp:print_suppressions=0} \
  UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1} \
  ARGINE_FUZZ_WORKDIR="$work" \
    "$binary" "${bounds[@]}" -timeout=10 -rss_limit_mb=2048 -max_len=16384 \
    -print_final_stats=1 -artifact_prefix="$artifacts" "$corpus" "$root/fuzz/corpus/$target"
}

if [[ ${1:-} == build ]]; then
  build
  exit 0
fi
seconds=${1:-120}
shift || true
targets=("$@")
((${#targets[@]} == 0)) && targets=(deck exodus gmsh)
[[ -x "$build_dir/fuzz/fuzz_deck_reader" && ${ARGINE_FUZZ_SKIP_BUILD:-0} == 1 ]] || build
for target in "${targets[@]}"; do
  case "$target" in
    deck | exodus | gmsh) run "$target" "$seconds" ;;
    *) echo "usage: scripts/fuzz.sh [build | SECONDS [deck|exodus|gmsh]...]" >&2; exit 2 ;;
  esac
done

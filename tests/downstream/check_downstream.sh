#!/usr/bin/env bash
# Installs the built argine into a scratch prefix, then configures, builds and runs a
# downstream project that finds it with find_package(argine).
set -euo pipefail
source_dir=$1
build_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build_dir" --prefix "$work/prefix" >/dev/null
# The consumer is compiled and linked with the flags argine was built with: the static
# libraries of a sanitizer build (preset asan-ubsan) need the sanitizer runtimes at link time.
cached() { sed -n "s/^$1:[A-Z]*=//p" "$build_dir/CMakeCache.txt"; }
cmake -S "$source_dir/tests/downstream/consumer" -B "$work/build" \
  -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS="$(cached CMAKE_CXX_FLAGS)" \
  -DCMAKE_EXE_LINKER_FLAGS="$(cached CMAKE_EXE_LINKER_FLAGS)" >/dev/null
cmake --build "$work/build" >/dev/null
"$work/build/consumer"

#!/usr/bin/env bash
# Configures and builds argine (Release) into build/ after making sure the dependencies
# are installed. Extra arguments go to CMake's configure step.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh"
build_dir=${ARGINE_BUILD_DIR:-$root/build}
jobs=${ARGINE_JOBS:-$(nproc)}
cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$build_dir" -j "$jobs"

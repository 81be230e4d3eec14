#!/usr/bin/env bash
# Installs, builds and runs a scene (default: the levee scene named in inputs/DEFAULT).
#   scripts/run.sh [deck.yaml] [argine run options...]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
deck=${1:-$root/inputs/$(cat "$root/inputs/DEFAULT")}
shift || true
"$root/scripts/build.sh"
build_dir=${ARGINE_BUILD_DIR:-$root/build}
scene=$(basename "$deck" .yaml)
"$build_dir/argine" run "$deck" --output "$root/results/$scene" "$@"
echo "Results: $root/results/$scene (open the .e files in ParaView)"

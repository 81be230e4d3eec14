#!/usr/bin/env bash
# Installs, builds and runs a scene (default: the levee scene named in inputs/DEFAULT).
#   scripts/run.sh [deck.yaml] [argine run options...]
# ARGINE_RANKS=N runs it on N MPI ranks (mpiexec; doc/parallel.md).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
deck=${1:-$root/inputs/$(cat "$root/inputs/DEFAULT")}
shift || true
"$root/scripts/build.sh"
build_dir=${ARGINE_BUILD_DIR:-$root/build}
scene=$(basename "$deck" .yaml)
ranks=${ARGINE_RANKS:-1}
launcher=()
if ((ranks > 1)); then
  launcher=(mpiexec -n "$ranks" --oversubscribe)
  if ((EUID == 0)); then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
fi
"${launcher[@]}" "$build_dir/argine" run "$deck" --output "$root/results/$scene" "$@"
echo "Results: $root/results/$scene (open the .e files in ParaView)"

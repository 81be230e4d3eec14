#!/usr/bin/env bash
# V5 critical time-step study (doc/stability.md): builds argine_stability, runs the full
# sweep (sets saturation, permeability, mesh, realistic) as two shards in parallel, merges
# the CSV into verification/stability/results/ and draws doc/figures/stability_*.png.
#   scripts/stability.sh            full sweep, 179 cases (~13 min wall on 2 busy cores)
#   scripts/stability.sh quick      the 7-case subset of the unit test (~10 s CPU)
# ARGINE_BUILD_DIR (default build/) and ARGINE_STABILITY_SHARDS (default 2) are honoured.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${ARGINE_BUILD_DIR:-$root/build}
shards=${ARGINE_STABILITY_SHARDS:-2}
sets=${1:-all realistic}
results="$root/verification/stability/results"
figures="$root/doc/figures"
if [ "$sets" = quick ]; then  # a look at the subset: keep the committed results untouched
  results="$build_dir/verification/stability/quick"
  figures="$results"
fi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  "$root/scripts/build.sh"  # a fresh machine: install the packages, configure, build
fi
cmake --build "$build_dir" -j "$shards" --target argine_stability
driver="$build_dir/verification/stability/argine_stability"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
start=$(date +%s)
for set in $sets; do
  pids=()
  for ((i = 0; i < shards; i++)); do
    "$driver" --set "$set" --shard "$i" --shards "$shards" --output "$work" \
      >"$work/log_${set}_$i.txt" 2>&1 &
    pids+=($!)
  done
  for pid in "${pids[@]}"; do wait "$pid"; done
  cat "$work"/log_"${set}"_*.txt
done
echo "sweep: $(($(date +%s) - start)) s wall"
mkdir -p "$results"
/usr/bin/python3 "$root/verification/stability/plot_stability.py" --merge "$work" \
  --results "$results" --figures "$figures"

#!/usr/bin/env bash
# Accuracy against cost of the explicit and implicit paths on V3 (infiltration column) and V4
# (levee seepage), doc/verification.md "Accuracy against cost: explicit and implicit paths".
# Runs the explicit drivers on several meshes and mass scalings, the implicit drivers' studies
# (meshes, steps, theta), compares all with the refined implicit references, and writes
#   verification/accuracy_cost/{v3,v4}_cost.csv   (every run: path, settings, CPU, errors)
#   doc/figures/{infiltration_column,levee_seepage}_accuracy_cost.png
#   scripts/accuracy_cost.sh         both cases (about 160 CPU-min, 85 min wall: 2 runs at a time)
#   scripts/accuracy_cost.sh v3|v4   one case
# Cost is the processor time of each run (its wall time on an idle core): the runs share
# the machine two at a time. ARGINE_BUILD_DIR (default build/) is honoured.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${ARGINE_BUILD_DIR:-$root/build}
cases=${1:-v3 v4}
results="$root/verification/accuracy_cost"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  "$root/scripts/build.sh"  # a fresh machine: install the packages, configure, build
fi
cmake --build "$build_dir" -j 2 --target infiltration_column_verification \
  infiltration_column_explicit_verification levee_seepage_verification \
  levee_seepage_implicit_verification
work=${ARGINE_STUDY_WORK:-$(mktemp -d)}
mkdir -p "$work" "$results"
echo "accuracy_cost: run files in $work"
start=$(date +%s)

# Runs the commands of file $1 (one per line) two at a time; each logs to its own file.
run_pairs() {
  xargs -P 2 -I{} bash -c '{}' <"$1"
}

if [[ " $cases " == *" v3 "* ]]; then
  v3=$build_dir/verification/infiltration_column
  : >"$work/v3_jobs"
  echo "$v3/infiltration_column_verification --output $work >$work/v3_implicit.log 2>&1" \
    >>"$work/v3_jobs"
  for run in 0.01:10000 0.1:10000 0.05:10000 0.025:10000 0.05:1000 0.1:1000; do
    h=${run%%:*} ms=${run##*:}
    tag=v3_explicit_h${h}_ms${ms}
    echo "$v3/infiltration_column_explicit_verification --output $work --tag $tag" \
      "--element-size $h --mass-scaling $ms >$work/$tag.log 2>&1 || true" >>"$work/v3_jobs"
  done
  run_pairs "$work/v3_jobs"
  grep -h "V3x \] explicit vs\|element means at" "$work"/v3_explicit_*.log || true
  /usr/bin/python3 "$root/verification/accuracy_cost/accuracy_cost.py" merge-v3 --work "$work" \
    --output "$results/v3_cost.csv"
fi

if [[ " $cases " == *" v4 "* ]]; then
  v4=$build_dir/verification/levee_seepage
  : >"$work/v4_jobs"
  # Longest first (CPU: h 0.025 with mass scaling 1e3 ~80 min, 1e4 ~25 min; h 0.05 with
  # 1e2 ~30 min), the implicit study with its refined reference (~4 min) among them.
  implicit="$v4/levee_seepage_implicit_verification --study --output $work --tag v4_implicit"
  prefixes=()
  # The explicit runs use the V4 deck (with its liquid head stabilisation); "u" runs the
  # thesis' scheme without it (levee_seepage_unstabilised.yaml) for comparison.
  unstabilised="--deck $root/verification/levee_seepage/levee_seepage_unstabilised.yaml"
  for run in 0.025:1000 implicit 0.025:10000 0.05:100 0.05:1000 0.05:10000 u0.05:10000 \
    0.1:1000 0.1:10000; do
    if [ "$run" = implicit ]; then
      echo "$implicit >$work/v4_implicit.log 2>&1 || true" >>"$work/v4_jobs"
      continue
    fi
    deck="" kind=explicit
    if [ "${run:0:1}" = u ]; then
      run=${run:1} deck=$unstabilised kind=unstabilised
    fi
    h=${run%%:*} ms=${run##*:}
    tag=v4_${kind}_h${h}_ms${ms}
    prefixes+=("$work/$tag")
    echo "$v4/levee_seepage_verification --output $work --tag $tag --element-size $h" \
      "--mass-scaling $ms $deck >$work/$tag.log 2>&1 || true" >>"$work/v4_jobs"
  done
  run_pairs "$work/v4_jobs"
  # Compare every explicit run with the reference the implicit study computed.
  list=$(IFS=,; echo "${prefixes[*]}")
  "$v4/levee_seepage_implicit_verification" --quick --output "$work" --tag v4_compare \
    --reference-profiles "$work/v4_implicit_profiles.csv" --explicit-runs "$list" \
    >"$work/v4_compare.log" 2>&1 || true
  grep -h "V4i \]" "$work/v4_implicit.log" "$work/v4_compare.log" || true
  /usr/bin/python3 "$root/verification/accuracy_cost/accuracy_cost.py" merge-v4 --work "$work" \
    --output "$results/v4_cost.csv"
fi

echo "accuracy_cost: $(($(date +%s) - start)) s wall"
/usr/bin/python3 "$root/verification/accuracy_cost/accuracy_cost.py" plot --results "$results" \
  --figures "$root/doc/figures"

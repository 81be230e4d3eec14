#!/usr/bin/env bash
# Mesh convergence of a levee scene (issue P11 item 3): runs the deck at several element
# sizes, nothing else changed, and tabulates the run-out quantities at the same times with
# their changes and observed order (scripts/levee_convergence.py), and charts them against
# wall time.
#   scripts/convergence.sh [deck.yaml] [element sizes (m)...]
#   default: inputs/levee_drawdown/levee_drawdown.yaml at 0.4, 0.2 and 0.1 m
# CONVERGENCE_TIMES (s after the event started; default "2 3 6 20"), CONVERGENCE_START (the
# simulation time the event starts at; default 1), CONVERGENCE_LAST_DURATION (s: the last
# stage's Duration in every copy, e.g. 19 for the first 20 s of levee_rainfall's 100 s;
# default: the deck's), ARGINE_RANKS (MPI ranks per run), CONVERGENCE_CHECKPOINT_MIN (min of
# wall between checkpoints in every copy, for runs of hours: a run stopped part-way continues
# from its folder's checkpoint when the script is run again with the same settings; the copy
# is written anew with the same text, which the checkpoint's deck hash checks).
# Results in results/convergence/<scene>_h<size>/, the chart in
# results/convergence/<scene>_convergence.png. A run whose results exist is not repeated
# (delete its folder to rerun it).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
deck=${1:-$root/inputs/levee_drawdown/levee_drawdown.yaml}
shift || true
sizes=("$@")
((${#sizes[@]})) || sizes=(0.4 0.2 0.1)
"$root/scripts/build.sh"
build_dir=${ARGINE_BUILD_DIR:-$root/build}
scene=$(basename "$deck" .yaml)
out=$root/results/convergence
mkdir -p "$out"
ranks=${ARGINE_RANKS:-1}
launcher=()
if ((ranks > 1)); then
  launcher=(mpiexec -n "$ranks" --oversubscribe)
  if ((EUID == 0)); then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
fi
grep -q "Element Size (m):" "$deck" || { echo "$deck: no 'Element Size (m):' to change" >&2; exit 2; }
runs=()
for h in "${sizes[@]}"; do
  name=${scene}_h$h
  dir=$out/$name
  runs+=("$h:$dir:$name")
  if [[ -f $dir/$name.log ]] && grep -q "simulated in" "$dir/$name.log"; then
    echo "h = $h m: results exist in $dir"
    continue
  fi
  mkdir -p "$dir"
  # the deck beside the original (relative file keys keep working), removed afterwards
  copy=$(dirname "$deck")/.convergence_$name.yaml
  sed -e "s/Element Size (m): [0-9.eE+-]*/Element Size (m): $h/" \
    -e "s/Name: [A-Za-z0-9_]*}/Name: $name}/" "$deck" >"$copy"
  restart=()
  if [[ -n ${CONVERGENCE_CHECKPOINT_MIN:-} ]]; then
    sed -i "s/Name: $name}/Name: $name, Checkpoint: {Wall Interval (min): $CONVERGENCE_CHECKPOINT_MIN}}/" "$copy"
    grep -q "Checkpoint: {Wall Interval" "$copy" || { echo "$copy: no 'Name: $name}' to add a checkpoint to" >&2; exit 2; }
    if [[ -f $dir/$name.checkpoint ]]; then
      restart=(--restart "$dir/$name.checkpoint")
      echo "h = $h m: continuing from $dir/$name.checkpoint"
    fi
  fi
  if [[ -n ${CONVERGENCE_LAST_DURATION:-} ]]; then  # the last stage's Duration (s)
    last=$(grep -n "Duration (s):" "$copy" | tail -1 | cut -d: -f1)
    sed -i "${last}s/Duration (s): [0-9.eE+-]*/Duration (s): $CONVERGENCE_LAST_DURATION/" "$copy"
  fi
  echo "h = $h m: running $deck -> $dir"
  status=0
  ((${#restart[@]})) || : >"$dir/$name.log"  # a fresh run starts its log, a continued one adds
  "${launcher[@]}" "$build_dir/argine" run "$copy" --output "$dir" "${restart[@]}" >>"$dir/$name.log" 2>&1 || status=$?
  rm -f "$copy"
  if ((status != 0)); then
    echo "h = $h m: argine failed ($status), see $dir/$name.log" >&2
    mv "$dir/$name.log" "$dir/$name.failed.log"
  fi
done
# shellcheck disable=SC2086
/usr/bin/python3 "$root/scripts/levee_convergence.py" "${runs[@]}" \
  --times ${CONVERGENCE_TIMES:-2 3 6 20} --start "${CONVERGENCE_START:-1}" \
  --figure "$out/${scene}_convergence.png"

#!/usr/bin/env bash
# A run on RANKS MPI ranks, restarted from its last checkpoint on as many ranks, ends with the
# files of the run never stopped, bit for bit; restarted on another number of ranks it warns
# and ends within TOLERANCE of them (the rank-border sums in another order; doc/checkpoints.md):
#   restart_ranks_case.sh ARGINE MPIEXEC COMPARE_RESULTS DECK RANKS TOLERANCE
# The deck writes checkpoints and has an explicit stage after an implicit one with a head
# table (counted from the stage start), so the restart lands inside that stage.
set -euo pipefail
argine=$1 mpiexec=$2 compare=$3 deck=$4 ranks=$5 tolerance=$6
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
on_ranks() {
  local n=$1
  shift
  if [[ $n == 1 ]]; then "$argine" "$@"; else "$mpiexec" -n "$n" --oversubscribe "$argine" "$@"; fi
}
on_ranks "$ranks" run "$deck" --output "$work/full" --quiet
checkpoint=$(ls "$work"/full/*.checkpoint)
cp -r "$work/full" "$work/resumed"
on_ranks "$ranks" run "$deck" --output "$work/resumed" --restart "$work/resumed/$(basename "$checkpoint")" \
  > "$work/restart.log" 2>&1 || { cat "$work/restart.log"; exit 1; }
grep -q "restarted from .*inside stage" "$work/restart.log" ||
  { echo "FAIL: the restart did not continue inside a stage"; cat "$work/restart.log"; exit 1; }
"$compare" "$work/full" "$work/resumed" 0
other=$((ranks == 1 ? 2 : 1))
cp -r "$work/full" "$work/other"
on_ranks "$other" run "$deck" --output "$work/other" --restart "$work/other/$(basename "$checkpoint")" \
  > "$work/other.log" 2>&1 || { cat "$work/other.log"; exit 1; }
grep -q "checkpoint was made on $ranks MPI rank(s), this run has $other: it continues" \
  "$work/other.log" || { echo "FAIL: no warning on $other rank(s)"; cat "$work/other.log"; exit 1; }
"$compare" "$work/full" "$work/other" "$tolerance"
echo "restart on $ranks rank(s): identical; on $other rank(s): within $tolerance"

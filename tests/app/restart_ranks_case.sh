#!/usr/bin/env bash
# A run on RANKS MPI ranks, restarted from its last checkpoint on as many ranks, ends with the
# files of the run never stopped, bit for bit; on another number of ranks the checkpoint is
# refused (exit 2, naming both counts) before any output (doc/checkpoints.md):
#   restart_ranks_case.sh ARGINE MPIEXEC COMPARE_RESULTS DECK RANKS
# The deck writes checkpoints and has an explicit stage after an implicit one with a head
# table (counted from the stage start), so the restart lands inside that stage.
set -euo pipefail
argine=$1 mpiexec=$2 compare=$3 deck=$4 ranks=$5
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
status=0
on_ranks "$other" run "$deck" --output "$work/other" --restart "$checkpoint" > "$work/other.log" 2>&1 ||
  status=$?
if [[ $status != 2 ]] || ! grep -q "checkpoint of a run on $ranks MPI rank(s); this run has $other" "$work/other.log" ||
  [[ -e $work/other ]]; then
  echo "FAIL: restart on $other rank(s) from a $ranks-rank checkpoint: exit $status"
  cat "$work/other.log"
  exit 1
fi
echo "restart on $ranks rank(s): identical; on $other rank(s): refused"

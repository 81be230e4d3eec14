#!/usr/bin/env bash
# `argine run DECK` on 1 rank and on RANKS MPI ranks writes the same files (doc/parallel.md):
#   two_ranks_case.sh ARGINE MPIEXEC COMPARE_RESULTS DECK TOLERANCE [RANKS, default 2]
set -euo pipefail
argine=$1 mpiexec=$2 compare=$3 deck=$4 tolerance=$5 ranks=${6:-2}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$argine" run "$deck" --output "$work/one" --quiet
"$mpiexec" -n "$ranks" --oversubscribe "$argine" run "$deck" --output "$work/two" --quiet
"$compare" "$work/one" "$work/two" "$tolerance"

#!/usr/bin/env bash
# `argine run DECK` on 1 rank and on 2 MPI ranks writes the same files (doc/parallel.md):
#   two_ranks_case.sh ARGINE MPIEXEC COMPARE_RESULTS DECK TOLERANCE
set -euo pipefail
argine=$1 mpiexec=$2 compare=$3 deck=$4 tolerance=$5
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$argine" run "$deck" --output "$work/one" --quiet
"$mpiexec" -n 2 --oversubscribe "$argine" run "$deck" --output "$work/two" --quiet
"$compare" "$work/one" "$work/two" "$tolerance"

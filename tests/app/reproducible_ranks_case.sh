#!/usr/bin/env bash
# `Parallel: {Reproducible Sums: true}`: `argine run DECK` on 1 rank and on RANKS ranks writes
# the same files bit for bit (points, grid, probes, diagnostics and boundary fluxes), also
# through a damped stage, which turns the round-off of plain sums into visible differences
# (doc/parallel.md):
#   reproducible_ranks_case.sh ARGINE MPIEXEC COMPARE_RESULTS DECK RANKS
set -euo pipefail
argine=$1 mpiexec=$2 compare=$3 deck=$4 ranks=$5
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$argine" run "$deck" --output "$work/one" --quiet
"$mpiexec" -n "$ranks" --oversubscribe "$argine" run "$deck" --output "$work/many" --quiet
"$compare" "$work/one" "$work/many" 0

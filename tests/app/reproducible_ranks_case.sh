#!/usr/bin/env bash
# `Parallel: {Reproducible Sums: true}`: `argine run DECK` on 1 rank and on RANKS ranks writes
# the same point and grid files and probes bit for bit, also through a damped stage (which
# turns the round-off of plain sums into visible differences, doc/parallel.md); the run's
# totals (diagnostics and boundary-flux CSV, reduced over the ranks with plain sums) agree to
# TOTALS_TOLERANCE.
#   reproducible_ranks_case.sh ARGINE MPIEXEC COMPARE_RESULTS DECK RANKS TOTALS_TOLERANCE
set -euo pipefail
argine=$1 mpiexec=$2 compare=$3 deck=$4 ranks=$5 tolerance=$6
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$argine" run "$deck" --output "$work/one" --quiet
"$mpiexec" -n "$ranks" --oversubscribe "$argine" run "$deck" --output "$work/many" --quiet
for run in one many; do
  mkdir -p "$work/totals_$run"
  mv "$work/$run"/*_diagnostics.csv "$work/$run"/*_boundary_flux.csv "$work/totals_$run/"
done
"$compare" "$work/one" "$work/many" 0
"$compare" "$work/totals_one" "$work/totals_many" "$tolerance"

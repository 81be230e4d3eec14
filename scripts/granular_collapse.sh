#!/usr/bin/env bash
# V7 granular column collapse against laboratory experiments (doc/verification.md, "V7
# Granular column collapse"; verification/granular_collapse/README.md).
#   scripts/granular_collapse.sh         the study: the nine transfer (FLIP, APIC, TPIC) x
#                                        shape-function (linear, GIMP, B-spline) pairs at a = 2
#                                        on L0/10, L0/20, L0/40; every aspect ratio's deck on
#                                        L0/20, without its side walls (plane strain) and with
#                                        FLIP/linear; the decks on L0/10 and L0/40 (the costly
#                                        a = 6 on L0/40 last).
#                                        Writes verification/granular_collapse/results/
#                                        (runs.csv, convergence.csv, accuracy_cost.csv,
#                                        profiles/) and doc/figures/granular_collapse_*.png
#   scripts/granular_collapse.sh pairs   the a = 2 pairs only (into results/, as the study)
#   scripts/granular_collapse.sh sensitivity  floor friction, E, points per cell, time step,
#                                        L0/80 at a = 0.5, and the side walls' mu_w / W (the
#                                        only way they enter) halved, or at mu_w = 0.30
#                                        (rows in results/runs.csv; reported, not used)
#   scripts/granular_collapse.sh quick   the decks as written (L0/20) only, into
#                                        build/verification/granular_collapse/quick/
# One run at a time (the machine's cores are shared). Runs whose row is in runs.csv already
# are skipped, so an interrupted study continues; delete runs.csv to start afresh.
# ARGINE_BUILD_DIR (default build/) is honoured; ARGINE_STUDY_WORK keeps the run folders.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${ARGINE_BUILD_DIR:-$root/build}
case_dir=$root/verification/granular_collapse
python=/usr/bin/python3
if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  "$root/scripts/build.sh"  # a fresh machine: install the packages, configure, build
fi
cmake --build "$build_dir" -j "${ARGINE_JOBS:-2}" --target argine_app
mode=${1:-study}
if [ "$mode" = quick ]; then
  results=$build_dir/verification/granular_collapse/quick
  figures=$results
else
  results=$case_dir/results
  figures=$root/doc/figures
fi
work=${ARGINE_STUDY_WORK:-$(mktemp -d)}
mkdir -p "$results/profiles"
runs=$results/runs.csv
start=$(date +%s)
echo "granular_collapse: run folders in $work, rows in $runs"

run() {  # collapse_run.py arguments; skipped when runs.csv has the row already. A failed
         # (unstable) run is a result: its row says so and the study goes on
  "$python" "$case_dir/collapse_run.py" --argine "$build_dir/argine" --work "$work" \
    --csv "$runs" --profiles "$results/profiles" --skip-existing "$@" ||
    echo "granular_collapse: that run failed (recorded in $runs)"
}

ratios="0.5 1 2 4 6"
pairs() {
  for cells in 10 20 40; do
    for shape in linear GIMP B-spline; do
      for transfer in FLIP APIC TPIC; do
        run --deck "$case_dir/collapse_a2.yaml" --cells $cells --shape $shape --transfer $transfer
      done
    done
  done
}
case $mode in
  quick)
    for a in $ratios; do run --deck "$case_dir/collapse_a$a.yaml"; done ;;
  pairs)
    pairs ;;
  sensitivity)  # reported, not used: floor friction and E (README "Sensitivity"), and the
                # numerical checks of the run-out above the band (points per cell, time step,
                # a finer mesh at a = 0.5)
    d4=$case_dir/collapse_a4.yaml
    run --deck "$d4" --set "Friction Coefficient (-)=0.3640" --tag-suffix _mu0.364
    run --deck "$d4" --set "Friction Coefficient (-)=1.0" --tag-suffix _mu1.0
    run --deck "$d4" --set "Young's Modulus (Pa)=4.0e6" --tag-suffix _E4e6
    for d in "$d4" "$case_dir/collapse_a6.yaml"; do
      run --deck "$d" --set "Points Per Element=9" --tag-suffix _ppc9
      run --deck "$d" --set "Safety Factor=0.25" --tag-suffix _sf0.25
    done
    run --deck "$case_dir/collapse_a0.5.yaml" --cells 80
    for a in $ratios; do  # mu_w / W from 4.62 (the decks) to 2.31 and 3.00 per metre
      run --deck "$case_dir/collapse_a$a.yaml" --set "Channel Width (m)=0.2" --tag-suffix _W0.2
      run --deck "$case_dir/collapse_a$a.yaml" --set "Channel Width (m)=0.154" --tag-suffix _W0.154
    done ;;
  *)
    pairs
    for a in $ratios; do
      run --deck "$case_dir/collapse_a$a.yaml"
      run --deck "$case_dir/collapse_a$a.yaml" --without-side-walls --tag-suffix _nowalls
      run --deck "$case_dir/collapse_a$a.yaml" --shape linear --transfer FLIP
    done
    for a in $ratios; do run --deck "$case_dir/collapse_a$a.yaml" --cells 10; done
    for a in $ratios; do run --deck "$case_dir/collapse_a$a.yaml" --cells 40; done ;;
esac
"$python" "$case_dir/collapse_study.py" --results "$results" --figures "$figures"
echo "granular_collapse: done in $(( $(date +%s) - start )) s"

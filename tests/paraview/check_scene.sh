#!/usr/bin/env bash
# Runs a scene with argine and opens its Exodus results in ParaView (pvpython): the point
# count the run reports must be what ParaView reads, with the expected variables and a
# rendered picture.   check_scene.sh ARGINE DECK OUTPUT_DIR OUT.png
set -euo pipefail
argine=$1 deck=$2 output=$3 png=$4
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
rm -rf "$output"
log=$("$argine" run "$deck" --output "$output" 2>&1)
echo "$log" | tail -5
points=$(grep -oE '[0-9]+ points' <<<"$log" | head -1 | cut -d' ' -f1)
grid=$(ls "$output"/*_grid.e)
points_file=$(ls "$output"/*_points.e)
bash "$here/run_paraview_check.sh" "$grid" "$points_file" "$points" "$png"

#!/usr/bin/env bash
# The variants of levee_toe_uplift.yaml: the same deck with the clay's permeability changed
# (thesis Sec. 4.3: k_clay / k_sand = 1e-1, 1e-3 against the deck's 1e-2; and the
# experiment's clay, k = 1.16e-9 m/s). The permeability-ratio variants stop 60 s after the
# Phase 4 step (the thesis compares them at t = 170 min); the experiment's clay runs the
# implicit phases and the drained stages only (its explicit step would be about 1e-6 s even
# with mass scaling 100: the stage is cut to 1 ms and logs that step); kexp_drag runs the
# experiment's clay through the whole explicit Phase 4 stage with the drag implicit
# (`Liquid Drag: implicit`, doc/theory.md Sec. 3.1), which lifts that bound. Each variant deck is
# written to results/levee_toe_uplift_variants/ and run there, one after another. Usage,
# from the repository root:
#
#   inputs/levee_toe_uplift/run_variants.sh [VARIANT ...]     # default: all of them
#
# Variants: ratio1e-1 ratio1e-3 kexp kexp_drag
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
deck="$here/levee_toe_uplift.yaml"
out="$root/results/levee_toe_uplift_variants"
argine="${ARGINE:-$root/build/argine}"
mkdir -p "$out"

# sed expressions of each change (every one must change the deck)
mesh="s|Gmsh File: levee_toe_uplift.msh|Gmsh File: $here/levee_toe_uplift.msh|"
k1='s|Saturated Conductivity (m/s): 7.44e-5|Saturated Conductivity (m/s): 7.44e-4|g'
k3='s|Saturated Conductivity (m/s): 7.44e-5|Saturated Conductivity (m/s): 7.44e-6|g'
kexp='s|Saturated Conductivity (m/s): 7.44e-5|Saturated Conductivity (m/s): 1.16e-9|g'
short='/    phase4_onset:/,/Output Interval/{s|Duration (s): 600.0|Duration (s): 60.0|}'
cut='/    phase4_onset:/,/Output Interval/{s|Duration (s): 600.0|Duration (s): 0.001|;s|Output Interval (s): 10.0|Output Interval (s): 0.001|}'
drag='/    phase4_onset:/,/Output Interval/{s|      Velocity Transfer: TPIC|      Velocity Transfer: TPIC\n      Liquid Drag: implicit|}'

changes() {
  case "$1" in
    ratio1e-1) printf '%s\n' "$k1" "$short" ;;
    ratio1e-3) printf '%s\n' "$k3" "$short" ;;
    kexp) printf '%s\n' "$kexp" "$cut" ;;
    kexp_drag) printf '%s\n' "$kexp" "$drag" ;;
    *) echo "unknown variant $1" >&2; return 1 ;;
  esac
}

variants=("$@")
[ ${#variants[@]} -eq 0 ] && variants=(ratio1e-1 ratio1e-3 kexp kexp_drag)
for v in "${variants[@]}"; do changes "$v" > /dev/null; done
for v in "${variants[@]}"; do
  name="levee_toe_uplift_$v"
  target="$out/$name.yaml"
  cp "$deck" "$target"
  while IFS= read -r expr; do
    [ -z "$expr" ] && continue
    before=$(md5sum < "$target")
    sed -i "$expr" "$target"
    [ "$before" != "$(md5sum < "$target")" ] || { echo "$v: no change by $expr" >&2; exit 2; }
  done < <(changes "$v"; printf '%s\n' "$mesh")
  sed -i "s|Name: levee_toe_uplift}|Name: $name}|" "$target"
  echo "== $name"
  "$argine" check "$target"
  start=$(date +%s)
  "$argine" run "$target" --output "$out/$name" --quiet
  echo "$name: $(( $(date +%s) - start )) s wall"
done

#!/usr/bin/env bash
# The variants of experimental_slope_rise.yaml: the same deck with one or two inputs changed
# (the thesis' ten-fold permeability, Table 5.4's MC_1, the strength models of the thesis'
# LEM), and of the whole test with each level held one day, experimental_slope_slow.yaml
# (slow_*: Table 5.4's MC_1, the thesis' other two HCCs, Hillel r = 2 and constant, and the
# drawdown without mass scaling, slow_ms1, and with the liquid's relative velocity kept at
# the fixities too, slow_ms1_fixity; and the 20 % of air left at S_max = 0.8 compressing by
# Boyle's law below the water, slow_air, also with the relative velocity kept at the fixities
# and the cracks at the cut-off air-filled, slow_air_fixity_cracks, whose drawdown runs 60 s;
# and without mass scaling, with the relative velocity at the fixities, slow_ms1_air_fixity).
# Each variant deck is written to results/experimental_slope_variants/ and run there, one
# after another (one run at a time). Usage, from the repository root:
#
#   inputs/experimental_slope/run_variants.sh [VARIANT ...]     # default: all of them
#
# Variants: mc1 k10 k10_mc1 fredlund vanapalli k10_fredlund k10_vanapalli patm k10_patm
#           slow_mc1 slow_hillel slow_constant slow_ms1 slow_ms1_fixity slow_air
#           slow_air_fixity_cracks slow_ms1_air_fixity
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
out="$root/results/experimental_slope_variants"
argine="${ARGINE:-$root/build/argine}"
mkdir -p "$out"

# sed expressions of each change (every one must match exactly once)
k10='s|Saturated Conductivity (m/s): 5.3e-6|Saturated Conductivity (m/s): 5.3e-5|'
mc1a='s|Cohesion Increase Max (Pa): 12000  # Table 5.4, MC_2|Cohesion Increase Max (Pa): 15000  # Table 5.4, MC_1|'
mc1b='s|Cohesion Suction Rate B: 0.07      # Table 5.4, MC_2|Cohesion Suction Rate B: 0.04      # Table 5.4, MC_1|'
patm='s|Atmospheric Pressure (Pa): 1000$|Atmospheric Pressure (Pa): 101325|'
fredlund='s|    Minimum Depth (m): 0.5|    Minimum Depth (m): 0.5\n    Suction Strength: fredlund\n    Suction Friction Angle (deg): 20|'
vanapalli='s|    Minimum Depth (m): 0.5|    Minimum Depth (m): 0.5\n    Suction Strength: vanapalli|'
hillel='s|Conductivity: {Model: Mualem, Lambda: 0.75, |Conductivity: {Model: Hillel, Exponent: 2, |'
constant='s|Conductivity: {Model: Mualem, Lambda: 0.75, |Conductivity: {Model: constant, |'
ms1='s|Mass Scaling: 100                  # the thesis|Mass Scaling: 1                    # not the thesis|'
# every explicit and quasi-static stage: the liquid keeps its relative velocity at the fixities
fixity='s#^\( *\)Solver: \(explicit\|quasi-static\)\(.*\)$#&\n\1Liquid At Solid Fixities: relative velocity#'
air='s|Minimum Saturation: 0.16, Maximum Saturation: 0.8}|Minimum Saturation: 0.16, Maximum Saturation: 0.8, Occluded Air Pressure (Pa): 101325}|'
cracks='s|      Mass Balance: complete|      Mass Balance: complete\n      Tension Cracks: air-filled|'
minute='s|      Duration (s): 30.0|      Duration (s): 60.0|'   # the drawdown stage

changes() {
  case "$1" in
    mc1) printf '%s\n' "$mc1a" "$mc1b" ;;
    k10) printf '%s\n' "$k10" ;;
    k10_mc1) printf '%s\n' "$k10" "$mc1a" "$mc1b" ;;
    fredlund) printf '%s\n' "$fredlund" ;;
    vanapalli) printf '%s\n' "$vanapalli" ;;
    k10_fredlund) printf '%s\n' "$k10" "$fredlund" ;;
    k10_vanapalli) printf '%s\n' "$k10" "$vanapalli" ;;
    patm) printf '%s\n' "$patm" ;;
    k10_patm) printf '%s\n' "$k10" "$patm" ;;
    slow_mc1) printf '%s\n' "$mc1a" "$mc1b" ;;
    slow_hillel) printf '%s\n' "$hillel" ;;
    slow_constant) printf '%s\n' "$constant" ;;
    slow_ms1) printf '%s\n' "$ms1" ;;
    slow_ms1_fixity) printf '%s\n' "$ms1" "$fixity" ;;
    slow_air) printf '%s\n' "$air" ;;
    slow_air_fixity_cracks) printf '%s\n' "$air" "$fixity" "$cracks" "$minute" ;;
    slow_ms1_air_fixity) printf '%s\n' "$ms1" "$air" "$fixity" ;;
    *) echo "unknown variant $1" >&2; return 1 ;;
  esac
}

variants=("$@")
[ ${#variants[@]} -eq 0 ] && variants=(mc1 k10 k10_mc1 fredlund vanapalli k10_fredlund k10_vanapalli
  patm k10_patm slow_mc1 slow_hillel slow_constant slow_ms1 slow_ms1_fixity slow_air
  slow_air_fixity_cracks slow_ms1_air_fixity)
for v in "${variants[@]}"; do changes "$v" > /dev/null; done
for v in "${variants[@]}"; do
  case "$v" in
    slow_*) base=experimental_slope_slow name="experimental_slope_$v" ;;
    *) base=experimental_slope_rise name="experimental_slope_rise_$v" ;;
  esac
  target="$out/$name.yaml"
  cp "$here/$base.yaml" "$target"
  while IFS= read -r expr; do
    [ -z "$expr" ] && continue
    before=$(md5sum < "$target")
    sed -i "$expr" "$target"
    [ "$before" != "$(md5sum < "$target")" ] || { echo "$v: no match for $expr" >&2; exit 2; }
  done < <(changes "$v")
  sed -i "s|Name: $base}|Name: $name}|" "$target"
  echo "== $name"
  "$argine" check "$target"
  start=$(date +%s)
  "$argine" run "$target" --output "$out/$name" --quiet
  echo "$name: $(( $(date +%s) - start )) s wall"
done

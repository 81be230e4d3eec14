#!/usr/bin/env bash
# Instructions per material-point update of the explicit step, per kernel, counted by
# valgrind (callgrind): the same count on every run, where the times on this shared VM vary
# by up to 35 % from one run to the next (doc/scaling.md, "Measuring a change here").
#
#   scripts/count_instructions.sh [scene] [steps]
#
# scene: a benchmark scene (default quad4-mohr-coulomb; argine_benchmark lists them), steps:
# default 4. Runs the scene for `steps` and for 2 x `steps` steps and divides the
# difference of each function's count by steps x points, so that the set-up drops out.
# Needs the build of scripts/build.sh (ARGINE_BUILD_DIR to use another; on a CPU with
# AVX-512, build-callgrind/ without it, made on first use) and valgrind (installed with
# apt-get when missing, as root).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
scene=${1:-quad4-mohr-coulomb}
steps=${2:-4}
build_dir=${ARGINE_BUILD_DIR:-$root/build}
if ! command -v valgrind >/dev/null || ! command -v callgrind_annotate >/dev/null; then
  apt-get install -y --no-install-recommends valgrind >/dev/null
fi
if grep -qw avx512f /proc/cpuinfo && [[ -z ${ARGINE_BUILD_DIR:-} ]]; then
  # valgrind 3.19 stops at the first AVX-512 instruction, which -march=native allows here: a
  # build of its own without AVX-512 (the same results, and the counts of an AVX2 machine).
  build_dir=$root/build-callgrind
  if [[ ! -x $build_dir/verification/benchmark/argine_benchmark ]]; then
    "$root/scripts/setup.sh"
    cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release \
      -DARGINE_NATIVE_EXCLUDE=-mno-avx512f >/dev/null
  fi
  cmake --build "$build_dir" --target argine_benchmark -j "$(nproc)" >/dev/null
fi
benchmark=$build_dir/verification/benchmark/argine_benchmark
[[ -x $benchmark ]] || "$root/scripts/build.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

count() {  # count N: callgrind of N steps -> $work/N.txt (inclusive-free, per function)
  valgrind --tool=callgrind --callgrind-out-file="$work/$1.out" "$benchmark" --scenes "$scene" \
    --steps "$1" --repeat 1 --warmup 0 >"$work/$1.log" 2>&1
  callgrind_annotate --threshold=100 "$work/$1.out" >"$work/$1.txt"
}
count "$steps"
count $((2 * steps))
points=$(sed -n 's/^scene [^:]*: \([0-9]*\) points.*/\1/p' "$work/$steps.log")

python3 - "$work/$steps.txt" "$work/$((2 * steps)).txt" "$steps" "$points" <<'EOF'
import re, sys
def counts(path):
    """Instructions per function name (arguments dropped), from callgrind_annotate."""
    out = {}
    for line in open(path):
        m = re.match(r"\s*([\d,]+) \([ \d.]+%\)\s+(.*)", line)
        if not m or "PROGRAM TOTALS" in line:
            continue
        name = m.group(2).split(":", 1)[-1] if m.group(2).startswith("???:") else m.group(2)
        name = re.sub(r"\[.*\]$", "", name).strip()
        name = name.replace("(anonymous namespace)::", "")
        name = re.sub(r"\(.*", "", name)  # arguments
        out[name] = out.get(name, 0) + int(m.group(1).replace(",", ""))
    return out
short, long_, steps, points = counts(sys.argv[1]), counts(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
updates = steps * points
rows = sorted(((long_[k] - short.get(k, 0)) / updates, k) for k in long_)
total = sum(v for v, _ in rows if v > 0)
print(f"{points} points, {steps} steps: {total:.0f} instructions per point update")
for v, k in reversed(rows):
    if v >= 0.5:
        print(f"{v:8.1f}  {k[:110]}")
EOF

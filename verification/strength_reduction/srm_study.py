#!/usr/bin/python3
"""Strength reduction against limit equilibrium on a dry 2:1 slope (doc/verification.md,
"Strength reduction"), under mesh refinement.

  srm_study.py --argine ARGINE --work DIR [--sizes 0.5 0.25 0.125] [--locking none nodal]
               [--own-mean-stress] [--dilatancy DEG] [--criterion WORD] [--check]

Runs srm_slope.yaml (0.25 m, associated flow, nodal volumetric averaging with forces
conjugate to it, failure by continuing displacement: the deck as written) and the same deck
with another Element Size (m) and Volumetric Strain Averaging, each in its own folder under
DIR, and reads from each log FS_SRM (+- its bracket) and Bishop's F on the same state (the
Factor Of Safety section at the SRM stage's start). Writes
  DIR/srm_slope.csv          h, points, FS_SRM, half width, Bishop F, wall s per run
  DIR/srm_slope.png          FS_SRM against h, and |FS_SRM - F_Bishop| against wall time
and prints the table, the changes between meshes, the observed order and the Richardson
extrapolation of FS_SRM. --own-mean-stress gives the forces each point's own mean stress
instead of the conjugate average (`Conjugate Mean Stress: false`, doc/theory.md Sec. 3.3.4;
unstable under dilatant flow); --dilatancy sets the soil's dilatancy angle (deg; 0: the
thesis' non-associated flow); --criterion the trials' Failure Criterion (e.g.
non-convergence, the deck's before 7 Dec 2026). The CTest runs the deck as written. --check
(the CTest) fails unless every run brackets FS_SRM to +- 0.01 and, with nodal averaging on the
three finest meshes, the extrapolated FS_SRM lies within 3 % of Bishop's F on the finest mesh
(SRM with associated flow and LEM on a homogeneous slope: Griffiths and Lane 1999, Dawson et
al. 1999 report agreement to a few per cent; with psi = 0 the answer on this slope depends on
the mesh and the damping, README.md).
"""
import argparse
import csv
import math
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
FS_LINE = re.compile(r"trials: FS_SRM = ([0-9.eE+-]+) \+- ([0-9.eE+-]+)")
LEM_LINE = re.compile(r"limit equilibrium on the same state \(last output\): F = ([0-9.eE+-]+)")
POINTS_LINE = re.compile(r"argine: \d+ steps, (\d+) points")


def variant(text, size, locking, directory, conjugate=True, dilatancy=None, criterion=None):
    text = re.sub(r"Element Size \(m\): [0-9.]+", f"Element Size (m): {size}", text)
    text = re.sub(r", Conjugate Mean Stress: \w+", "", text)
    averaging = f"Volumetric Strain Averaging: {locking}"
    if conjugate and locking != "none":
        averaging += ", Conjugate Mean Stress: true"
    text = re.sub(r"Volumetric Strain Averaging: \w+", averaging, text)
    if dilatancy is not None:
        text = re.sub(r"Dilatancy Angle \(deg\): [0-9.]+", f"Dilatancy Angle (deg): {dilatancy:g}",
                      text)
    if criterion is not None:
        text = re.sub(r"Failure Criterion: [a-z -]+\}", f"Failure Criterion: {criterion}}}", text)
    return re.sub(r"Directory: \S+,", f"Directory: {directory},", text)


def run(argine, work, size, locking, conjugate=True, dilatancy=None, criterion=None):
    name = f"h{size}_{locking}" + ("" if conjugate else "_own") + (
        f"_psi{dilatancy:g}" if dilatancy is not None else "") + (
        "_" + criterion.replace(" ", "_") if criterion else "")
    folder = os.path.join(work, name)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(HERE, "srm_slope.yaml")) as handle:
        deck = variant(handle.read(), size, locking, folder, conjugate, dilatancy, criterion)
    path = os.path.join(folder, "srm_slope.yaml")
    with open(path, "w") as handle:
        handle.write(deck)
    begin = time.time()
    done = subprocess.run([argine, "run", path], capture_output=True, text=True)
    wall = time.time() - begin
    log = done.stdout + done.stderr
    with open(os.path.join(folder, "argine.log"), "w") as handle:
        handle.write(log)
    if done.returncode != 0:
        raise SystemExit(f"argine failed on {path}:\n{log[-2000:]}")
    fs, half = map(float, FS_LINE.search(log).groups())
    return {"h": size, "locking": locking, "points": int(POINTS_LINE.search(log).group(1)),
            "fs_srm": fs, "half_width": half,
            "bishop": float(LEM_LINE.search(log).group(1)), "wall_s": wall}


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for locking, marker in (("nodal", "o-"), ("none", "s--")):
        sel = sorted((r for r in rows if r["locking"] == locking), key=lambda r: r["h"])
        if not sel:
            continue
        axes[0].errorbar([r["h"] for r in sel], [r["fs_srm"] for r in sel],
                         yerr=[r["half_width"] for r in sel], fmt=marker, capsize=3,
                         label=f"FS_SRM, volumetric averaging {locking}")
        axes[1].loglog([r["wall_s"] for r in sel],
                       [abs(r["fs_srm"] - r["bishop"]) / r["bishop"] for r in sel], marker,
                       label=f"averaging {locking}")
        for r in sel:
            axes[1].annotate(f"{r['h']} m", (r["wall_s"], abs(r["fs_srm"] - r["bishop"]) /
                                             r["bishop"]), fontsize=8)
    finest = min(rows, key=lambda r: r["h"])
    axes[0].axhline(finest["bishop"], color="k", lw=0.8,
                    label=f"Bishop on the same state ({finest['h']} m)")
    axes[0].set_xlabel("element size h (m)")
    axes[0].set_ylabel("factor of safety")
    axes[0].legend(fontsize=8)
    axes[0].grid(alpha=0.3)
    axes[1].set_xlabel("wall time of the run (s)")
    axes[1].set_ylabel("|FS_SRM - F_Bishop| / F_Bishop")
    axes[1].legend(fontsize=8)
    axes[1].grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--argine", required=True)
    parser.add_argument("--work", required=True)
    parser.add_argument("--sizes", type=float, nargs="+", default=[0.5, 0.25, 0.125])
    parser.add_argument("--locking", nargs="+", default=["nodal"])
    parser.add_argument("--own-mean-stress", action="store_true")
    parser.add_argument("--dilatancy", type=float)
    parser.add_argument("--criterion")
    parser.add_argument("--check", action="store_true")
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)
    rows = [run(args.argine, args.work, h, lock, not args.own_mean_stress, args.dilatancy,
                args.criterion)
            for lock in args.locking for h in args.sizes]
    with open(os.path.join(args.work, "srm_slope.csv"), "w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    print("h (m)  averaging  points  FS_SRM          Bishop  diff     wall (s)")
    for r in rows:
        print(f"{r['h']:<6} {r['locking']:<10} {r['points']:<7} {r['fs_srm']:.4f} +- "
              f"{r['half_width']:.4f}  {r['bishop']:.4f}  {100 * (r['fs_srm'] / r['bishop'] - 1):+.1f} %"
              f"  {r['wall_s']:.0f}")
    failures = [f"h = {r['h']} ({r['locking']}): bracket +- {r['half_width']} > 0.01"
                for r in rows if r["half_width"] > 0.01 + 1e-12]
    nodal = sorted((r for r in rows if r["locking"] == "nodal"), key=lambda r: -r["h"])
    if len(nodal) >= 3:
        f1, f2, f3 = (r["fs_srm"] for r in nodal[-3:])
        d12, d23 = f1 - f2, f2 - f3
        ratio = nodal[-3]["h"] / nodal[-2]["h"]
        print(f"changes: {d12:+.4f} ({nodal[-3]['h']} -> {nodal[-2]['h']} m), {d23:+.4f} "
              f"({nodal[-2]['h']} -> {nodal[-1]['h']} m)")
        if d12 * d23 > 0 and abs(d23) < abs(d12):
            order = math.log(d12 / d23) / math.log(ratio)
            limit = f3 - d23 / (ratio ** order - 1)
            bishop = nodal[-1]["bishop"]
            print(f"observed order {order:.2f}; extrapolated FS_SRM {limit:.4f}, Bishop {bishop:.4f}"
                  f" ({100 * (limit / bishop - 1):+.1f} %)")
            if abs(limit / bishop - 1) > 0.03:
                failures.append(f"extrapolated FS_SRM {limit:.4f} more than 3 % from Bishop "
                                f"{bishop:.4f}")
        else:
            print("FS_SRM does not converge monotonically on these meshes: no order")
            failures.append("no monotonic convergence of FS_SRM")
    try:
        plot(rows, os.path.join(args.work, "srm_slope.png"))
    except ImportError:
        print("(no matplotlib: no figure)")
    if args.check and failures:
        print("FAILED: " + "; ".join(failures))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())

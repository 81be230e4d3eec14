#!/usr/bin/env python3
"""A strength-reduction stage (doc/theory.md Sec. 11): the trials' displacement against F from
<Name>_strength_reduction.csv, and the failure mechanism (deviatoric strain increment) of the
lowest failing trial beside the highest holding one from <Name>_strength_reduction_points.csv;
with the critical circle of the limit-equilibrium search on the same state drawn over it when
<Name>_factor_of_safety.csv is there.

    scripts/plot_strength_reduction.py RESULTS_DIR NAME [--time T] [--out FILE.png]

--time: the start time (s) of the strength-reduction stage to draw (default: the last one).
"""
import argparse
import csv
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def read_rows(path):
    with open(path) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("directory")
    parser.add_argument("name")
    parser.add_argument("--out")
    parser.add_argument("--time", type=float, help="start time of the stage to draw (s)")
    args = parser.parse_args()
    stem = os.path.join(args.directory, args.name)
    trials = read_rows(stem + "_strength_reduction.csv")
    if not trials:
        raise SystemExit(f"{args.name}_strength_reduction.csv has no rows")
    times = sorted({r["time"] for r in trials})
    chosen = times[-1] if args.time is None else min(times, key=lambda t: abs(t - args.time))
    trials = [r for r in trials if r["time"] == chosen]
    points = [p for p in read_rows(stem + "_strength_reduction_points.csv")
              if p["time"] == chosen]
    circle = None
    if os.path.exists(stem + "_factor_of_safety.csv"):
        rows = [r for r in read_rows(stem + "_factor_of_safety.csv")
                if not math.isnan(r["factor_of_safety"]) and abs(r["time"] - chosen) < 1e-9]
        if rows:
            circle = rows[-1]

    fig, axes = plt.subplots(1, 3, figsize=(16, 4.6), gridspec_kw={"width_ratios": [1, 1.4, 1.4]})
    ax = axes[0]
    trials.sort(key=lambda r: r["factor"])
    for failed, style, label in ((0, "o", "holds"), (1, "x", "fails")):
        sel = [r for r in trials if r["failed"] == failed]
        ax.semilogy([r["factor"] for r in sel],
                    [max(r["mobilised_displacement"], 1e-7) for r in sel], style, ms=7,
                    label=label)
    ax.set_xlabel("strength reduction factor F")
    ax.set_ylabel("mean displacement of the mobilised mass (m)")
    ax.grid(alpha=0.3, which="both")
    ax.legend()
    ax.set_title(f"trials from t = {chosen:.4g} s")
    for ax, failed in ((axes[1], 0), (axes[2], 1)):
        sel = [p for p in points if p["failed"] == failed]
        if not sel:
            ax.set_axis_off()
            continue
        values = [max(p["deviatoric_strain_increment"], 1e-6) for p in sel]
        top = max(values)
        sc = ax.scatter([p["x"] for p in sel], [p["y"] for p in sel],
                        c=[math.log10(v) for v in values], s=4, cmap="viridis",
                        vmin=math.log10(top) - 3, vmax=math.log10(top))
        fig.colorbar(sc, ax=ax, label="log10 deviatoric strain increment")
        if circle is not None:
            t = [i * math.pi / 180 for i in range(181, 360)]
            xc, yc, r = circle["centre_x"], circle["centre_y"], circle["radius"]
            ax.plot([xc + r * math.cos(a) for a in t], [yc + r * math.sin(a) for a in t], "r--",
                    lw=1, label=f"critical circle, LEM F = {circle['factor_of_safety']:.3f}")
            ax.legend(loc="upper left", fontsize=8)
        ax.set_aspect("equal")
        xs = [p["x"] for p in sel]
        ys = [p["y"] for p in sel]
        ax.set_xlim(min(xs), max(xs))
        ax.set_ylim(min(ys), max(ys) + 0.5)
        ax.set_title(f"{'fails' if failed else 'holds'} at F = {sel[0]['factor']:.4g}")
        ax.set_xlabel("x (m)")
        ax.set_ylabel("y (m)")
    fig.tight_layout()
    out = args.out or stem + "_strength_reduction.png"
    fig.savefig(out, dpi=110)
    print(out)


if __name__ == "__main__":
    main()

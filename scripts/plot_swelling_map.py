#!/usr/bin/python3
"""Where a slide's points swelled since the event started, on several meshes (P11 item 3).

  plot_swelling_map.py H:DIR:NAME ... [--start S] [--times T ...] [--window X0 X1 Y0 Y1]
                       [--limit L] --figure PATH

One row per run (DIR/NAME_points.e, Exodus II read with SciPy), one column per time (s after
the event started, the simulation time minus --start): the points at their current
positions coloured by V / V(start) - 1, their volume change since the start, clipped to
+-L (default 5e-3). A slide whose skeleton keeps its volume (dilatancy angle 0) shows
white; a band or crack that opens shows as a red line. For each run and time it prints the
crest core's points (levee_convergence.py's crest core: x0 < 1.5 m, y0 > 2 m) that swelled
by more than 2e-3, their share of the core's volume change and where they started.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import levee_convergence as lc  # noqa: E402  (the points reader and the crest core)

SWOLLEN = 2e-3  # a point counts as swollen above this volume change since the start


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("runs", nargs="+", help="H:DIR:NAME")
    parser.add_argument("--start", type=float, default=1.0)
    parser.add_argument("--times", type=float, nargs="+", default=[1.0, 2.5])
    parser.add_argument("--window", type=float, nargs=4, default=[0.0, 8.0, -0.5, 3.1])
    parser.add_argument("--limit", type=float, default=5e-3)
    parser.add_argument("--figure", required=True)
    args = parser.parse_args()

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(len(args.runs), len(args.times),
                             figsize=(6.5 * len(args.times), 2.6 * len(args.runs)),
                             squeeze=False, layout="constrained")
    print("| h (m) | t (s) | crest core points swollen > 2e-3 | their share of its change "
          "| x0 (m), 10/50/90 % | y0 (m), 10/50/90 % |")
    print("|---|---|---|---|---|---|")
    for row, spec in enumerate(args.runs):
        h, directory, name = spec.split(":")[:3]
        time, x0, y0, v = lc.right_half(*lc.read_points(
            os.path.join(directory, name + "_points.e"), ("displ_x", "displ_y", "volume")))
        k0 = lc.output_index(time, args.start)
        core = lc.crest_core(x0, y0)
        for col, t in enumerate(args.times):
            k = lc.output_index(time, args.start + t)
            change = v["volume"][k] / v["volume"][k0] - 1
            ax = axes[row][col]
            scatter = ax.scatter(x0 + v["displ_x"][k], y0 + v["displ_y"][k], c=change,
                                 s=0.6 * (float(h) / 0.05) ** 2, cmap="RdBu_r",
                                 vmin=-args.limit, vmax=args.limit, linewidths=0)
            ax.set_xlim(args.window[:2])
            ax.set_ylim(args.window[2:])
            ax.set_aspect("equal")
            ax.set_title(f"h = {h} m, {t:g} s after the start", fontsize=9)
            swollen = core & (change > SWOLLEN)
            gain = v["volume"][k][core] - v["volume"][k0][core]
            share = (v["volume"][k][swollen] - v["volume"][k0][swollen]).sum() / gain.sum()
            where = [" / ".join(f"{q:.2f}" for q in np.percentile(a[swollen], [10, 50, 90]))
                     if swollen.any() else "-" for a in (x0, y0)]
            print(f"| {h} | {t:g} | {swollen.sum()} | {share:.2f} | {where[0]} | {where[1]} |")
    fig.colorbar(scatter, ax=axes, label="V / V(start) - 1", shrink=0.6)
    fig.savefig(args.figure, dpi=80)
    print(f"\nwrote {args.figure}")


if __name__ == "__main__":
    main()

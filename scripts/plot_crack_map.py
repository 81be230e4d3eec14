#!/usr/bin/python3
"""Where a slide's points sit at the tension cut-off, and their liquid pressure (P11).

  plot_crack_map.py H:DIR:NAME ... [--start S] [--times T ...] [--pressure-time T]
                    [--window X0 X1 Y0 Y1] --figure PATH

One column per run (DIR/NAME_points.e, Exodus II read with SciPy), one row per time (s after
the event started, the simulation time minus --start): the points at their current
positions, grey, with those whose last return was to the tension cut-off (plastic_state 3,
kMohrCoulombTension) in red; a last row maps p_L (kPa) at --pressure-time. The title of each
panel gives the share of the moved points (|u| > 0.1 m) at the cut-off; the same counts are
printed as a table.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import levee_convergence as lc  # noqa: E402  (the points reader and the "moved" threshold)

TENSION = 3  # plastic_state of a return to the tension cut-off (MohrCoulomb.hpp)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("runs", nargs="+", help="H:DIR:NAME")
    parser.add_argument("--start", type=float, default=1.0)
    parser.add_argument("--times", type=float, nargs="+", default=[1.0, 2.0])
    parser.add_argument("--pressure-time", type=float, default=2.0)
    parser.add_argument("--window", type=float, nargs=4, default=[0.0, 9.0, 0.0, 3.2])
    parser.add_argument("--figure", required=True)
    args = parser.parse_args()

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rows = len(args.times) + 1
    fig, axes = plt.subplots(rows, len(args.runs), figsize=(6.5 * len(args.runs), 2.6 * rows),
                             squeeze=False, layout="constrained")
    x0, x1, y0, y1 = args.window
    table = []  # (h, t, points at the cut-off, moved points, moved ones at the cut-off)
    for j, spec in enumerate(args.runs):
        h, directory, name = spec.split(":")[:3]
        time, first_x, first_y, v = lc.read_points(
            f"{directory}/{name}_points.e",
            ("displacement_x", "displacement_y", "plastic_state", "pressure_liquid"))
        v.update(time=time, x0=first_x, y0=first_y)
        size = 0.3 if len(v["x0"]) > 20000 else 1.5
        for i, t in enumerate(args.times + [args.pressure_time]):
            k = lc.output_index(v["time"], args.start + t)
            x = v["x0"] + v["displacement_x"][k]
            y = v["y0"] + v["displacement_y"][k]
            ax = axes[i][j]
            if i < len(args.times):
                moved = np.hypot(v["displacement_x"][k], v["displacement_y"][k]) > lc.MOVED
                cracked = v["plastic_state"][k] == TENSION
                share = (cracked & moved).sum() / max(moved.sum(), 1)
                table.append((h, t, int(cracked.sum()), int(moved.sum()),
                               int((cracked & moved).sum())))
                ax.scatter(x, y, s=size, c="lightgrey", linewidths=0)
                ax.scatter(x[cracked], y[cracked], s=2 * size, c="red", linewidths=0)
                ax.set_title(f"h = {h} m, {t:g} s after the start: {cracked.sum()} points at the "
                             f"cut-off ({100 * share:.1f} % of the moved)", fontsize=8)
            else:
                sc = ax.scatter(x, y, s=size, c=v["pressure_liquid"][k] / 1e3, cmap="RdBu_r",
                                vmin=-8, vmax=8, linewidths=0)
                fig.colorbar(sc, ax=ax, label="p_L (kPa)", shrink=0.8)
                ax.set_title(f"h = {h} m, {t:g} s after the start: p_L", fontsize=8)
            ax.set_xlim(x0, x1)
            ax.set_ylim(y0, y1)
            ax.set_aspect("equal")
            ax.tick_params(labelsize=7)
    fig.savefig(args.figure, dpi=100)
    print("| h (m) | t after the start (s) | points at the cut-off | moved points | "
          "moved at the cut-off (%) |")
    print("|---:|---:|---:|---:|---:|")
    for h, t, cracked, moved, both in table:
        print(f"| {h} | {t:g} | {cracked} | {moved} | {100 * both / max(moved, 1):.1f} |")
    print(f"wrote {args.figure}")


if __name__ == "__main__":
    main()

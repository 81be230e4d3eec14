#!/usr/bin/env python3
"""Cell crossing against cost: position error of the settled column against wall time, one
line per transfer scheme x shape family (cell_crossing.csv of cell_crossing_verification)."""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STYLE = {"linear": "o-", "GIMP": "s-", "B-spline": "^-"}
COLOUR = {"FLIP": "tab:red", "APIC": "tab:blue", "TPIC": "tab:green", "XPIC": "tab:purple"}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--csv", required=True)
    parser.add_argument("--figures", required=True)
    args = parser.parse_args()
    rows = list(csv.DictReader(open(os.path.join(args.csv, "cell_crossing.csv"))))
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for family in STYLE:
        for scheme in COLOUR:
            mine = [r for r in rows if r["family"] == family and r["scheme"] == scheme
                    and r["status"] == "ok"]
            if not mine:
                continue
            wall = [float(r["wall_s"]) for r in mine]
            cells = [int(r["cells"]) for r in mine]
            position = [float(r["position_error"]) for r in mine]
            stress = [float(r["stress_error"]) for r in mine]
            label = f"{scheme} / {family}"
            axes[0].loglog(wall, position, STYLE[family], color=COLOUR[scheme], label=label)
            axes[1].loglog(cells, stress, STYLE[family], color=COLOUR[scheme], label=label)
    axes[0].set_xlabel("wall time (s)")
    axes[0].set_ylabel("RMS position error / settlement")
    axes[0].set_title("accuracy against cost (8 ... 64 cells)")
    axes[1].set_xlabel("cells over the height")
    axes[1].set_ylabel("RMS stress error / rho g H")
    axes[1].set_title("stress: the quadrature floor of 2 x 2 points a cell")
    for ax in axes:
        ax.grid(alpha=0.3, which="both")
    axes[0].legend(fontsize=7, ncol=2)
    fig.tight_layout()
    path = os.path.join(args.figures, "cell_crossing_accuracy_cost.png")
    fig.savefig(path, dpi=110)
    print("wrote", path)


if __name__ == "__main__":
    main()

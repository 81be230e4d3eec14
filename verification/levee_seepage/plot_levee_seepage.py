#!/usr/bin/env python3
"""Figures of V4 (levee seepage, explicit path) from the CSV files of
levee_seepage_verification: p_L and S_L on sections S1 (x = 1.5 m) and S2 (x = 3.0 m) at
72, 160, 300 s; S_L contours at 75, 150, 225, 300 s; river level, seepage exit point and
liquid balance against time."""
import argparse
import csv
import os
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402

OUTLINE = [(0.0, 0.0), (4.5, 0.0), (2.5, 1.0), (2.0, 1.0), (0.0, 0.0)]


def read(path):
    with open(path) as f:
        return [{k: float(v) if k != "section" else v for k, v in row.items()}
                for row in csv.DictReader(f)]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--csv", required=True)
    parser.add_argument("--figures", required=True)
    parser.add_argument("--tag", default="levee_seepage")
    a = parser.parse_args()
    base = os.path.join(a.csv, a.tag)

    sections = read(base + "_sections.csv")
    fig, axes = plt.subplots(2, 2, figsize=(9, 7), sharey=True)
    for r, name in enumerate(["S1", "S2"]):
        groups = defaultdict(list)
        for row in sections:
            if row["section"] == name:
                groups[row["time"]].append(row)
        for t in sorted(groups):
            rows = sorted(groups[t], key=lambda q: q["y"])
            y = [q["y"] for q in rows]
            axes[r][0].plot([q["pressure"] / 1000 for q in rows], y, ".-", label=f"{t:g} s")
            axes[r][1].plot([q["saturation"] for q in rows], y, ".-", label=f"{t:g} s")
        axes[r][0].set_title(f"{name}: liquid pressure")
        axes[r][1].set_title(f"{name}: degree of saturation")
        axes[r][0].set_xlabel("p_L (kPa)")
        axes[r][1].set_xlabel("S_L (-)")
        axes[r][0].set_ylabel("y (m)")
        axes[r][0].legend()
    fig.tight_layout()
    fig.savefig(os.path.join(a.figures, a.tag + "_sections.png"), dpi=120)

    field = read(base + "_field.csv")
    history = read(base + "_history.csv")
    level = {round(h["time"], 6): h["river_level"] for h in history}
    times = sorted({row["time"] for row in field})[:4]
    fig, axes = plt.subplots(len(times), 1, figsize=(8, 2.4 * len(times)), sharex=True)
    if len(times) == 1:
        axes = [axes]
    for ax, t in zip(axes, times):
        rows = [q for q in field if q["time"] == t]
        tri = mtri.Triangulation([q["x"] for q in rows], [q["y"] for q in rows])
        c = ax.tricontourf(tri, [q["saturation"] for q in rows], levels=[0.1 + 0.1 * k for k in range(10)] + [1.0001])
        ax.plot(*zip(*OUTLINE), "k-", lw=1)
        h = level.get(round(t, 6))
        if h is not None:
            ax.plot([0, 2.0 * h], [h, h], "b-", lw=2)
        ax.set_title(f"S_L at {t:g} s")
        ax.set_aspect("equal")
        fig.colorbar(c, ax=ax)
    axes[-1].set_xlabel("x (m)")
    fig.tight_layout()
    fig.savefig(os.path.join(a.figures, a.tag + "_saturation.png"), dpi=120)

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    t = [h["time"] for h in history]
    ax1.plot(t, [h["river_level"] for h in history], label="river level H")
    ax1.plot(t, [h["landside_exit"] for h in history], "o-", label="landside exit point")
    ax1.plot(t, [h["riverside_exit"] for h in history], "s-", label="riverside outflow top")
    ax1.set_xlabel("t (s)")
    ax1.set_ylabel("y (m)")
    ax1.legend()
    ax2.plot(t, [h["storage_change"] for h in history], "k-", lw=3, label="storage change")
    total = [h["inflow_river"] + h["inflow_landside"] + h["inflow_crest"] for h in history]
    ax2.plot(t, total, "y--", label="sum of boundary inflows")
    ax2.plot(t, [h["inflow_river"] for h in history], label="river")
    ax2.plot(t, [h["inflow_landside"] for h in history], label="landside seepage face")
    ax2.set_xlabel("t (s)")
    ax2.set_ylabel("volume (m3/m)")
    ax2.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(a.figures, a.tag + "_history.png"), dpi=120)
    print("figures in", a.figures)


if __name__ == "__main__":
    main()

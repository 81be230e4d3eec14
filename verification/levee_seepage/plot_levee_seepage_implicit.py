#!/usr/bin/env python3
"""V4 implicit vs explicit: error against wall time (levee_seepage_implicit_cost.csv) and the
S1/S2 p_L profiles of every run (levee_seepage_implicit_profiles.csv)."""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--csv", default=".")
parser.add_argument("--figures", default=".")
parser.add_argument("--explicit-wall", type=float, default=None,
                    help="wall time (s) of the explicit runs, for their points on the chart")
args = parser.parse_args()

cost = list(csv.DictReader(open(os.path.join(args.csv, "levee_seepage_implicit_cost.csv"))))
fig, ax = plt.subplots(figsize=(5.5, 4))
for row in cost:
    wall = row["wall_seconds"] or (args.explicit_wall and str(args.explicit_wall))
    if not wall:
        continue
    ax.loglog(float(wall), 100 * float(row["p_error"]), "o" if "implicit" in row["run"] else "s")
    ax.annotate(row["run"], (float(wall), 100 * float(row["p_error"])), fontsize=7)
ax.set_xlabel("wall time (s, shared machine)")
ax.set_ylabel("max |p_L - p_ref| / range (%)")
ax.axhline(3, color="grey", lw=0.8, ls="--")
ax.set_title("V4 sections S1/S2 at 72/160/300 s vs the refined implicit reference", fontsize=8)
fig.tight_layout()
fig.savefig(os.path.join(args.figures, "levee_seepage_error_vs_time.png"), dpi=120)

profiles = list(csv.DictReader(open(os.path.join(args.csv, "levee_seepage_implicit_profiles.csv"))))
fig, axes = plt.subplots(1, 2, figsize=(9, 4), sharey=True)
# One colour per run, one line style per time; --explicit2 is the unstabilised deck.
styles = {"reference": ("black", "reference"), "implicit": ("tab:blue", "implicit h 0.05"),
          "explicit": ("tab:red", "explicit, head stabilisation 0.1"),
          "explicit2": ("tab:orange", "explicit, thesis scheme (unstabilised)")}
dashes = {"72": "-", "160": "--", "300": ":"}
for ax, section in zip(axes, ["S1", "S2"]):
    for run in [r for r in styles if any(p["run"] == r for p in profiles)]:
        colour, name = styles[run]
        for time in ["72", "160", "300"]:
            rows = [r for r in profiles if r["run"] == run and r["section"] == section
                    and r["time"] == time and r["pressure"] != "nan"]
            ax.plot([float(r["pressure"]) for r in rows], [float(r["y"]) for r in rows],
                    lw=1.6 if run == "reference" else 0.9, color=colour, ls=dashes[time],
                    label=f"{name}, {time} s")
    ax.set_title(section)
    ax.set_xlabel("p_L (Pa)")
axes[0].set_ylabel("y (m)")
axes[1].legend(fontsize=5)
fig.tight_layout()
fig.savefig(os.path.join(args.figures, "levee_seepage_implicit_sections.png"), dpi=120)

#!/usr/bin/python3
"""Plots of V2 suction diffusion from the CSV files of suction_diffusion_verification.

  plot_suction_diffusion.py [--csv DIR] [--figures DIR] [--elements 40]

Reads suction_diffusion_errors.csv and suction_diffusion_profiles.csv from DIR (default:
the current directory) and writes into --figures (default: doc/figures of the repository):
  suction_diffusion_isochrones.png   s/s0 against height for the three cases (thesis
                                     Fig. 4.2): Eq. 4.17 (lines), complete mass balance
                                     (circles) and simplified (crosses) on one mesh
  suction_diffusion_convergence.png  error of the complete form against element count and
                                     against wall time
"""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.ticker import NullFormatter, ScalarFormatter  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_FIGURES = os.path.normpath(os.path.join(HERE, "..", "..", "doc", "figures"))
TITLES = {"a": "(a) s0 = 500 kPa, a_v = 1e-3 /kPa",
          "b": "(b) s0 = 500 kPa, a_v = 1e-5 /kPa",
          "c": "(c) s0 = 5 kPa, a_v = 1e-3 /kPa"}


def read(path):
    with open(path, newline="") as handle:
        return [{k: (v if k in ("case", "form") else float(v)) for k, v in row.items()}
                for row in csv.DictReader(handle)]


def isochrones(profiles, elements, path):
    cases = sorted({r["case"] for r in profiles})
    factors = sorted({r["T"] for r in profiles})
    colours = plt.cm.viridis([0.05 + 0.8 * i / max(1, len(factors) - 1)
                              for i in range(len(factors))])
    fig, axes = plt.subplots(1, len(cases), figsize=(4 * len(cases), 4.6), sharey=True,
                             squeeze=False)
    for ax, case in zip(axes[0], cases):
        for colour, T in zip(colours, factors):
            def rows(form):
                return sorted((r for r in profiles if r["case"] == case and r["form"] == form
                               and int(r["elements"]) == elements and r["T"] == T),
                              key=lambda r: r["y0_m"])
            complete, simplified = rows("complete"), rows("simplified")
            ax.plot([r["s_ref_over_s0"] for r in complete], [r["y0_m"] for r in complete], "-",
                    color=colour, lw=1.3, label=f"Eq. 4.17, T = {T:g}")
            ax.plot([r["s_num_over_s0"] for r in complete], [r["y0_m"] for r in complete], "o",
                    color=colour, ms=3, mfc="none", label="complete (4.12)" if T == factors[0]
                    else None)
            ax.plot([r["s_num_over_s0"] for r in simplified], [r["y0_m"] for r in simplified],
                    "x", color=colour, ms=3, label="simplified (4.14)" if T == factors[0]
                    else None)
        ax.set_title(TITLES.get(case, case), fontsize=9)
        ax.set_xlabel("normalised suction s / s0")
        ax.set_xlim(-0.1, 1.1)
        ax.grid(alpha=0.3)
    axes[0][0].set_ylabel("height y (m)")
    axes[0][0].legend(fontsize=7, loc="lower left")
    fig.suptitle(f"V2 suction diffusion in a rigid 1 m column, {elements} elements, "
                 "4 points per element", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def convergence(errors, path):
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    markers = {"a": "o", "b": "s", "c": "^"}
    for case in sorted({r["case"] for r in errors}):
        rows = [r for r in errors if r["case"] == case and r["form"] == "complete"]
        meshes = sorted({int(r["elements"]) for r in rows})
        for T in sorted({r["T"] for r in rows}):
            sel = sorted((r for r in rows if r["T"] == T), key=lambda r: r["elements"])
            left.loglog([r["elements"] for r in sel], [r["error"] for r in sel],
                        markers.get(case, "o") + "-", ms=4, lw=0.8,
                        label=f"case {case}, T = {T:g}")
        worst = [max(r["error"] for r in rows if int(r["elements"]) == n) for n in meshes]
        wall = [max(r["wall_s"] for r in rows if int(r["elements"]) == n) for n in meshes]
        right.loglog(wall, worst, markers.get(case, "o") + "-", label=f"case {case}")
        for n, w, e in zip(meshes, wall, worst):
            right.annotate(f"{n}", (w, e), textcoords="offset points", xytext=(4, 4), fontsize=7)
    x = [10, 80]
    left.loglog(x, [0.09 * 10 / v for v in x], "k:", lw=1, label="slope -1")
    for ax in (left, right):
        ax.axhline(0.03, color="r", lw=0.8, ls="--", label="bound 3 % (40 el.)")
        ax.grid(alpha=0.3, which="both")
    left.set_xticks([10, 20, 40, 80])
    left.xaxis.set_major_formatter(ScalarFormatter())
    left.xaxis.set_minor_formatter(NullFormatter())
    left.set_xlabel("elements over the height")
    left.set_ylabel("error of s/s0 (complete mass balance)")
    left.legend(fontsize=6, ncol=2)
    right.set_xlabel("wall time of the run to T = 0.5 (s)")
    right.set_ylabel("largest error over T = 0.05, 0.2, 0.5")
    right.legend(fontsize=7)
    fig.suptitle("V2 suction diffusion: error against resolution and against cost "
                 "(labels: elements)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--csv", default=".")
    parser.add_argument("--figures", default=DEFAULT_FIGURES)
    parser.add_argument("--elements", type=int, default=40)
    args = parser.parse_args()
    os.makedirs(args.figures, exist_ok=True)
    errors = read(os.path.join(args.csv, "suction_diffusion_errors.csv"))
    profiles = read(os.path.join(args.csv, "suction_diffusion_profiles.csv"))
    isochrones(profiles, args.elements,
               os.path.join(args.figures, "suction_diffusion_isochrones.png"))
    convergence(errors, os.path.join(args.figures, "suction_diffusion_convergence.png"))
    print(f"wrote suction diffusion figures into {args.figures}")


if __name__ == "__main__":
    main()

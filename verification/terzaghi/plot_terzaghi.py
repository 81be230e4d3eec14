#!/usr/bin/python3
"""Plots of V1 Terzaghi consolidation from the CSV files of terzaghi_verification.

  plot_terzaghi.py [--csv DIR] [--figures DIR] [--tags terzaghi,terzaghi_simplified]

Reads <tag>_errors.csv, <tag>_profiles.csv and <tag>_consolidation.csv for every tag found
in DIR (default: the current directory) and writes into --figures (default: doc/figures of
the repository):
  terzaghi_isochrones.png        p/p0 against height, numerical (points) and series (lines),
                                 one panel per mesh, for the first tag
  terzaghi_isochrones_<tag>.png  the same for every further tag
  terzaghi_consolidation.png     degree of consolidation U(T): series against U from the
                                 settlement and from the mean pore pressure
  terzaghi_convergence.png       relative L2 error against element count and wall time
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
LABELS = {"terzaghi": "complete mass balance (4.12)",
          "terzaghi_simplified": "simplified mass balance (4.14)"}


def read(path):
    with open(path, newline="") as handle:
        return [{k: (float(v) if k not in ("case", "form") else v) for k, v in row.items()}
                for row in csv.DictReader(handle)]


def isochrones(profiles, tag, path):
    meshes = sorted({int(r["elements"]) for r in profiles})
    factors = sorted({r["T"] for r in profiles})
    fig, axes = plt.subplots(1, len(meshes), figsize=(3.2 * len(meshes), 4.2), sharey=True,
                             squeeze=False)
    colours = plt.cm.viridis([i / max(1, len(factors) - 1) * 0.9 for i in range(len(factors))])
    for ax, n in zip(axes[0], meshes):
        for colour, T in zip(colours, factors):
            rows = sorted((r for r in profiles if int(r["elements"]) == n and r["T"] == T),
                          key=lambda r: r["y0_m"])
            y = [r["y0_m"] for r in rows]
            ax.plot([r["p_ref_over_p0"] for r in rows], y, "-", color=colour, lw=1.2,
                    label=f"T = {T:g}")
            ax.plot([r["p_num_over_p0"] for r in rows], y, "o", color=colour, ms=2.5, mfc="none")
        ax.set_title(f"{n} elements")
        ax.set_xlabel("p / p0")
        ax.set_xlim(-0.15, 1.1)
        ax.grid(alpha=0.3)
    axes[0][0].set_ylabel("height y (m)")
    axes[0][0].legend(fontsize=7, loc="lower left")
    fig.suptitle(f"V1 Terzaghi isochrones, {LABELS.get(tag, tag)}: series (lines), "
                 "material points (circles)", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def consolidation(tables, path):
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    first = True
    for tag, rows in tables.items():
        meshes = sorted({int(r["elements"]) for r in rows})
        n = 40 if 40 in meshes else meshes[-1]
        sel = sorted((r for r in rows if int(r["elements"]) == n), key=lambda r: r["T"])
        T = [r["T"] for r in sel]
        if first:
            left.semilogx(T, [r["U_ref"] for r in sel], "k-", lw=1.5, label="series U(T)")
            right.plot([r["t_s"] for r in sel], [1e3 * r["settlement_ref_m"] for r in sel], "k-",
                       lw=1.5, label="series")
            first = False
        name = LABELS.get(tag, tag)
        left.semilogx(T, [r["U_settlement"] for r in sel], "o", ms=3.5, mfc="none",
                      label=f"{name}, {n} el.: from settlement")
        left.semilogx(T, [r["U_pressure"] for r in sel], "x", ms=3.5,
                      label=f"{name}, {n} el.: 1 - mean p / p0")
        right.plot([r["t_s"] for r in sel], [1e3 * r["settlement_m"] for r in sel], "o", ms=3,
                   mfc="none", label=f"{name}, {n} el.")
    left.set_xlabel("time factor T = c_v t / h^2")
    left.set_ylabel("degree of consolidation U")
    left.grid(alpha=0.3, which="both")
    left.legend(fontsize=7)
    right.set_xlabel("time t (s)")
    right.set_ylabel("settlement of the top (mm)")
    right.grid(alpha=0.3)
    right.legend(fontsize=7)
    fig.suptitle("V1 Terzaghi: degree of consolidation and settlement", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def convergence(tables, path):
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    markers = "osd^v"
    for k, (tag, rows) in enumerate(tables.items()):
        name = LABELS.get(tag, tag)
        factors = sorted({r["T"] for r in rows})
        meshes = sorted({int(r["elements"]) for r in rows})
        for T in factors:
            sel = sorted((r for r in rows if r["T"] == T), key=lambda r: r["elements"])
            left.loglog([r["elements"] for r in sel], [r["error"] for r in sel],
                        markers[k % len(markers)] + ("-" if k == 0 else "--"), ms=4,
                        label=f"{name}, T = {T:g}")
        # cost: the wall time of the whole run (to the last isochrone) against the largest
        # error over the isochrones
        worst = [max(r["error"] for r in rows if int(r["elements"]) == n)
                 for n in meshes]
        wall = [max(r["wall_s"] for r in rows if int(r["elements"]) == n) for n in meshes]
        right.loglog(wall, worst, markers[k % len(markers)] + "-", label=name)
        for n, w, e in zip(meshes, wall, worst):
            right.annotate(f"{n}", (w, e), textcoords="offset points", xytext=(4, 4), fontsize=7)
    x = [10, 80]
    left.loglog(x, [0.04 * 10 / v for v in x], "k:", lw=1, label="slope -1")
    left.axhline(0.03, color="r", lw=0.8, ls="--", label="bound 3 % (40 el.)")
    right.axhline(0.03, color="r", lw=0.8, ls="--", label="bound 3 %")
    left.set_xticks([10, 20, 40, 80])
    left.xaxis.set_major_formatter(ScalarFormatter())
    left.xaxis.set_minor_formatter(NullFormatter())
    left.set_xlabel("elements over the height")
    left.set_ylabel("error of p (max of the two relative L2 norms)")
    left.grid(alpha=0.3, which="both")
    left.legend(fontsize=6, ncol=2)
    right.set_xlabel("wall time of the run to T = 1 (s)")
    right.set_ylabel("largest error over the isochrones")
    right.grid(alpha=0.3, which="both")
    right.legend(fontsize=7)
    fig.suptitle("V1 Terzaghi: error against resolution and against cost", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--csv", default=".")
    parser.add_argument("--figures", default=DEFAULT_FIGURES)
    parser.add_argument("--tags", default="terzaghi,terzaghi_simplified")
    args = parser.parse_args()
    tags = [t for t in args.tags.split(",")
            if os.path.exists(os.path.join(args.csv, f"{t}_errors.csv"))]
    if not tags:
        raise SystemExit(f"no <tag>_errors.csv for tags {args.tags} in {args.csv}")
    os.makedirs(args.figures, exist_ok=True)
    errors = {t: read(os.path.join(args.csv, f"{t}_errors.csv")) for t in tags}
    consol = {t: read(os.path.join(args.csv, f"{t}_consolidation.csv")) for t in tags}
    for i, tag in enumerate(tags):
        name = "terzaghi_isochrones.png" if i == 0 else f"terzaghi_isochrones_{tag}.png"
        isochrones(read(os.path.join(args.csv, f"{tag}_profiles.csv")), tag,
                   os.path.join(args.figures, name))
    consolidation(consol, os.path.join(args.figures, "terzaghi_consolidation.png"))
    convergence(errors, os.path.join(args.figures, "terzaghi_convergence.png"))
    print(f"wrote terzaghi figures for {', '.join(tags)} into {args.figures}")


if __name__ == "__main__":
    main()

"""V6 K0 initialisation: sigma'_yy and p_L of the points (after the K0 procedure and after the
quasi-static relaxation) against the independent reference profile. Writes k0_profiles.png."""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--csv", required=True)
    parser.add_argument("--figures", required=True)
    a = parser.parse_args()
    initial = read(os.path.join(a.csv, "k0_points_initial.csv"))
    relaxed = read(os.path.join(a.csv, "k0_points_relaxed.csv"))
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9, 6), sharey=True)
    for data, style, label in ((initial, "o", "K0 procedure"), (relaxed, "x", "after relaxation")):
        ax1.plot([v / 1e3 for v in data["stress_yy"]], data["y"], style, ms=3, label=label)
        ax2.plot([v / 1e3 for v in data["liquid_pressure"]], data["y"], style, ms=3, label=label)
    order = sorted(range(len(initial["y"])), key=lambda i: initial["y"][i])
    ax1.plot([initial["stress_yy_reference"][i] / 1e3 for i in order],
             [initial["y"][i] for i in order], "k-", lw=1, label="reference (quadrature)")
    ax2.plot([initial["liquid_pressure_reference"][i] / 1e3 for i in order],
             [initial["y"][i] for i in order], "k-", lw=1, label="reference")
    for ax in (ax1, ax2):
        for y in (2.0, 4.0):
            ax.axhline(y, color="0.7", lw=0.5)
        ax.axhline(3.0, color="b", lw=0.5, ls="--")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    ax1.set_xlabel("effective vertical stress sigma'_yy (kPa, tension +)")
    ax2.set_xlabel("liquid pressure p_L (kPa, compression +)")
    ax1.set_ylabel("y (m)")
    fig.suptitle("V6: K0 initialisation of a layered, partly saturated column")
    fig.tight_layout()
    out = os.path.join(a.figures, "k0_profiles.png")
    fig.savefig(out, dpi=120)
    print("wrote", out)


if __name__ == "__main__":
    main()

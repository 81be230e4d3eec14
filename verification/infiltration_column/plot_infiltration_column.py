"""V3 implicit infiltration column: profiles vs the refined reference, error vs wall time.

Reads infiltration_column_profiles.csv and infiltration_column_study.csv written by
infiltration_column_verification; writes infiltration_column_profiles.png and
infiltration_column_error_vs_time.png.
"""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--csv", required=True)
    parser.add_argument("--figures", required=True)
    args = parser.parse_args()

    rows = read(os.path.join(args.csv, "infiltration_column_profiles.csv"))
    fig, (ax_p, ax_s) = plt.subplots(1, 2, figsize=(10, 5), sharey=True)
    for time in sorted({float(r["time"]) for r in rows}):
        for run, style in (("reference", "-"), ("implicit", "o")):
            sel = [r for r in rows if r["run"] == run and float(r["time"]) == time]
            y = [float(r["y"]) for r in sel]
            label = f"{run} {time:.0f} s"
            ax_p.plot([float(r["p_L"]) / 1e3 for r in sel], y, style, ms=3, label=label)
            ax_s.plot([float(r["S_L"]) for r in sel], y, style, ms=3, label=label)
    ax_p.set_xlabel("p_L (kPa, compression positive)")
    ax_p.set_ylabel("y (m)")
    ax_s.set_xlabel("S_L (-)")
    ax_p.legend(fontsize=7)
    fig.suptitle("V3 infiltration, implicit path (h 0.05 m) vs refined implicit reference")
    fig.tight_layout()
    fig.savefig(os.path.join(args.figures, "infiltration_column_profiles.png"), dpi=120)

    study = read(os.path.join(args.csv, "infiltration_column_study.csv"))
    fig, ax = plt.subplots(figsize=(7, 5))
    for theta, marker in (("1", "o"), ("0.5", "s")):
        for size in sorted({r["element_size"] for r in study}, key=float):
            sel = [r for r in study if r["theta"] == theta and r["element_size"] == size]
            ax.loglog([float(r["wall_seconds"]) for r in sel],
                      [max(float(r["error_p"]), float(r["error_S"])) for r in sel],
                      marker=marker, label=f"theta {theta}, h {size} m")
    ax.axhline(0.02, color="k", ls="--", lw=1, label="V3 bound 2 %")
    ax.set_xlabel("wall time (s)")
    ax.set_ylabel("max(p_L, S_L) error / range")
    ax.set_title("V3 implicit: error vs wall time (steps <= 8, 2, 0.5 s)")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(args.figures, "infiltration_column_error_vs_time.png"), dpi=120)


if __name__ == "__main__":
    main()

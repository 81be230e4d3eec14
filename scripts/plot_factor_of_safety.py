#!/usr/bin/env python3
"""The factor of safety of a run (doc/theory.md Sec. 10): F(t) from <Name>_factor_of_safety.csv
and the critical circle's slices at one evaluation from <Name>_critical_slices.csv.

    scripts/plot_factor_of_safety.py RESULTS_DIR NAME [--time T] [--out FILE.png] [--hours]

--time: the evaluation whose slip surface is drawn (default: the one with the lowest F).
"""
import argparse
import csv
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def read_csv(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]} if rows else {}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("directory")
    parser.add_argument("name")
    parser.add_argument("--time", type=float)
    parser.add_argument("--out")
    parser.add_argument("--hours", action="store_true", help="time axis in hours")
    args = parser.parse_args()
    history = read_csv(os.path.join(args.directory, args.name + "_factor_of_safety.csv"))
    if not history:
        raise SystemExit(f"{args.name}_factor_of_safety.csv has no rows")
    scale = 3600.0 if args.hours else 1.0
    times = history["time"]
    factors = history["factor_of_safety"]
    finite = [(t, f) for t, f in zip(times, factors) if not math.isnan(f)]
    chosen = args.time
    if chosen is None and finite:
        chosen = min(finite, key=lambda tf: tf[1])[0]

    slices_path = os.path.join(args.directory, args.name + "_critical_slices.csv")
    has_slices = os.path.exists(slices_path)
    fig, axes = plt.subplots(1, 2 if has_slices else 1, figsize=(12 if has_slices else 6, 4.6))
    ax = axes[0] if has_slices else axes
    ax.plot([t / scale for t in times], factors, "o-", ms=3, label="F of the critical circle")
    if "bishop" in history and history["bishop"] != factors:  # Method: spencer
        ax.plot([t / scale for t in times], history["bishop"], ":", lw=1,
                label="Bishop, same circle")
    ax.plot([t / scale for t in times], history["ordinary_method"], "--", lw=1,
            label="ordinary method, same circle")
    ax.axhline(1.0, color="k", lw=0.8)
    ax.set_xlabel("time (h)" if args.hours else "time (s)")
    ax.set_ylabel("factor of safety")
    ax.legend()
    ax.grid(alpha=0.3)
    if has_slices and chosen is not None:
        slices = read_csv(slices_path)
        at = min(set(slices["time"]), key=lambda t: abs(t - chosen))
        pick = [i for i, t in enumerate(slices["time"]) if t == at]
        x = [slices["x_mid"][i] for i in pick]
        ax2 = axes[1]
        ax2.plot(x, [slices["top_y"][i] for i in pick], "k-", label="ground over the mass")
        ax2.plot(x, [slices["base_y"][i] for i in pick], "r-", label="critical slip circle")
        k = times.index(min(times, key=lambda t: abs(t - at)))
        ax2.set_title(f"t = {at / scale:.4g} {'h' if args.hours else 's'}: F = {factors[k]:.3f}")
        ax2.set_aspect("equal")
        ax2.set_xlabel("x (m)")
        ax2.set_ylabel("y (m)")
        ax2.legend()
    out = args.out or os.path.join(args.directory, args.name + "_factor_of_safety.png")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()

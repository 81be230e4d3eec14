#!/usr/bin/env python3
"""Figures and numbers of inputs/levee_flood_72h/README.md from the run of
levee_flood_72h_seepage.yaml (the 72 h implicit phase):

  /usr/bin/python3 inputs/levee_flood_72h/plot_levee_flood_72h.py [--results DIR]

Writes levee_flood_72h_history.png (river level, phreatic levels and pore pressures against
time) and levee_flood_72h_phreatic.png (phreatic surface across the section at several times)
next to this script, and prints the critical time: the time of the largest exit gradient
across the landside blanket at the toe, i = (H(-6 m) - 0) / 6 m, H = y + p_L/(rho_L g) the
total head at the base of the sandy silt under the landside toe (x = 44.4 m).
"""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
RHO_G = 1000.0 * 9.81
NAME = "levee_flood_72h_seepage"
SECTIONS = ["x10_0", "x25_0", "x28_0", "x32_2", "x36_0", "x38_0", "x40_0", "x42_0", "x44_4",
            "x47_0", "x55_0"]
GROUND = [(0, 0), (20, 0), (30.2, 5.1), (34.2, 5.1), (44.4, 0), (80, 0)]


def read_rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def hydrograph():
    t, h = [], []
    with open(os.path.join(HERE, "hydrograph.csv")) as f:
        for line in f:
            if line.startswith("#") or line.startswith("time"):
                continue
            a, b = line.split(",")
            t.append(float(a) / 3600)
            h.append(float(b))
    return t, h


def section(results, name):
    """{time (h): [(y, p_L, S_L)]} of a vertical profile."""
    out = {}
    for r in read_rows(os.path.join(results, f"{NAME}_section_{name}.csv")):
        out.setdefault(float(r["time"]) / 3600, []).append(
            (float(r["y"]), float(r["liquid_pressure"]), float(r["saturation"])))
    return out


def phreatic_level(profile):
    """Highest y where p_L changes sign from + (below) to - (above); None if all negative."""
    profile = sorted(profile)
    level = None
    for (y0, p0, _), (y1, p1, _) in zip(profile, profile[1:]):
        if p0 >= 0 > p1:
            level = y0 + (y1 - y0) * p0 / (p0 - p1)
    if level is None and profile and profile[-1][1] >= 0:
        level = profile[-1][0]
    return level


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--results", default=os.path.join(ROOT, "results", NAME))
    args = parser.parse_args()

    sections = {name: section(args.results, name) for name in SECTIONS}
    times = sorted(sections["x44_4"])
    # Exit gradient across the landside blanket at the toe.
    gradient = []
    for t in times:
        base = min(sections["x44_4"][t])  # lowest sample, y = -6 m
        head = base[0] + base[1] / RHO_G
        gradient.append(head / 6.0)
    i_max = max(range(len(times)), key=lambda i: gradient[i])
    t_crit = times[i_max]
    print(f"critical time (largest exit gradient at the landside toe): t = {t_crit:g} h "
          f"({t_crit * 3600:.0f} s), i = {gradient[i_max]:.3f}")
    for name in ["x32_2", "x40_0", "x44_4"]:
        levels = [phreatic_level(sections[name][t]) for t in times]
        valid = [(lv, t) for lv, t in zip(levels, times) if lv is not None]
        if valid:
            lv, t = max(valid)
            print(f"  phreatic level at {name}: highest {lv:.2f} m at t = {t:g} h; "
                  f"at the critical time {levels[i_max] if levels[i_max] is not None else float('nan'):.2f} m")
    probes = {}
    for probe in ["river_toe", "crest", "landside_slope", "landside_toe", "blanket_base", "aquifer"]:
        rows = read_rows(os.path.join(args.results, f"{NAME}_probe_{probe}.csv"))
        probes[probe] = ([float(r["time"]) / 3600 for r in rows],
                         [float(r["liquid_pressure"]) / 1000 for r in rows],
                         [float(r["saturation"]) for r in rows])
        p = probes[probe][1]
        k = max(range(len(p)), key=lambda i: p[i])
        print(f"  probe {probe} ({rows[0]['x'][:6]}, {rows[0]['y'][:6]}): p_L {p[0]:.1f} -> max "
              f"{p[k]:.1f} kPa at t = {probes[probe][0][k]:g} h -> {p[-1]:.1f} kPa at 72 h")

    th, hh = hydrograph()
    fig, ax = plt.subplots(3, 1, figsize=(8, 10), sharex=True)
    ax[0].plot(th, hh, "k-", label="river (total head)")
    for name, style in [("x32_2", "b-"), ("x40_0", "g-"), ("x44_4", "r-")]:
        levels = [phreatic_level(sections[name][t]) for t in times]
        ax[0].plot([t for t, lv in zip(times, levels) if lv is not None],
                   [lv for lv in levels if lv is not None], style,
                   label=f"phreatic level at x = {name[1:].replace('_', '.')} m")
    ax[0].axvline(t_crit, color="0.5", ls="--", label=f"critical time {t_crit:g} h")
    ax[0].set_ylabel("elevation (m)")
    ax[0].legend(fontsize=8)
    for probe, (t, p, s) in probes.items():
        ax[1].plot(t, p, label=probe)
        ax[2].plot(t, s, label=probe)
    ax[1].set_ylabel("p_L (kPa)")
    ax[1].legend(fontsize=8)
    ax[2].set_ylabel("S_L (-)")
    ax[2].set_xlabel("time (h)")
    ax[1].axvline(t_crit, color="0.5", ls="--")
    fig.suptitle("levee_flood_72h: implicit seepage, 72 h hydrograph")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "levee_flood_72h_history.png"), dpi=110)

    fig, ax = plt.subplots(figsize=(10, 4.5))
    gx, gy = zip(*GROUND)
    ax.fill_between(gx, gy, -7, color="#d9c9a3", label="sandy silt")
    ax.plot(gx, gy, "k-")
    xs = [float(n[1:].replace("_", ".")) for n in SECTIONS]
    for t, color in [(0, "0.4"), (12, "c"), (24, "b"), (t_crit, "r"), (48, "m"), (72, "g")]:
        tt = min(times, key=lambda s: abs(s - t))
        levels = [phreatic_level(sections[n][tt]) for n in SECTIONS]
        ax.plot([x for x, lv in zip(xs, levels) if lv is not None],
                [lv for lv in levels if lv is not None], "o-", color=color, ms=3,
                label=f"t = {tt:g} h")
    ax.set_xlim(0, 80)
    ax.set_ylim(-6, 6)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title("phreatic surface (p_L = 0) from the vertical profiles")
    ax.legend(fontsize=8, ncol=2)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "levee_flood_72h_phreatic.png"), dpi=110)


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Figures and the F-versus-water-level table of inputs/experimental_slope/README.md.

  /usr/bin/python3 inputs/experimental_slope/plot_experimental_slope.py [--results DIR]

Reads, where present (DIR defaults to the repository's results/):
  DIR/experimental_slope_rise/                 the deck experimental_slope_rise.yaml
  DIR/experimental_slope_rise_slow/            experimental_slope_rise_slow.yaml
  DIR/experimental_slope_variants/<name>/      the runs of run_variants.sh
  DIR/experimental_slope_drawdown/             experimental_slope_drawdown.yaml (explicit)
  DIR/experimental_slope/, DIR/experimental_slope_slow/
                                               experimental_slope.yaml, _slow.yaml (the whole
                                               test: implicit rise, drained equilibria,
                                               explicit drawdown)
Each run's water level comes from the Total Head Table of its own deck (the variants' decks
are in DIR/experimental_slope_variants/). Writes next to this script:
  experimental_slope_factor_of_safety.png  F against time and against the water level
  experimental_slope_critical_circle.png   p_L of the points and the critical circle
  experimental_slope_drawdown.png          the drawdown: probes and the final deposit
  experimental_slope_whole_test.png        the whole-test decks: F(t), probes, deposits
  experimental_slope_whole_test_variants.png  the same for the slow deck and its run_variants.sh
                                           slow_* variants (DIR/experimental_slope_variants/)
and prints, per run, F at the end of every water level's hold and the first level at which
F < 1. With --mesh-study it reads only DIR/convergence/experimental_slope_slow_h<h>/ (the
runs of scripts/convergence.sh), prints the drawdown's measures per mesh with their changes,
observed order and Richardson estimate, and writes experimental_slope_mesh_study.png (the
distance to that estimate against wall time).
"""
import argparse
import csv
import glob
import math
import os
import re

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
SURFACE = [(0.0, 6.0), (5.0, 6.0), (11.0, 0.0), (15.0, 0.0)]
THESIS_LEM_LEVEL = 5.8            # thesis: first FS < 1 of its LEM (Fredlund / Vanapalli)
EXPERIMENT_ONSET = (5.0, 6.0)     # thesis: the experiment's failure onset

# (label, results sub-directory, run name, deck, style)
RUNS = [
    ("MC_2, k 5.3e-6 (deck)", "experimental_slope_rise", "experimental_slope_rise",
     os.path.join(HERE, "experimental_slope_rise.yaml"), dict(color="C0", lw=2)),
    ("MC_1, k 5.3e-6", "experimental_slope_variants/experimental_slope_rise_mc1",
     "experimental_slope_rise_mc1", None, dict(color="C0", ls="--")),
    ("MC_2, k 5.3e-5 (thesis' k)", "experimental_slope_variants/experimental_slope_rise_k10",
     "experimental_slope_rise_k10", None, dict(color="C1", lw=2)),
    ("MC_1, k 5.3e-5", "experimental_slope_variants/experimental_slope_rise_k10_mc1",
     "experimental_slope_rise_k10_mc1", None, dict(color="C1", ls="--")),
    ("MC, Eq. 4.25 with p_atm, k 5.3e-6", "experimental_slope_variants/experimental_slope_rise_patm",
     "experimental_slope_rise_patm", None, dict(color="C4", ls="-")),
    ("MC, Eq. 4.25 with p_atm, k 5.3e-5",
     "experimental_slope_variants/experimental_slope_rise_k10_patm",
     "experimental_slope_rise_k10_patm", None, dict(color="C4", ls="--")),
    ("Fredlund 20 deg, k 5.3e-6", "experimental_slope_variants/experimental_slope_rise_fredlund",
     "experimental_slope_rise_fredlund", None, dict(color="C2", ls="-")),
    ("Fredlund 20 deg, k 5.3e-5",
     "experimental_slope_variants/experimental_slope_rise_k10_fredlund",
     "experimental_slope_rise_k10_fredlund", None, dict(color="C2", ls="--")),
    ("Vanapalli, k 5.3e-6", "experimental_slope_variants/experimental_slope_rise_vanapalli",
     "experimental_slope_rise_vanapalli", None, dict(color="C3", ls="-")),
    ("Vanapalli, k 5.3e-5", "experimental_slope_variants/experimental_slope_rise_k10_vanapalli",
     "experimental_slope_rise_k10_vanapalli", None, dict(color="C3", ls="--")),
    ("MC_2, k 5.3e-6, levels held 1 day", "experimental_slope_rise_slow",
     "experimental_slope_rise_slow", os.path.join(HERE, "experimental_slope_rise_slow.yaml"),
     dict(color="k", lw=2)),
]


def read_csv(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]} if rows else {}


def level_table(deck):
    """(times, levels) of the first Total Head Table in the deck."""
    with open(deck) as f:
        text = f.read()
    m = re.search(r"Total Head Table:\s*\[([^\]]*)\]", text)
    values = [float(v) for v in m.group(1).split(",")]
    return np.array(values[0::2]), np.array(values[1::2])


def holds(times, levels):
    """[(level, end of its hold)] of the table's plateaus, the initial level first."""
    out = [(levels[0], times[0])]
    for k in range(1, len(times)):
        if levels[k] == levels[k - 1] and times[k] > times[k - 1]:
            out.append((levels[k], times[k]))
    return out


def load(results):
    runs = []
    for label, sub, name, deck, style in RUNS:
        directory = os.path.join(results, sub)
        path = os.path.join(directory, name + "_factor_of_safety.csv")
        if deck is None:
            deck = os.path.join(results, "experimental_slope_variants", name + ".yaml")
        if not (os.path.exists(path) and os.path.exists(deck)):
            continue
        fs = read_csv(path)
        tt, hh = level_table(deck)
        runs.append(dict(label=label, name=name, dir=directory, fs=fs, style=style,
                         table=(tt, hh), level=np.interp(fs["time"], tt, hh)))
    return runs


def point_variable_numbers(f):
    """{name: number} of an Exodus file's point (nodal) variables, as in vals_nod_var<number>."""
    names = ["".join(c.decode() for c in row).strip("\x00 ")
             for row in f.variables["name_nod_var"][:]]
    return {n: k + 1 for k, n in enumerate(names)}


def point_displacements(path):
    """(times, x0, y0, [(u_x, u_y) per output]) of a points file (Exodus)."""
    from scipy.io import netcdf_file
    with netcdf_file(path, "r", mmap=False) as f:
        var = point_variable_numbers(f)
        times = f.variables["time_whole"][:].copy()
        x0, y0 = f.variables["coordx"][:].copy(), f.variables["coordy"][:].copy()
        ux, uy = (f.variables["vals_nod_var%d" % var[n]] for n in ("displ_x", "displ_y"))
        displacement = [(ux[k].copy(), uy[k].copy()) for k in range(len(times))]
    return times, x0, y0, displacement


def report(run):
    fs, (tt, hh) = run["fs"], run["table"]
    print(f"\n{run['label']} ({run['name']})")
    print("  level (m)  end of hold (s)      F    ordinary   circle entry -> exit x, depth")
    for level, t in holds(tt, hh):
        # the last output at or before the end of the hold
        k = max(i for i in range(len(fs["time"])) if fs["time"][i] <= t + 1e-6)
        print(f"  {level:8.2f}  {fs['time'][k]:14.0f}  {fs['factor_of_safety'][k]:6.3f}  "
              f"{fs['ordinary_method'][k]:8.3f}   {fs['entry_x'][k]:5.2f} -> "
              f"{fs['exit_x'][k]:5.2f}, {fs['max_depth'][k]:4.2f} m")
    below = np.nonzero(fs["factor_of_safety"] < 1.0)[0]
    lowest = int(np.nanargmin(fs["factor_of_safety"]))
    print(f"  lowest F {fs['factor_of_safety'][lowest]:.3f} at t = {fs['time'][lowest]:.0f} s "
          f"(level {run['level'][lowest]:.2f} m)")
    if len(below):
        k = below[0]
        print(f"  first F < 1: {fs['factor_of_safety'][k]:.3f} at t = {fs['time'][k]:.0f} s, "
              f"level {run['level'][k]:.2f} m")
    else:
        print("  F stays >= 1")


def plot_factor(runs, path):
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12.5, 5.6))
    fast = [r for r in runs if r["fs"]["time"][-1] < 1000]
    for r in fast:
        ax1.plot(r["fs"]["time"], r["fs"]["factor_of_safety"], label=r["label"], **r["style"])
    if fast:
        tt, hh = fast[0]["table"]
        twin = ax1.twinx()
        twin.plot(tt, hh, color="0.6", lw=1)
        twin.set_ylabel("water level (m), grey", color="0.4")
        twin.set_ylim(0, 12)
    ax1.axhline(1.0, color="k", lw=0.8)
    ax1.set_xlabel("time (s): the thesis' schedule (each level in 2 s, held 60 s)")
    ax1.set_ylabel("factor of safety (critical circle)")
    ax1.set_ylim(0, None)
    ax1.grid(alpha=0.3)
    ax1.set_title("F(t), the thesis' schedule", fontsize=10)
    for r in runs:
        tt, hh = r["table"]
        pts = []
        for level, t in holds(tt, hh):
            k = max(i for i in range(len(r["fs"]["time"])) if r["fs"]["time"][i] <= t + 1e-6)
            pts.append((level, r["fs"]["factor_of_safety"][k]))
        x, y = zip(*pts)
        ax2.plot(x, y, marker="o", ms=4, label=r["label"], **r["style"])
    ax2.axhline(1.0, color="k", lw=0.8)
    ax2.axvspan(*EXPERIMENT_ONSET, color="0.85", zorder=0, label="experiment: onset 5-6 m")
    ax2.axvline(THESIS_LEM_LEVEL, color="m", ls=":", label="thesis LEM: F < 1 at 5.8 m")
    ax2.set_xlabel("water level (m) at the end of its hold")
    ax2.set_ylabel("factor of safety")
    ax2.set_ylim(0, None)
    ax2.grid(alpha=0.3)
    ax2.set_title("F at the end of each level's hold", fontsize=10)
    handles, labels = ax2.get_legend_handles_labels()
    fig.legend(handles, labels, fontsize=7.5, loc="lower center", ncol=5)
    fig.tight_layout(rect=(0, 0.13, 1, 1))
    fig.savefig(path, dpi=90)
    plt.close(fig)
    print(f"wrote {path}")


def points_at(directory, name, time):
    from scipy.io import netcdf_file
    with netcdf_file(os.path.join(directory, name + "_points.e"), "r", mmap=False) as f:
        times = f.variables["time_whole"][:].copy()
        k = int(np.argmin(abs(times - time)))
        var = point_variable_numbers(f)
        p = f.variables["vals_nod_var%d" % var["pressure_liquid"]][k].copy()
        x = f.variables["coordx"][:].copy() + f.variables["vals_nod_var%d" % var["displ_x"]][k]
        y = f.variables["coordy"][:].copy() + f.variables["vals_nod_var%d" % var["displ_y"]][k]
    return x, y, p, times[k]


def circle(fs, k):
    """The critical circle of evaluation k from entry to exit (its lower arc)."""
    xc, yc, r = fs["centre_x"][k], fs["centre_y"][k], fs["radius"][k]
    x = np.linspace(fs["entry_x"][k], fs["exit_x"][k], 200)
    return x, yc - np.sqrt(np.maximum(r * r - (x - xc) ** 2, 0.0))


def plot_circles(runs, path):
    """p_L of the points with the critical circle: the deck at its lowest F and at its end,
    the slow-rise run at its first F < 1 (or lowest F)."""
    panels = []
    by_name = {r["name"]: r for r in runs}
    main = by_name.get("experimental_slope_rise")
    if main:
        fs = main["fs"]
        k = int(np.nanargmin(fs["factor_of_safety"]))
        panels.append((main, fs["time"][k]))
        panels.append((main, fs["time"][-1]))
    slow = by_name.get("experimental_slope_rise_slow")
    if slow:
        fs = slow["fs"]
        below = np.nonzero(fs["factor_of_safety"] < 1.0)[0]
        k = below[0] if len(below) else int(np.nanargmin(fs["factor_of_safety"]))
        panels.append((slow, fs["time"][k]))
    if not panels:
        return
    try:
        import scipy.io  # noqa: F401
    except ImportError:
        print("no SciPy: critical-circle figure skipped (apt-get install python3-scipy)")
        return
    fig, axes = plt.subplots(len(panels), 1, figsize=(7.5, 2.9 * len(panels)),
                             layout="constrained")
    image = None
    for ax, (run, t) in zip(np.atleast_1d(axes), panels):
        x, y, p, tp = points_at(run["dir"], run["name"], t)
        norm = matplotlib.colors.TwoSlopeNorm(vmin=-30.0, vcenter=0.0, vmax=60.0)
        image = ax.scatter(x, y, c=p / 1e3, s=3.0, lw=0, cmap="RdBu_r", norm=norm,
                           rasterized=True)
        k = int(np.argmin(abs(run["fs"]["time"] - t)))
        ax.plot(*circle(run["fs"], k), "k-", lw=1.8)
        level = run["level"][k]
        ax.plot([0, 15], [level, level], color="C0", lw=0.8, ls="--")
        ax.plot(*zip(*SURFACE), color="0.5", lw=0.6)
        unit = f"{tp / 3600:.1f} h" if tp > 3600 else f"{tp:.0f} s"
        ax.set_title(f"{run['label']}: t = {unit}, water level {level:.2f} m, "
                     f"F = {run['fs']['factor_of_safety'][k]:.3f}", fontsize=9)
        ax.set_aspect("equal")
        ax.set_xlim(0, 15)
        ax.set_ylim(0, 7)
        ax.set_ylabel("y (m)")
    np.atleast_1d(axes)[-1].set_xlabel("x (m); dashed: the water level; black: critical circle")
    fig.colorbar(image, ax=axes, label="p_L (kPa), suction negative", shrink=0.8)
    fig.savefig(path, dpi=75)
    plt.close(fig)
    print(f"wrote {path}")


def plot_drawdown(results, path):
    """Probe displacements against time and the points at the end of the drawdown, coloured
    by their displacement; prints the run-out numbers."""
    directory = os.path.join(results, "experimental_slope_drawdown")
    name = "experimental_slope_drawdown"
    if not os.path.exists(os.path.join(directory, name + "_points.e")):
        return
    times, x0, y0, displacement = point_displacements(
        os.path.join(directory, name + "_points.e"))
    ux, uy = displacement[-1]
    u = np.hypot(ux, uy)
    x, y = x0 + ux, y0 + uy
    k = int(np.argmax(u))
    print(f"\ndrawdown ({name}), t = {times[-1]:.1f} s: largest |u| {u[k]:.2f} m, point "
          f"from ({x0[k]:.2f}, {y0[k]:.2f}) to ({x[k]:.2f}, {y[k]:.2f})")
    print(f"  toe: the farthest point at y < 0.5 m is at x = {x[y < 0.5].max():.2f} m "
          f"(initial toe 11.0 m)")
    crest = (x0 < 5.0) & (y0 > 5.5)
    print(f"  crest (x0 < 5 m, y0 > 5.5 m): largest settlement {-uy[crest].min():.2f} m, "
          f"at x0 = {x0[crest][np.argmin(uy[crest])]:.2f} m")
    moved = u > 0.1
    print(f"  points that moved more than 0.1 m: {moved.sum()} of {len(u)}; they started "
          f"at x >= {x0[moved].min():.2f} m" if moved.any() else "  no point moved 0.1 m")
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12.5, 4.2), width_ratios=[1, 1.6])
    for probe, colour in (("crest_edge", "C0"), ("mid_slope", "C1"), ("toe", "C2")):
        pr = read_csv(os.path.join(directory, f"{name}_probe_{probe}.csv"))
        if pr:
            ax1.plot(pr["time"], np.hypot(pr["displacement_x"], pr["displacement_y"]),
                     color=colour, label=probe)
    ax1.axvspan(2.0, 3.0, color="0.85", label="level 6 -> 3 m")
    ax1.set_xlabel("time (s): settle 0-2 s, drawdown from 2 s")
    ax1.set_ylabel("|u| (m)")
    ax1.grid(alpha=0.3)
    ax1.legend(fontsize=8)
    image = ax2.scatter(x, y, c=u, s=3.0, lw=0, cmap="viridis", rasterized=True)
    ax2.plot(*zip(*SURFACE), "k--", lw=0.8)
    ax2.plot([0, 15], [3, 3], color="C0", lw=0.8, ls=":")
    ax2.set_aspect("equal")
    ax2.set_xlim(0, 15)
    ax2.set_ylim(0, 6.5)
    ax2.set_title(f"t = {times[-1]:.0f} s; dashed: initial surface; dotted: level 3 m",
                  fontsize=9)
    fig.colorbar(image, ax=ax2, label="|u| (m)", shrink=0.8)
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    plt.close(fig)
    print(f"wrote {path}")


def stage_plan(deck):
    """[(name, duration, output interval)] of the deck's stages, in order."""
    with open(deck) as f:
        text = f.read()
    body = text[text.index("  Stages:") + len("  Stages:"):]
    end = re.search(r"^  \w", body, re.M)  # the next top-level section
    body = body[:end.start()] if end else body
    plan = []
    for m in re.finditer(r"^    (\w+):.*?\n(.*?)(?=^    \w+:|^  \w)", body, re.S | re.M):
        duration = float(re.search(r"Duration \(s\): ([0-9.eE+-]+)", m.group(2)).group(1))
        interval = re.search(r"Output Interval \(s\): ([0-9.eE+-]+)", m.group(2))
        plan.append((m.group(1), duration, float(interval.group(1)) if interval else 0.0))
    return plan


def stage_ends(plan, times):
    """End time of every stage: a stage that may stop early (quasi-static, Relaxation) ends at
    the first output after its start; the others run their duration."""
    ends, start = [], 0.0
    for name, duration, _ in plan:
        if name.startswith(("settle", "drained")):
            later = times[times > start + 1e-9]
            end = later[0]
        else:
            end = start + duration
        ends.append(end)
        start = end
    return ends


def face_angle(x, y, low=0.5, high=5.0):
    """Mean inclination (deg) of the slope face between heights low and high: the
    outermost point of every 0.25 m band of height, a line x(y) fitted through them."""
    bands = np.arange(low, high, 0.25)
    xs, ys = [], []
    for b in bands:
        inside = (y >= b) & (y < b + 0.25)
        if inside.any():
            xs.append(x[inside].max())
            ys.append(b + 0.125)
    slope = np.polyfit(ys, xs, 1)[0]  # dx/dy
    return math.degrees(math.atan2(1.0, -slope)) if slope < 0 else float("nan")


# run_variants.sh slow_*: the slow whole test with MC_1, the Hillel and constant HCCs, and
# without mass scaling in the drawdown (also with the liquid's relative velocity kept at the
# fixities); with the occluded air compressing (also with the fixities' relative velocity and
# air-filled cracks)
SLOW_VARIANTS = ("experimental_slope_slow_mc1", "experimental_slope_slow_hillel",
                 "experimental_slope_slow_constant", "experimental_slope_slow_ms1",
                 "experimental_slope_slow_ms1_fixity", "experimental_slope_slow_air",
                 "experimental_slope_slow_air_fixity_cracks",
                 "experimental_slope_slow_ms1_air_fixity")


def report_whole_test(results, name, deck):
    """The whole-test decks: F and the largest displacement at the end of every stage, the
    face angle, the drawdown's run-out; returns what the figure needs."""
    directory = os.path.join(results, name)
    if not os.path.exists(os.path.join(directory, name + "_points.e")):
        return None
    fs = read_csv(os.path.join(directory, name + "_factor_of_safety.csv"))
    times, x0, y0, displacement = point_displacements(
        os.path.join(directory, name + "_points.e"))
    plan = stage_plan(deck)
    try:
        ends = stage_ends(plan, times)
    except IndexError:  # a run still going (or stopped): its outputs miss the last stages
        print(f"\n{name}: outputs end at {times[-1]:.1f} s, before the deck's last stage; "
              "left out")
        return None
    print(f"\n{name}: stage, end time, F (Bishop, critical circle), largest |u| of a point "
          f"since the start, face angle (0.5-5 m high)")
    rows = []
    for (stage, _, _), end in zip(plan, ends):
        k = int(np.argmin(np.abs(times - end)))
        j = int(np.argmin(np.abs(fs["time"] - end)))
        ux, uy = displacement[k]
        u = np.hypot(ux, uy)
        angle = face_angle(x0 + ux, y0 + uy)
        rows.append((stage, times[k], fs["factor_of_safety"][j], u.max(), angle))
        print(f"  {stage:12s} {times[k]:10.1f} s  F {fs['factor_of_safety'][j]:6.3f}  "
              f"|u|max {u.max():7.4f} m  face {angle:5.1f} deg")
    ux, uy = displacement[-1]
    u = np.hypot(ux, uy)
    x, y = x0 + ux, y0 + uy
    start = ends[-2]
    k0 = int(np.argmin(np.abs(times - start)))
    du = np.hypot(ux - displacement[k0][0], uy - displacement[k0][1])
    print(f"  drawdown: largest |u| since its start {du.max():.3f} m; the farthest point at "
          f"y < 0.5 m at x = {x[y < 0.5].max():.2f} m (toe 11.0 m); points that moved > 0.1 m "
          f"in it: {(du > 0.1).sum()} of {len(du)}")
    report_drawdown_pressures_and_probes(directory, name, start)
    return dict(name=name, fs=fs, rows=rows, x=x, y=y, u=u, directory=directory,
                drawdown_start=start, drawdown_largest=du.max(), front=x[y < 0.5].max(),
                mobilised=(du > 0.1).mean())


def report_drawdown_pressures_and_probes(directory, name, start):
    """The drawdown's outputs with p_L outside the physical range (diagnostics column), the
    kinetic energy at its end, and each probe's displacement since its start and peak speed."""
    diagnostics = read_csv(os.path.join(directory, name + "_diagnostics.csv"))
    during = diagnostics["time"] >= start - 1e-6
    outside = diagnostics["unphysical_pressure_points"][during]
    print(f"  drawdown outputs {during.sum()}: {(outside > 0).sum()} with p_L outside the "
          f"physical range, at most {int(outside.max())} points; kinetic energy at the end "
          f"{diagnostics['kinetic_energy_solid'][during][-1]:.2f} J/m")
    for label, (moved, peak, when) in probe_moves(directory, name, start).items():
        print(f"  probe {label:11s} |u| since the drawdown started {moved:.3f} m; peak speed "
              f"{peak:.3f} m/s at {when:.1f} s after")


def probe_moves(directory, name, start):
    """{probe: (|u| from `start` to the last output, peak speed after `start`, its time after
    `start`)} from the probes' CSV files."""
    moves = {}
    for probe in sorted(glob.glob(os.path.join(directory, name + "_probe_*.csv"))):
        p = read_csv(probe)
        k0 = int(np.argmin(np.abs(p["time"] - start)))
        moved = np.hypot(p["displacement_x"] - p["displacement_x"][k0],
                         p["displacement_y"] - p["displacement_y"][k0])
        speed = np.hypot(p["velocity_x"], p["velocity_y"])[k0:]
        j = int(np.argmax(speed))
        label = os.path.basename(probe)[len(name + "_probe_"):-len(".csv")]
        moves[label] = (moved[-1], speed[j], p["time"][k0 + j] - start)
    return moves


def plot_whole_test(runs, path):
    runs = [r for r in runs if r]
    if not runs:
        return
    fig, axes = plt.subplots(len(runs), 3, figsize=(15, 3.6 * len(runs)), squeeze=False,
                             width_ratios=[1, 1, 1.5])
    for row, run in zip(axes, runs):
        fs = run["fs"]
        # up to the drawdown: once the slope moves, a circle's F is no margin
        before = fs["time"] <= run["drawdown_start"] + 1e-9
        row[0].plot(fs["time"][before] / 3600.0, fs["factor_of_safety"][before], "C0.-", ms=2)
        row[0].axhline(1.0, color="k", lw=0.6)
        row[0].set_xlabel("time (h), rise and drained equilibria")
        row[0].set_ylabel("F (Bishop)")
        row[0].set_title(run["name"], fontsize=9)
        row[0].grid(alpha=0.3)
        for probe, colour in (("crest_edge", "C0"), ("mid_slope", "C1"), ("toe", "C2")):
            pr = read_csv(os.path.join(run["directory"], f"{run['name']}_probe_{probe}.csv"))
            if pr:
                after = pr["time"] >= run["drawdown_start"] - 1e-9
                t = pr["time"][after] - run["drawdown_start"]
                ux = pr["displacement_x"][after] - pr["displacement_x"][after][0]
                uy = pr["displacement_y"][after] - pr["displacement_y"][after][0]
                row[1].plot(t, np.hypot(ux, uy), color=colour, label=probe)
        row[1].axvspan(0.0, 1.0, color="0.85", label="level 6 -> 3 m")
        row[1].set_xlabel("time since the drawdown started (s)")
        row[1].set_ylabel("|u| in the drawdown (m)")
        row[1].grid(alpha=0.3)
        row[1].legend(fontsize=8)
        image = row[2].scatter(run["x"], run["y"], c=run["u"], s=2.0, lw=0, cmap="viridis",
                               rasterized=True)
        row[2].plot(*zip(*SURFACE), "k--", lw=0.8)
        row[2].set_aspect("equal")
        row[2].set_xlim(0, 15)
        row[2].set_ylim(0, 6.5)
        row[2].set_title("end of the drawdown, |u| since the start; dashed: initial surface",
                         fontsize=9)
        fig.colorbar(image, ax=row[2], label="|u| (m)", shrink=0.8)
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    plt.close(fig)
    print(f"wrote {path}")


MESH_STUDY_NAME = "experimental_slope_slow_h"  # scripts/convergence.sh's run names


def wall_seconds(log):
    """The wall time of a run from the last line of its log ("... simulated in X s wall")."""
    with open(log, errors="replace") as f:
        found = re.findall(r"simulated in ([0-9.eE+-]+) s wall", f.read())
    return float(found[-1]) if found else math.nan


def rise_pressure_samples():
    """Where the rise's p_L of two meshes is compared: three verticals (x = 3, 6, 8 m, 0.1 m
    inside the soil at both ends) and the face 0.1-1 m deep (its inward normal, from 30 to
    95 % of its length from the crest)."""
    samples, kinds = [], []
    for x in (3.0, 6.0, 8.0):
        top = 6.0 if x <= 5.0 else 11.0 - x
        for y in np.linspace(0.1, top - 0.1, 40):
            samples.append((x, y))
            kinds.append("verticals")
    for s in np.linspace(0.3, 0.95, 30):
        for d in np.linspace(0.1, 1.0, 10):
            samples.append((5.0 + 6.0 * s - d / math.sqrt(2), 6.0 - 6.0 * s - d / math.sqrt(2)))
            kinds.append("face")
    return np.array(samples), np.array(kinds)


def rise_pressures(run, samples, levels=(2.0, 3.0, 4.0)):
    """{level: p_L at the samples at the end of its rise stage}, the run's points
    interpolated linearly (SciPy, Delaunay of the points' current positions)."""
    from scipy.interpolate import LinearNDInterpolator
    ends = {float(stage[len("rise_"):].replace("_", ".")): end
            for stage, end, *_ in run["rows"] if stage.startswith("rise_")}
    pressures = {}
    for level in levels:
        x, y, p, _ = points_at(run["directory"], run["name"], ends[level])
        pressures[level] = LinearNDInterpolator(np.c_[x, y], p)(samples)
    return pressures


def compare_rise_pressures(runs, sizes):
    """The finest mesh's p_L at the ends of the 2 / 3 / 4 m rises against each coarser one's."""
    samples, kinds = rise_pressure_samples()
    finest = rise_pressures(runs[sizes[-1]], samples)
    for h in sizes[:-1]:
        other = rise_pressures(runs[h], samples)
        for kind in ("verticals", "face"):
            spread = []
            for level in finest:
                d = np.abs(finest[level] - other[level])[kinds == kind]
                spread.append(f"{np.nanmax(d) / 1e3:.2f}")
            print(f"  rise p_L, {sizes[-1]:g} m against {h:g} m, {kind:9s}: largest difference "
                  f"at the ends of the 2 / 3 / 4 m rises {' / '.join(spread)} kPa "
                  f"({int(np.isfinite(d).sum())} samples)")


def mesh_study(results, path):
    """The slow whole test's drawdown on the meshes of scripts/convergence.sh (results/
    convergence/experimental_slope_slow_h<h>/): each quantity per element size, its change
    to the next finer mesh, with three meshes the observed order p = log2(change ratio) and
    Richardson's estimate of the mesh-converged value; a chart of each run's distance to that
    estimate against its wall time."""
    deck = os.path.join(HERE, "experimental_slope_slow.yaml")
    runs = {}
    for directory in glob.glob(os.path.join(results, MESH_STUDY_NAME + "*")):
        name = os.path.basename(directory)
        h = float(name[len(MESH_STUDY_NAME):])
        run = report_whole_test(results, name, deck)
        if run:
            run["probes"] = probe_moves(directory, name, run["drawdown_start"])
            run["wall"] = wall_seconds(os.path.join(directory, name + ".log"))
            runs[h] = run
    if not runs:
        return
    sizes = sorted(runs, reverse=True)
    measures = [
        ("largest |u| in the drawdown (m)", lambda r: r["drawdown_largest"]),
        ("crest edge probe (m)", lambda r: r["probes"]["crest_edge"][0]),
        ("mid-slope probe (m)", lambda r: r["probes"]["mid_slope"][0]),
        ("toe probe (m)", lambda r: r["probes"]["toe"][0]),
        ("front: farthest x at y < 0.5 m (m)", lambda r: r["front"]),
        ("share of points moved > 0.1 m", lambda r: r["mobilised"]),
    ]
    print("\nmesh study of the slow whole test's drawdown: h (m) " +
          " / ".join(f"{h:g}" for h in sizes) + "; wall (s) " +
          " / ".join(f"{runs[h]['wall']:.0f}" for h in sizes))
    if len(sizes) > 1:
        compare_rise_pressures(runs, sizes)
    estimates = {}
    for label, measure in measures:
        values = [measure(runs[h]) for h in sizes]
        line = f"  {label:36s} " + " / ".join(f"{v:.3f}" for v in values)
        changes = np.diff(values)
        if len(changes):
            line += "; changes " + " / ".join(f"{c:+.3f}" for c in changes)
        # the three finest, each half the size of the one before
        if len(values) >= 3 and all(abs(sizes[i] / sizes[i + 1] - 2) < 1e-9
                                    for i in range(len(sizes) - 3, len(sizes) - 1)):
            coarse, finer = changes[-2], changes[-1]
            if coarse * finer > 0 and abs(finer) < abs(coarse):
                order = math.log2(coarse / finer)
                estimate = values[-1] + finer / (2 ** order - 1)
                estimates[label] = estimate
                line += f"; order {order:.2f}, estimate {estimate:.3f}"
            else:
                line += "; changes not shrinking: no order"
        print(line)
    if not estimates:
        return
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for (label, measure), marker in zip(measures, "osD^v<"):
        if label not in estimates or "share" in label:
            continue
        error = [abs(measure(runs[h]) - estimates[label]) for h in sizes]
        ax.loglog([runs[h]["wall"] for h in sizes], error, marker + "-", label=label)
    for h in sizes:
        ax.annotate(f"{h:g} m", (runs[h]["wall"], abs(runs[h]["drawdown_largest"] -
                    estimates[measures[0][0]])), textcoords="offset points", xytext=(4, 4),
                    fontsize=8)
    ax.set_xlabel("wall time of the whole run (s)")
    ax.set_ylabel("|value - Richardson estimate| (m)")
    ax.set_title("slow whole test, drawdown: accuracy against wall time", fontsize=10)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print(f"wrote {path}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", default=os.path.join(ROOT, "results"))
    parser.add_argument("--mesh-study", action="store_true",
                        help="only the slow whole test on the meshes of scripts/convergence.sh "
                        "(DIR/convergence/experimental_slope_slow_h<h>/)")
    args = parser.parse_args()
    if args.mesh_study:
        mesh_study(os.path.join(args.results, "convergence"),
                   os.path.join(HERE, "experimental_slope_mesh_study.png"))
        return
    runs = load(args.results)
    whole = [report_whole_test(args.results, name, os.path.join(HERE, name + ".yaml"))
             for name in ("experimental_slope", "experimental_slope_slow")]
    if not runs and not any(whole):
        raise SystemExit(f"no runs of the experimental slope under {args.results}")
    for r in runs:
        report(r)
    if runs:
        plot_factor(runs, os.path.join(HERE, "experimental_slope_factor_of_safety.png"))
        plot_circles(runs, os.path.join(HERE, "experimental_slope_critical_circle.png"))
    plot_drawdown(args.results, os.path.join(HERE, "experimental_slope_drawdown.png"))
    plot_whole_test(whole, os.path.join(HERE, "experimental_slope_whole_test.png"))
    # run_variants.sh's variants of the slow whole test, each with its own deck beside it
    variants_dir = os.path.join(args.results, "experimental_slope_variants")
    variants = [report_whole_test(variants_dir, name, os.path.join(variants_dir, name + ".yaml"))
                for name in SLOW_VARIANTS]
    if any(variants):
        plot_whole_test([whole[1]] + variants,
                        os.path.join(HERE, "experimental_slope_whole_test_variants.png"))


if __name__ == "__main__":
    main()

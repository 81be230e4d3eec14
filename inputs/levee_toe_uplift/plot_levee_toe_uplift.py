#!/usr/bin/env python3
"""Figures and numbers of inputs/levee_toe_uplift/README.md from a run of a deck of this folder:

  /usr/bin/python3 inputs/levee_toe_uplift/plot_levee_toe_uplift.py [--results DIR] [--name NAME]
                   [--figures DIR] [--threshold KPA] [--handover MIN] [--after MIN ...]

Reads <NAME>_section_s1.csv (every material point within 0.5 m of the sand/clay interface
S1 at every output), the probes, the diagnostics, the factor-of-safety CSV and, for the
map, <NAME>_points.e (needs SciPy). Times are event times: minutes from the end of the
'settle' stage (the thesis' t = 0 after its initialisation); each 'drained' stage adds its
few seconds of relaxation to them.

Writes
  <NAME>_interface.png  p_L and total vertical stress along S1 at the phase ends (the thesis'
                        Fig. 5.33), from the points of the clay's first row above S1;
  <NAME>_uplift.png     uplift length against time: the length of 1 m bins in 11 < x < 50 m
                        whose clay points at S1 carry a vertical effective stress below the
                        threshold (default 5 kPa), and the factor of safety (Bishop);
  <NAME>_history.png    displacement histories of the crest, interface and toe probes;
  <NAME>_map.png        deviatoric strain and displacement at the last output.
and prints the numbers of the README's tables.

The vertical effective stress: at an output of an explicit or quasi-static stage it is the
point's own -sigma'_yy. On the implicit seepage path the skeleton is fixed, so its
sigma'_yy is the last equilibrium's; there the script takes the total vertical stress of the
point at the last equilibrium (sigma_v = -(sigma'_yy - S_L p_L), Bishop's chi = S_L) and
subtracts the current S_L p_L.
"""
import argparse
import csv
import os
from collections import defaultdict

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
SURFACE = [(0, 0), (11, 0), (20, 6), (24, 6), (33, 0), (50, 0)]
LAYERS = [(0, -3.6, 50, -3.6)]
PHASE_ENDS_MIN = [8, 53, 169, 351, 553]  # Table 5.6, cumulative
OVERBURDEN_KPA = 73.44  # thesis: 3.6 m of clay outside the levee's footprint
HANDOVER_MIN = 169.0  # the end of Phase 3: the main deck's hand-over (--handover)


def read_csv(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return rows


def columns(rows):
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]} if rows else {}


def load_section(results, name):
    rows = read_csv(os.path.join(results, f"{name}_section_s1.csv"))
    by_time = defaultdict(list)
    for r in rows:
        by_time[float(r["time"])].append(r)
    return by_time


def settle_end(results, name):
    """Event time origin: the output that ends 'settle' is the first with t > 0."""
    diag = columns(read_csv(os.path.join(results, f"{name}_diagnostics.csv")))
    return float(diag["time"][1]), diag


def effective_series(by_time):
    """Per output time: arrays x, y, p, S, sigma'_v (kPa, compression positive) of the band
    points, with sigma'_v on implicit outputs from the last equilibrium's total stress."""
    out = {}
    ref_total = {}  # point id -> total vertical stress (Pa) at the last equilibrium
    last_syy = {}
    for t in sorted(by_time):
        rows = by_time[t]
        ids = [int(r["id"]) for r in rows]
        x = np.array([float(r["x"]) for r in rows])
        y = np.array([float(r["y"]) for r in rows])
        p = np.array([float(r["liquid_pressure"]) for r in rows])
        s = np.array([float(r["saturation"]) for r in rows])
        syy = np.array([float(r["stress_yy"]) for r in rows])
        frozen = all(last_syy.get(i) == v for i, v in zip(ids, syy)) and len(last_syy) > 0
        sv_eff = np.empty_like(p)
        for k, i in enumerate(ids):
            if frozen and i in ref_total:
                sv_eff[k] = ref_total[i] - s[k] * p[k]
            else:
                sv_eff[k] = -syy[k]
                ref_total[i] = -(syy[k] - s[k] * p[k])
        for i, v in zip(ids, syy):
            last_syy[i] = v
        total = sv_eff + s * p
        out[t] = dict(x=x, y=y, p=p, s=s, sv_eff=sv_eff, sv=total, frozen=frozen, id=ids)
    return out


def uplift_length(frame, threshold_pa, x_range=(11.0, 50.0), clay=True):
    sel = (frame["x"] > x_range[0]) & (frame["x"] < x_range[1])
    sel &= (frame["y"] > -3.6) if clay else (frame["y"] < -3.6)
    edges = np.arange(x_range[0], x_range[1] + 1e-9, 1.0)
    length, where = 0.0, []
    for a, b in zip(edges[:-1], edges[1:]):
        inside = sel & (frame["x"] >= a) & (frame["x"] < b)
        if inside.any() and frame["sv_eff"][inside].mean() < threshold_pa:
            length += b - a
            where.append(0.5 * (a + b))
    return length, where


def nearest_frame(frames, t):
    times = np.array(sorted(frames))
    return times[np.argmin(np.abs(times - t))]


def plot_interface(frames, t0, path, name):
    """The equilibrium at the end of Phases 1-3 (the drained stage's output: the last one
    within 25 s after the phase's end, the drained stages adding a few seconds each), the
    explicit stage 1 min after the Phase 4 step (170 min, the thesis' Fig. 5.38 instant)
    and the last output."""
    times = np.array(sorted(frames))
    shown = []
    for m in [p for p in PHASE_ENDS_MIN if p <= HANDOVER_MIN]:
        cands = times[times <= t0 + 60 * m + 25]
        if len(cands) and cands[-1] not in shown:
            shown.append(cands[-1])
    for t in (times[np.argmin(np.abs(times - (t0 + 60 * (HANDOVER_MIN + 1))))], times[-1]):
        if t not in shown and t > shown[-1]:
            shown.append(t)
    fig, axes = plt.subplots(len(shown), 1, figsize=(9, 2.3 * len(shown)), sharex=True)
    for ax, t in zip(np.atleast_1d(axes), shown):
        f = frames[t]
        c = f["y"] > -3.6
        order = np.argsort(f["x"][c])
        ax.plot(f["x"][c][order], f["p"][c][order] / 1e3, ".-", ms=3, lw=0.8, label="p_L")
        ax.plot(f["x"][c][order], f["sv"][c][order] / 1e3, ".-", ms=3, lw=0.8,
                label="total vertical stress")
        ax.axhline(OVERBURDEN_KPA, color="r", lw=0.8, label="73.44 kPa (3.6 m of clay)")
        ax.set_ylabel("kPa")
        ax.set_title(f"t = {(t - t0) / 60:.1f} min", fontsize=9)
        ax.set_ylim(0, 220)
        ax.grid(alpha=0.3)
    np.atleast_1d(axes)[0].legend(fontsize=7, ncol=3)
    np.atleast_1d(axes)[-1].set_xlabel("x (m); clay points of the first row above S1 (y = -3.6 m)")
    fig.suptitle(f"{name}: pore pressure and total vertical stress along S1", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def plot_uplift(frames, t0, fos, threshold, path, name):
    times = np.array(sorted(frames))
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(8, 5.5), sharex=True)
    for thr, style in ((threshold, "k.-"), (2e3, "C0:"), (10e3, "C1:")):
        lengths = [uplift_length(frames[t], thr)[0] for t in times]
        ax1.plot((times - t0) / 60, lengths, style, ms=3,
                 label=f"|sigma'_v| < {thr / 1e3:g} kPa")
    ax1.axhline(7.2, color="g", lw=0.8, ls="--", label="experiment 7.2 m")
    ax1.plot([180], [7.6], "r*", label="thesis 7.6 m at 180 min")
    ax1.set_ylabel("uplift length (m)")
    ax1.legend(fontsize=7)
    ax1.grid(alpha=0.3)
    if fos:
        ax2.plot((fos["time"] - t0) / 60, fos["factor_of_safety"], "k.-", ms=3)
    ax2.axhline(1.0, color="r", lw=0.8)
    ax2.set_ylabel("F (Bishop, landside)")
    ax2.set_xlabel("time (min) after the initialisation")
    for ax in (ax1, ax2):
        for m in PHASE_ENDS_MIN:
            if m < (times[-1] - t0) / 60 + 10:
                ax.axvline(m, color="0.7", lw=0.6)
    ax2.grid(alpha=0.3)
    ax2.set_xlim(-5, (times[-1] - t0) / 60 + 10)
    fig.suptitle(f"{name}: uplift length in 11 < x < 50 m and factor of safety", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def plot_history(results, name, t0, path):
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 3.8))
    for probe, colour in (("crest", "C0"), ("interface_clay", "C1"), ("toe", "C2")):
        p = os.path.join(results, f"{name}_probe_{probe}.csv")
        if not os.path.exists(p):
            continue
        pr = columns(read_csv(p))
        tm = (pr["time"] - t0) / 60
        for ax in (ax1, ax2):
            ax.plot(tm, pr["displacement_x"], color=colour, label=f"{probe} u_x")
            ax.plot(tm, pr["displacement_y"], color=colour, ls="--", label=f"{probe} u_y")
    ax1.set_xlabel("time (min)")
    ax1.set_ylabel("displacement (m)")
    ax1.legend(fontsize=7)
    ax1.grid(alpha=0.3)
    start = HANDOVER_MIN
    last = max(ax1.get_lines()[0].get_xdata()) if ax1.get_lines() else start + 10
    ax2.set_xlim(start - 0.5, max(last, start + 1) + 0.5)
    ax2.set_xlabel("time (min), explicit stage")
    ax2.grid(alpha=0.3)
    fig.suptitle(f"{name}: crest (22, 5.8), interface (27, -3.4) and toe (34, -0.2)",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def read_points(results, name):
    try:
        from scipy.io import netcdf_file
    except ImportError:
        print("no SciPy: map skipped (apt-get install python3-scipy)")
        return None
    path = os.path.join(results, f"{name}_points.e")
    if not os.path.exists(path):
        return None
    with netcdf_file(path, "r", mmap=False) as f:
        names = ["".join(c.decode() for c in row).strip("\x00 ")
                 for row in f.variables["name_nod_var"][:]]
        var = {n: k + 1 for k, n in enumerate(names)}
        times = f.variables["time_whole"][:].copy()
        x0, y0 = f.variables["coordx"][:].copy(), f.variables["coordy"][:].copy()
        get = {n: f.variables["vals_nod_var%d" % var[n]][-1].copy()
               for n in ("displ_x", "displ_y", "deviatoric_strain", "stress_eff_yy",
                         "pressure_liquid")}
        # the displacement at the hand-over: the last output before the explicit stage
        # (within 25 s after the end of Phase 3, as in plot_interface)
        k = int(np.searchsorted(times, times[0] + 1e-9))  # skip t = 0
        t0 = times[1] if len(times) > 1 else times[0]
        k = int(np.where(times <= t0 + 60 * HANDOVER_MIN + 25)[0][-1])
        first = {n: f.variables["vals_nod_var%d" % var[n]][k].copy()
                 for n in ("displ_x", "displ_y")}
        first["time"] = times[k]
    return times, x0, y0, get, first


def plot_map(points, t0, path, name):
    times, x0, y0, v, first = points
    ux, uy = v["displ_x"], v["displ_y"]
    x, y = x0 + ux, y0 + uy
    u = np.hypot(ux, uy)
    dux, duy = ux - first["displ_x"], uy - first["displ_y"]
    fig, (ax1, ax2, ax3) = plt.subplots(3, 1, figsize=(11, 9.5), sharex=True)
    im1 = ax1.scatter(x, y, c=v["deviatoric_strain"], s=7, lw=0, cmap="magma_r",
                      vmin=0, vmax=max(0.02, np.percentile(v["deviatoric_strain"], 99)))
    im2 = ax2.scatter(x, y, c=100 * u, s=7, lw=0, cmap="viridis")
    im3 = ax3.scatter(x, y, c=100 * np.hypot(dux, duy), s=7, lw=0, cmap="viridis")
    sub = np.arange(0, len(x), 5)
    ax3.quiver(x[sub], y[sub], dux[sub], duy[sub], color="k", width=0.0012)
    fig.colorbar(im3, ax=ax3, label=f"|u - u({HANDOVER_MIN:g} min)| (cm)", shrink=0.8)
    ax3.set_title(f"displacement since the hand-over to the explicit stage "
                  f"(t = {(first['time'] - t0) / 60:.1f} min)", fontsize=9)
    for ax in (ax1, ax2, ax3):
        ax.plot(*zip(*SURFACE), "k--", lw=0.6)
        ax.plot([0, 50], [-3.6, -3.6], "k:", lw=0.6)
        ax.set_aspect("equal")
        ax.set_ylim(-6.2, 6.8)
        ax.set_ylabel("y (m)")
    # displacement vectors of a subset
    fig.colorbar(im1, ax=ax1, label="deviatoric strain", shrink=0.8)
    fig.colorbar(im2, ax=ax2, label="|u| (cm)", shrink=0.8)
    ax1.set_title(f"t = {(times[-1] - t0) / 60:.1f} min; dashed: initial surface, "
                  f"dotted: S1", fontsize=9)
    ax3.set_xlabel("x (m)")
    fig.tight_layout()
    fig.savefig(path, dpi=65)
    plt.close(fig)


def report(results, name, frames, t0, diag, fos, points, threshold):
    times = np.array(sorted(frames))
    print(f"{name}: event time origin (end of settle) t0 = {t0:.3f} s")
    print("uplift length (m) in 11 < x < 50 m, clay points at S1, |sigma'_v| < "
          f"{threshold / 1e3:g} / 2 / 10 kPa, and where:")
    for m in (8, 53, 120, 169, 170, 172, 175, 180, 351, 352, 355, 361):
        t = t0 + 60 * m
        if t > times[-1] + 1:
            continue
        k = times[np.argmin(np.abs(times - t))]
        f = frames[k]
        L, where = uplift_length(f, threshold)
        L2, _ = uplift_length(f, 2e3)
        L10, _ = uplift_length(f, 10e3)
        xs = f"{min(where):.1f}..{max(where):.1f}" if where else "-"
        print(f"  t = {(k - t0) / 60:7.2f} min: {L:5.1f} / {L2:5.1f} / {L10:5.1f} m; "
              f"bins at x = {xs}")
    k = times[-1]
    L, where = uplift_length(frames[k], threshold)
    xs = f"{min(where):.1f}..{max(where):.1f}" if where else "-"
    print(f"  last output t = {(k - t0) / 60:.2f} min: {L:.1f} m; bins at x = {xs}")
    if fos:
        print("factor of safety (Bishop, landside) at the phase ends / last output:")
        for m in PHASE_ENDS_MIN + [1e9]:
            sel = fos["time"] <= t0 + 60 * m + 30
            if sel.any():
                j = np.where(sel)[0][-1]
                print(f"  t = {(fos['time'][j] - t0) / 60:7.2f} min: F = "
                      f"{fos['factor_of_safety'][j]:.3f}")
        j = int(np.argmin(fos["factor_of_safety"]))
        below = np.where(fos["factor_of_safety"] < 1.0)[0]
        print(f"  lowest F {fos['factor_of_safety'][j]:.3f} at {(fos['time'][j] - t0) / 60:.2f}"
              f" min; first below 1: "
              + (f"{(fos['time'][below[0]] - t0) / 60:.2f} min" if len(below) else "never"))
    ke = diag["kinetic_energy_solid"] + diag["kinetic_energy_liquid"]
    j = int(np.argmax(ke))
    print(f"kinetic energy: largest {ke[j]:.3g} J/m at {(diag['time'][j] - t0) / 60:.2f} min")
    late = diag["time"] > t0 + 60 * HANDOVER_MIN + 25
    if late.any():
        tl, kl = diag["time"][late], ke[late]
        j = int(np.argmax(kl))
        print(f"  after the hand-over: largest {kl[j]:.3g} J/m at {(tl[j] - t0) / 60:.2f} min; "
              + ", ".join(f"{(tl[i] - t0) / 60:.1f} min {kl[i]:.2g}"
                          for i in np.linspace(0, len(tl) - 1, 6).astype(int)))
    for probe in ("crest", "interface_clay", "toe"):
        p = os.path.join(results, f"{name}_probe_{probe}.csv")
        if os.path.exists(p):
            pr = columns(read_csv(p))
            for m in (HANDOVER_MIN, 1e9):
                sel = pr["time"] <= t0 + 60 * m + 30
                j = np.where(sel)[0][-1]
                print(f"  {probe:15s} t = {(pr['time'][j] - t0) / 60:7.2f} min: u = "
                      f"({100 * pr['displacement_x'][j]:+.1f}, "
                      f"{100 * pr['displacement_y'][j]:+.1f}) cm")
    p = os.path.join(results, f"{name}_probe_toe.csv")
    if os.path.exists(p):
        pr = columns(read_csv(p))
        late = pr["time"] > t0 + 60 * HANDOVER_MIN + 25
        if late.any():
            sp = np.hypot(pr["velocity_x"], pr["velocity_y"])[late]
            tl = pr["time"][late]
            print("  toe speed after the hand-over (mm/min): " + ", ".join(
                f"{(tl[i] - t0) / 60:.1f} min {6e4 * sp[i]:.2f}"
                for i in np.linspace(0, len(tl) - 1, 6).astype(int)))
    if points is not None:
        times_p, x0, y0, v, first = points
        du = np.hypot(v["displ_x"] - first["displ_x"], v["displ_y"] - first["displ_y"])
        j = int(np.argmax(du))
        print(f"points: largest displacement since the hand-over ({(first['time'] - t0) / 60:.2f}"
              f" min) {100 * du[j]:.1f} cm at ({x0[j]:.1f}, {y0[j]:.1f})")
        u = np.hypot(v["displ_x"], v["displ_y"])
        j = int(np.argmax(u))
        print(f"points at {(times_p[-1] - t0) / 60:.2f} min: largest |u| {100 * u[j]:.1f} cm "
              f"at ({x0[j]:.1f}, {y0[j]:.1f}); median {100 * np.median(u):.2f} cm")
        crest = (x0 > 20) & (x0 < 24) & (y0 > 5.3)
        print(f"  crest (20 < x0 < 24, y0 > 5.3): u_y from {100 * v['displ_y'][crest].min():.1f}"
              f" to {100 * v['displ_y'][crest].max():.1f} cm")
        toe = (x0 > 33) & (x0 < 40) & (y0 > -0.5)
        print(f"  landside ground 33 < x0 < 40: u_y up to {100 * v['displ_y'][toe].max():.1f} cm,"
              f" u_x up to {100 * v['displ_x'][toe].max():.1f} cm")
        strained = v["deviatoric_strain"] > 0.01
        if strained.any():
            print(f"  points with deviatoric strain > 1 %: {strained.sum()}, x0 "
                  f"{x0[strained].min():.1f}..{x0[strained].max():.1f}, y0 "
                  f"{y0[strained].min():.1f}..{y0[strained].max():.1f}")


def handover_table(results, name, t0, diag, fos, minutes):
    """The probes, the toe's speed, F and the kinetic energy at `minutes` after the hand-over
    (the README's Phase 5 table): displacements since the hand-over, speeds from the probes'
    velocities and from their displacement over the last 1.5 min."""
    h = t0 + 60 * HANDOVER_MIN
    probes = {}
    for probe in ("crest", "toe"):
        path = os.path.join(results, f"{name}_probe_{probe}.csv")
        if not os.path.exists(path):
            return
        probes[probe] = columns(read_csv(path))
    ke = diag["kinetic_energy_solid"] + diag["kinetic_energy_liquid"]

    def at(series, t):
        return int(np.argmin(np.abs(series["time"] - t)))

    print(f"after the hand-over ({HANDOVER_MIN:g} min): minutes | crest landwards / settlement "
          "(cm) | toe out / up (cm) | toe speed (mm/min) | crest / toe speed over 1.5 min "
          "(mm/min) | F | kinetic energy (J/m)")
    for m in minutes:
        t = h + 60 * m
        if t > probes["crest"]["time"][-1] + 30:
            break
        row = []
        speeds = []
        for probe in ("crest", "toe"):
            pr = probes[probe]
            j, j0, jb = at(pr, t), at(pr, h), at(pr, t - 90)
            dx = pr["displacement_x"][j] - pr["displacement_x"][j0]
            dy = pr["displacement_y"][j] - pr["displacement_y"][j0]
            row.append(f"{100 * dx:.1f} / {100 * (-dy if probe == 'crest' else dy):.1f}")
            dt = pr["time"][j] - pr["time"][jb]
            du = np.hypot(pr["displacement_x"][j] - pr["displacement_x"][jb],
                          pr["displacement_y"][j] - pr["displacement_y"][jb])
            speeds.append(f"{6e4 * du / dt:.1f}" if dt > 0 else "-")
        toe = probes["toe"]
        j = at(toe, t)
        v = 6e4 * np.hypot(toe["velocity_x"][j], toe["velocity_y"][j])
        F = "-"
        if fos:
            sel = fos["time"] <= t + 1e-6
            if sel.any():
                F = f"{fos['factor_of_safety'][np.where(sel)[0][-1]]:.3f}"
        k = int(np.argmin(np.abs(diag["time"] - t)))
        print(f"  {(toe['time'][j] - h) / 60:6.1f} | {row[0]} | {row[1]} | {v:.1f} | "
              f"{speeds[0]} / {speeds[1]} | {F} | {ke[k]:.3g}")


def points_at(results, name, t):
    """Positions, displacement, deviatoric strain and p_L of the points at the output nearest t,
    and the displacement at the end of Phase 3."""
    from scipy.io import netcdf_file
    with netcdf_file(os.path.join(results, f"{name}_points.e"), "r", mmap=False) as f:
        names = ["".join(c.decode() for c in row).strip("\x00 ")
                 for row in f.variables["name_nod_var"][:]]
        var = {n: k + 1 for k, n in enumerate(names)}
        times = f.variables["time_whole"][:].copy()
        k = int(np.argmin(np.abs(times - t)))
        t0 = times[1]
        h = int(np.where(times <= t0 + 60 * HANDOVER_MIN + 25)[0][-1])
        get = lambda n, j: f.variables["vals_nod_var%d" % var[n]][j].copy()  # noqa: E731
        out = dict(time=times[k], x0=f.variables["coordx"][:].copy(),
                   y0=f.variables["coordy"][:].copy(), ux=get("displ_x", k),
                   uy=get("displ_y", k), dx=get("displ_x", k) - get("displ_x", h),
                   dy=get("displ_y", k) - get("displ_y", h),
                   eps=get("deviatoric_strain", k), p=get("pressure_liquid", k))
    return out


def compare_variants(runs, path, minute=170.0):
    """The permeability-ratio table at `minute` (thesis Fig. 5.38: 170 min) and a figure of the
    deviatoric strain and p_L of each run then. runs: (label, results, name)."""
    print(f"\nvariants at {minute:g} min: label | uplift (5 / 10 kPa) | F | points with "
          f"deviatoric strain > 1 % (x0 range) | largest |u - u(169 min)| | mean p_L of the "
          f"levee above y = 2 m")
    fig, axes = plt.subplots(len(runs), 2, figsize=(13, 2.6 * len(runs)), squeeze=False)
    for row, (label, results, name) in enumerate(runs):
        t0, _ = settle_end(results, name)
        frames = effective_series(load_section(results, name))
        times = np.array(sorted(frames))
        t = times[np.argmin(np.abs(times - (t0 + 60 * minute)))]
        L5, _ = uplift_length(frames[t], 5e3)
        L10, _ = uplift_length(frames[t], 10e3)
        fos = columns(read_csv(os.path.join(results, f"{name}_factor_of_safety.csv")))
        F = fos["factor_of_safety"][np.argmin(np.abs(fos["time"] - t))]
        pts = points_at(results, name, t)
        strained = pts["eps"] > 0.01
        du = np.hypot(pts["dx"], pts["dy"])
        j = int(np.argmax(du))
        levee = (pts["y0"] > 2.0)
        print(f"  {label:10s} t = {(pts['time'] - t0) / 60:.2f} min | {L5:.0f} / {L10:.0f} m | "
              f"{F:.3f} | {strained.sum()} ("
              + (f"{pts['x0'][strained].min():.1f}..{pts['x0'][strained].max():.1f}"
                 if strained.any() else "-")
              + f") | {100 * du[j]:.1f} cm at "
              f"({pts['x0'][j]:.1f}, {pts['y0'][j]:.1f}) | "
              f"{pts['p'][levee].mean() / 1e3:.1f} kPa")
        x, y = pts["x0"] + pts["ux"], pts["y0"] + pts["uy"]
        a, b = axes[row]
        im = a.scatter(x, y, c=pts["eps"], s=4, lw=0, cmap="magma_r", vmin=0, vmax=0.03)
        fig.colorbar(im, ax=a, shrink=0.8, label="dev. strain")
        im = b.scatter(x, y, c=pts["p"] / 1e3, s=4, lw=0, cmap="RdBu_r", vmin=-100, vmax=100)
        fig.colorbar(im, ax=b, shrink=0.8, label="p_L (kPa)")
        for ax in (a, b):
            ax.set_aspect("equal")
            ax.set_ylim(-6.2, 6.8)
            ax.set_title(f"{label}, t = {(pts['time'] - t0) / 60:.1f} min", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=65)
    plt.close(fig)


def main():
    global HANDOVER_MIN
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--name", default="levee_toe_uplift")
    parser.add_argument("--results")
    parser.add_argument("--figures", default=HERE)
    parser.add_argument("--threshold", type=float, default=5.0, help="kPa")
    parser.add_argument("--handover", type=float, default=HANDOVER_MIN,
                        help="minute of the hand-over to the explicit stage, event time "
                        "(351.45 for _phase5)")
    parser.add_argument("--after", type=float, nargs="*",
                        default=[10, 20, 30, 40, 60, 90, 120, 150, 180, 202],
                        help="minutes after the hand-over for the probe table")
    parser.add_argument("--variants", action="store_true",
                        help="the permeability-ratio table and figure (run_variants.sh first)")
    args = parser.parse_args()
    HANDOVER_MIN = args.handover
    os.makedirs(args.figures, exist_ok=True)
    if args.variants:
        v = os.path.join(ROOT, "results", "levee_toe_uplift_variants")
        runs = [("1e-1", os.path.join(v, "levee_toe_uplift_ratio1e-1"),
                 "levee_toe_uplift_ratio1e-1"),
                ("1e-2", os.path.join(ROOT, "results", "levee_toe_uplift"), "levee_toe_uplift"),
                ("1e-3", os.path.join(v, "levee_toe_uplift_ratio1e-3"),
                 "levee_toe_uplift_ratio1e-3")]
        runs = [r for r in runs if os.path.exists(os.path.join(r[1], r[2] + "_points.e"))]
        compare_variants(runs, os.path.join(args.figures, "levee_toe_uplift_ratios.png"))
        return
    name = args.name
    results = args.results or os.path.join(ROOT, "results", name)
    threshold = 1e3 * args.threshold
    t0, diag = settle_end(results, name)
    frames = effective_series(load_section(results, name))
    fos_path = os.path.join(results, f"{name}_factor_of_safety.csv")
    fos = columns(read_csv(fos_path)) if os.path.exists(fos_path) else None
    points = read_points(results, name)
    report(results, name, frames, t0, diag, fos, points, threshold)
    handover_table(results, name, t0, diag, fos, args.after)
    plot_interface(frames, t0, os.path.join(args.figures, f"{name}_interface.png"), name)
    plot_uplift(frames, t0, fos, threshold, os.path.join(args.figures, f"{name}_uplift.png"),
                name)
    plot_history(results, name, t0, os.path.join(args.figures, f"{name}_history.png"))
    if points is not None:
        plot_map(points, t0, os.path.join(args.figures, f"{name}_map.png"), name)
    print(f"figures in {args.figures}")


if __name__ == "__main__":
    main()

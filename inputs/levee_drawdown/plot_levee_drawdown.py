#!/usr/bin/python3
"""Figures and key numbers of the levee failure scenes (drawdown and rainfall).

  plot_levee_drawdown.py [--name NAME] [--results DIR] [--figures DIR] [--times T ...]

NAME is the deck's Output Name: levee_drawdown (default), levee_drawdown_constant, or
levee_rainfall (plot_levee_rainfall.py calls this script with that name). Reads from
--results (default: results/NAME of the repository, where scripts/run.sh writes):
  NAME_probe_MP*.csv   the probed material points (crest, mid-slope, toe)
  NAME_diagnostics.csv kinetic energy at every output
  NAME_points.e        material points (Exodus II = netCDF-3, read with SciPy), for the map
Writes into --figures (default: the folder of the deck):
  NAME_history.png     displacement, liquid pressure and deviatoric strain of the probes,
                       kinetic energy
  NAME_map.png         the points coloured by their displacement at three output times
and prints the numbers quoted in the README: the probes' displacement at --times, the
failure time and when the motion stops.
"""
import argparse
import csv
import glob
import os
import sys

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
FOLDER = {"levee_drawdown": HERE, "levee_drawdown_constant": HERE,
          "levee_rainfall": os.path.join(ROOT, "inputs", "levee_rainfall")}
# Reporting times, counted like the thesis' from the start of the event (the drawdown or the
# rain): t_event = t - EVENT_START.
TIMES = {"levee_drawdown": (3.0, 6.0, 10.0, 20.0),
         "levee_drawdown_constant": (3.0, 6.0, 10.0, 20.0, 60.0),
         "levee_rainfall": (2.0, 5.0, 10.0, 20.0)}
# Simulation time t at which the event starts: after `settle` (1 s) for the drawdown, after
# `settle` (2 s) and `soften` (1 s) for the rainfall.
EVENT_STARTS = {"levee_drawdown": 1.0, "levee_drawdown_constant": 1.0, "levee_rainfall": 3.0}
STAGE_START = 1.0  # set by main() from EVENT_STARTS
ONSET = 0.01  # failure onset: the crest probe has moved this far since STAGE_START (m)
STILL = 1e-3  # "at rest": the probes' speed is below this (m/s)


def read_csv(path):
    with open(path, newline="") as handle:
        rows = [{k: float(v) for k, v in row.items()} for row in csv.DictReader(handle)]
    return {k: np.array([r[k] for r in rows]) for k in rows[0]}


def read_probes(directory, name):
    paths = sorted(glob.glob(os.path.join(directory, name + "_probe_MP*.csv")))
    if not paths:
        sys.exit(f"no probe files {name}_probe_MP*.csv in {directory}")
    probes = {}
    for path in paths:
        label = os.path.basename(path)[len(name + "_probe_"):-len(".csv")].replace("_", " ")
        p = read_csv(path)
        p["norm"] = np.hypot(p["displacement_x"], p["displacement_y"])
        probes[label] = p
    return probes


def at(t, values, time):
    """values at `time`, interpolated linearly (NaN beyond the record)."""
    return float(np.interp(time, t, values, right=np.nan))


def report(name, probes, diag, times):
    print(f"{name}: probes (initial position); |u| (cm) at event times t - {STAGE_START:g} s; "
          f"in brackets the displacement since the event started")
    for label, p in probes.items():
        u0 = [at(p["time"], p[k], STAGE_START) for k in ("displacement_x", "displacement_y")]
        since = np.hypot(p["displacement_x"] - u0[0], p["displacement_y"] - u0[1])
        cells = ", ".join(f"{s:g} s: {100 * at(p['time'], p['norm'], STAGE_START + s):.2f} "
                          f"({100 * at(p['time'], since, STAGE_START + s):.2f})" for s in times)
        print(f"  {label} ({p['x'][0]:.2f}, {p['y'][0]:.2f}) m: at the event start "
              f"{100 * at(p['time'], p['norm'], STAGE_START):.2f}; {cells}; largest "
              f"{100 * p['norm'].max():.2f} at t - {STAGE_START:g} = "
              f"{p['time'][np.argmax(p['norm'])] - STAGE_START:.1f} s")
    crest = next(p for label, p in probes.items() if "MP1" in label)
    moved = crest["norm"] - at(crest["time"], crest["norm"], STAGE_START)
    after = crest["time"] > STAGE_START
    onset = crest["time"][after & (moved >= ONSET)]
    print(f"  failure onset (crest probe {100 * ONSET:g} cm beyond its position at "
          f"t = {STAGE_START:g} s): " +
          (f"t - {STAGE_START:g} = {onset[0] - STAGE_START:.1f} s" if onset.size else "none"))
    speed = np.max([np.hypot(p["velocity_x"], p["velocity_y"]) for p in probes.values()], axis=0)
    moving = np.where(after & (speed > STILL))[0]
    if moving.size:
        print(f"  probes move faster than {1e3 * STILL:g} mm/s until t - {STAGE_START:g} = "
              f"{crest['time'][moving[-1]] - STAGE_START:.1f} s (record ends at t = "
              f"{crest['time'][-1]:.1f} s)")
    energy = diag["kinetic_energy_solid"] + diag["kinetic_energy_liquid"]
    k = int(np.argmax(energy))
    print(f"  largest kinetic energy (outputs): {energy[k]:.3g} J/m at t = {diag['time'][k]:g} s")
    for label, p in probes.items():
        cells = ", ".join(f"{s:g} s: {at(p['time'], p['liquid_pressure'], STAGE_START + s) / 1e3:.1f}"
                          for s in (0.0, *times))
        print(f"  p_L (kPa) of {label} at event times {cells}; lowest "
              f"{p['liquid_pressure'].min() / 1e3:.1f} at t - {STAGE_START:g} = "
              f"{p['time'][np.argmin(p['liquid_pressure'])] - STAGE_START:.1f} s")


def plot_history(name, probes, diag, path):
    fig, axes = plt.subplots(2, 2, figsize=(11, 7.5))
    event = f"time since the event started, t - {STAGE_START:g} s (s)"
    for j, (label, p) in enumerate(probes.items()):
        t = p["time"] - STAGE_START
        axes[0][0].plot(t, 100 * p["norm"], color=f"C{j}", label=label + " |u|")
        axes[0][0].plot(t, 100 * p["displacement_x"], color=f"C{j}", ls="--", lw=0.8)
        axes[0][1].plot(t, p["liquid_pressure"] / 1e3, color=f"C{j}", label=label)
        axes[1][0].plot(t, p["deviatoric_strain"], color=f"C{j}", label=label)
    axes[0][0].set(xlabel=event, ylabel="displacement (cm)",
                   title="displacement of the probes (solid: norm, dashed: horizontal)")
    axes[0][1].set(xlabel=event, ylabel="p_L (kPa), suction negative",
                   title="liquid pressure of the probes")
    axes[1][0].set(xlabel=event, ylabel="deviatoric strain (-)",
                   title="deviatoric strain of the probes")
    energy = diag["kinetic_energy_solid"] + diag["kinetic_energy_liquid"]
    axes[1][1].semilogy(diag["time"][1:] - STAGE_START, np.maximum(energy[1:], 1e-9), "o-", ms=3)
    axes[1][1].set(xlabel=event, ylabel="kinetic energy (J/m)",
                   title="kinetic energy of solid and liquid (diagnostics CSV)")
    for ax in axes.flat:
        ax.axvline(0.0, color="0.5", lw=0.8)
        ax.grid(alpha=0.3)
    for ax in axes.flat[:3]:
        ax.legend(fontsize=8)
    fig.suptitle(f"{name}: initial stages before the grey line (t = {STAGE_START:g} s of the "
                 f"simulation), then the event", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def plot_map(name, directory, path, until=None):
    """Points coloured by their displacement norm at three output times; skipped without
    SciPy or the points file."""
    try:
        from scipy.io import netcdf_file
    except ImportError:
        print("no SciPy: map skipped (apt-get install python3-scipy)")
        return False
    points = os.path.join(directory, name + "_points.e")
    if not os.path.exists(points):
        return False
    with netcdf_file(points, "r", mmap=False) as f:
        names = ["".join(c.decode() for c in row).strip("\x00 ")
                 for row in f.variables["name_nod_var"][:]]
        values = {n: f.variables["vals_nod_var%d" % (k + 1)][:].copy()
                  for k, n in enumerate(names)}
        x0, y0 = f.variables["coordx"][:].copy(), f.variables["coordy"][:].copy()
        time = f.variables["time_whole"][:].copy()
    last = len(time) - 1 if until is None else int(np.searchsorted(time, until * (1 + 1e-9))) - 1
    shown = sorted({int(np.searchsorted(time, STAGE_START + 0.5 * (time[last] - STAGE_START)
                                        / 4)), int(np.searchsorted(time, 0.5 * (STAGE_START
                                                                              + time[last]))),
                    last})
    top = np.hypot(values["displ_x"][last], values["displ_y"][last]).max()
    fig, axes = plt.subplots(len(shown), 1, figsize=(7.5, 2.4 * len(shown)), sharex=True,
                             layout="constrained")
    for ax, k in zip(np.atleast_1d(axes), shown):
        ux, uy = values["displ_x"][k], values["displ_y"][k]
        image = ax.scatter(x0 + ux, y0 + uy, c=100 * np.hypot(ux, uy), s=1.5, lw=0,
                           cmap="viridis", vmin=0, vmax=100 * top)
        ax.plot([0, 1.5, 6.0, 10.0], [3.0, 3.0, 0.0, 0.0], "k--", lw=0.6)
        ax.set_aspect("equal")
        ax.set_ylim(-0.6, 3.3)
        ax.set_ylabel("y (m)")
        ax.set_title(f"t = {time[k]:.3g} s ({time[k] - STAGE_START:.3g} s after the event "
                     f"started)", fontsize=9)
    fig.colorbar(image, ax=axes, label="displacement |u| (cm)", shrink=0.8)
    np.atleast_1d(axes)[-1].set_xlabel("x (m); symmetry axis at x = 0; dashed: initial surface")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return True


def by_scene(table, name, default):
    """The entry of `table` for the scene `name`: its own, else that of the longest scene name
    it starts with (a variant's deck, e.g. levee_rainfall_grid_conjugate), else `default`."""
    keys = sorted((k for k in table if name.startswith(k)), key=len, reverse=True)
    return table[keys[0]] if keys else default


def main(default_name="levee_drawdown"):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--name", default=default_name)
    parser.add_argument("--results")
    parser.add_argument("--figures")
    parser.add_argument("--times", type=float, nargs="*")
    parser.add_argument("--until", type=float, help="ignore results after this time (s)")
    args = parser.parse_args()
    name = args.name
    global STAGE_START
    STAGE_START = by_scene(EVENT_STARTS, name, 1.0)
    results = args.results or os.path.join(ROOT, "results", name)
    figures = args.figures or by_scene(FOLDER, name, HERE)
    probes = read_probes(results, name)
    diag = read_csv(os.path.join(results, name + "_diagnostics.csv"))
    if args.until is not None:  # drop the rows after --until (a run that went on longer)
        for series in (*probes.values(), diag):
            keep = series["time"] <= args.until * (1 + 1e-9)
            for key in series:
                series[key] = series[key][keep]
    report(name, probes, diag, args.times or by_scene(TIMES, name, (5.0, 10.0, 20.0)))
    history = os.path.join(figures, name + "_history.png")
    plot_history(name, probes, diag, history)
    written = [history]
    mapped = os.path.join(figures, name + "_map.png")
    if plot_map(name, results, mapped, args.until):
        written.append(mapped)
    print("wrote " + " and ".join(written))


if __name__ == "__main__":
    main()

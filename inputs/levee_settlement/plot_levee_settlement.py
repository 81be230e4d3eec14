#!/usr/bin/python3
"""Figures and key numbers of the levee settlement scene.

  plot_levee_settlement.py [--results DIR] [--drained DIR] [--figures DIR]

Reads from --results (default: results/levee_settlement of the repository, where
scripts/run.sh writes):
  levee_settlement_points.e        material points (Exodus II = netCDF-3, read with SciPy)
  levee_settlement_diagnostics.csv kinetic energy and liquid mass at every output time
and, when --drained (default: results/levee_settlement_drained) holds the results of
levee_settlement_drained.yaml, the drained elastic settlement the consolidation tends to.

Writes into --figures (default: this folder):
  levee_settlement_history.png  settlement, excess pore pressure, isochrones, surface
                                profiles, expelled water and kinetic energy
  levee_settlement_excess.png   maps of the excess pore pressure
and prints the numbers quoted in README.md.

Excess pore pressure: p_L minus the hydrostatic pressure of a water table at the foundation
surface, p_exc = p_L - rho_L g (y_w - y), at the point's current height y. Single points
carry an element-to-element oscillation of a few kPa, so every curve averages the points
near its probe (PROBE_RADIUS) or in a cell (CELL).
"""
import argparse
import csv
import os
import sys

import numpy as np

try:
    from scipy.io import netcdf_file
except ImportError:  # message for machines without python3-scipy
    sys.exit("plot_levee_settlement.py reads Exodus files with SciPy: "
             "apt-get install python3-scipy")

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
NAME = "levee_settlement"

RHO_L = 1000.0  # liquid density (kg/m3), as in the deck
G = 9.81  # gravity (m/s2)
WATER_TABLE = 4.0  # y of the foundation surface = water table (m)
WIDTH = 14.0  # width of the half section (m)
TOE = 6.0  # x of the levee toe (m)
CREST = (0.0, 7.0)  # crest on the symmetry axis (m)
LEVEE_BASE = (0.0, 4.0)  # foundation surface under the axis (m)
FAR_SURFACE = (13.0, 4.0)  # foundation surface far from the levee (m)
PROBE_RADIUS = 0.3  # points within this distance of a probe are averaged (m)
CELL = 0.4  # cell size of the excess pore pressure maps and maxima (m)
AXIS_DEPTHS = (1.0, 2.0, 3.0)  # probes on the axis, depth below the foundation surface (m)
# Terzaghi 1D: c_v = k / (rho_L g (1/E_oed + n/K_L)), k = kappa rho_L g / mu_L
# = 4e-11 * 1000 * 9.81 / 1e-3 = 3.924e-4 m/s, E_oed = 1e7 * 0.7 / (1.3 * 0.4) = 13.46 MPa,
# n/K_L = 0.4 / 8e7 = 5e-9 1/Pa: c_v = 3.924e-4 / (9810 * (7.429e-8 + 5e-9)) = 0.5045 m2/s;
# drainage length H = 4 m (drained top, sealed base).
C_V = 0.5045  # consolidation coefficient (m2/s)
DRAINAGE_LENGTH = 4.0  # H (m)
T_V = {0.5: 0.197, 0.9: 0.848}  # time factor of Terzaghi's 1D solution at U = 50 %, 90 %


class Points:
    """Time series of the material points of an argine points file."""

    def __init__(self, path):
        with netcdf_file(path, "r", mmap=False) as f:
            names = ["".join(c.decode() for c in row).strip("\x00 ")
                     for row in f.variables["name_nod_var"][:]]
            self.values = {n: f.variables["vals_nod_var%d" % (k + 1)][:].copy()
                           for k, n in enumerate(names)}
            self.x0 = f.variables["coordx"][:].copy()
            self.y0 = f.variables["coordy"][:].copy()
            self.time = f.variables["time_whole"][:].copy()
        self.material = self.values["material"][0].astype(int)  # 0: levee (first in deck)
        self.foundation = sorted(set(self.material) - {0})

    def near(self, centre, materials):
        """Indices of the points of `materials` within PROBE_RADIUS of `centre` (reference)."""
        d2 = (self.x0 - centre[0]) ** 2 + (self.y0 - centre[1]) ** 2
        chosen = np.isin(self.material, materials) & (d2 < PROBE_RADIUS ** 2)
        if not chosen.any():
            sys.exit(f"no material point near {centre}")
        return np.where(chosen)[0]

    def position(self, k):
        """Current point coordinates (x, y) at output k."""
        return self.x0 + self.values["displ_x"][k], self.y0 + self.values["displ_y"][k]

    def excess_pressure(self):
        """p_exc (Pa) of every point at every output; NaN for the dry levee."""
        y = self.y0[None, :] + self.values["displ_y"]
        excess = self.values["pressure_liquid"] - RHO_L * G * (WATER_TABLE - y)
        excess[:, self.material == 0] = np.nan
        return excess

    def surface_settlement(self, k, x_bins):
        """Mean settlement (m, down positive) of the top 0.25 m of the foundation per x bin."""
        top = np.isin(self.material, self.foundation) & (self.y0 > WATER_TABLE - 0.25)
        down = -self.values["displ_y"][k]
        return np.array([down[top & (self.x0 >= lo) & (self.x0 < hi)].mean()
                         for lo, hi in zip(x_bins[:-1], x_bins[1:])])


def cell_means(run, excess, k):
    """Mean excess pore pressure of the foundation points in CELL x CELL cells (NaN: none)."""
    edges = (np.arange(0.0, WIDTH + 1e-9, CELL), np.arange(0.0, WATER_TABLE + 1e-9, CELL))
    x, y = run.position(k)
    found = ~np.isnan(excess[k])
    sums, _, _ = np.histogram2d(x[found], y[found], edges, weights=excess[k][found])
    counts, _, _ = np.histogram2d(x[found], y[found], edges)
    with np.errstate(invalid="ignore", divide="ignore"):
        return edges, np.where(counts >= 3, sums / counts, np.nan)


def read_diagnostics(path):
    with open(path, newline="") as handle:
        rows = [{k: float(v) for k, v in row.items()} for row in csv.DictReader(handle)]
    return {k: np.array([r[k] for r in rows]) for k in rows[0]}


def drained_settlement(directory, x_bins):
    """Drained settlement (m, down positive) caused by the levee alone, or None."""
    path = os.path.join(directory, NAME + "_drained_points.e")
    if not os.path.exists(path):
        return None
    run = Points(path)
    down = -run.values["displ_y"][-1]
    # Superposition: minus the foundation's own (1D) settlement, read far from the levee.
    self_weight = down[run.near(FAR_SURFACE, run.foundation)].mean()
    return {"crest": down[run.near(CREST, [0])].mean() - self_weight,
            "base": down[run.near(LEVEE_BASE, run.foundation)].mean() - self_weight,
            "self_weight": self_weight,
            "surface": run.surface_settlement(len(run.time) - 1, x_bins) - self_weight}


def first_time(t, values, threshold, after):
    """First time after output `after` at which `values` (rising) reaches `threshold`,
    interpolated linearly between outputs; NaN if never."""
    for k in range(after + 1, len(t)):
        if values[k] >= threshold:
            w = (threshold - values[k - 1]) / (values[k] - values[k - 1])
            return t[k - 1] + w * (t[k] - t[k - 1])
    return float("nan")


def measure(run, diag, drained):
    """Histories and numbers of the run."""
    m = {"t": run.time}
    t = run.time
    total = -run.values["displ_y"]  # down positive, since t = 0
    crest, base = run.near(CREST, [0]), run.near(LEVEE_BASE, run.foundation)
    m["crest"] = total[:, crest].mean(axis=1)
    m["base"] = total[:, base].mean(axis=1)
    # The consolidation stage starts with Reset Displacements: from then on 'displacement'
    # differs from 'displ' (current minus reference position). The output before is the
    # end of construction.
    reset = np.abs(run.values["displacement_y"][:, crest].mean(axis=1)
                   + m["crest"]) > 1e-12
    m["k_built"] = int(np.argmax(reset)) - 1 if reset.any() else len(t) - 1
    excess = run.excess_pressure()
    m["excess"] = excess
    m["probe"] = {d: np.nanmean(excess[:, run.near((0.0, WATER_TABLE - d), run.foundation)],
                                axis=1) for d in AXIS_DEPTHS}
    m["x_bins"] = np.arange(0.0, WIDTH + 1e-9, 0.5)
    m["drained"] = drained
    m["expelled"] = (diag["liquid_mass"][1] - diag["liquid_mass"]) / RHO_L  # m3/m since 1st
    return m


def report(run, m):
    t, k, last = m["t"], m["k_built"], len(m["t"]) - 1
    excess = m["excess"]
    cells = {j: np.nanmax(cell_means(run, excess, j)[1]) for j in (k, last)}
    surface = m["x_bins"][:-1] + 0.25
    beside = surface > TOE
    heave = -run.surface_settlement(k, m["x_bins"])[beside]
    print(f"construction (stage 1, 0 .. {t[k]:g} s): crest settles {1e3 * m['crest'][k]:.2f} mm, "
          f"levee base {1e3 * m['base'][k]:.2f} mm; ground beside the toe heaves up to "
          f"{1e3 * heave.max():.2f} mm")
    print("  excess pore pressure on the axis after construction: "
          + ", ".join(f"{d:g} m deep {m['probe'][d][k] / 1e3:.1f} kPa" for d in AXIS_DEPTHS))
    print(f"  largest excess pore pressure: {cells[k] / 1e3:.1f} kPa (mean over {CELL} m cells), "
          f"{np.nanmax(excess[k]) / 1e3:.1f} kPa (single point)")
    print(f"consolidation (stage 2, {t[k]:g} .. {t[last]:g} s): crest settles a further "
          f"{1e3 * (m['crest'][last] - m['crest'][k]):.2f} mm, levee base "
          f"{1e3 * (m['base'][last] - m['base'][k]):.2f} mm")
    print(f"  total at {t[last]:g} s: crest {1e3 * m['crest'][last]:.2f} mm, "
          f"levee base {1e3 * m['base'][last]:.2f} mm")
    halved = first_time(t, -m["probe"][2.0], -0.5 * m["probe"][2.0][k], k)
    print(f"  excess pore pressure 2 m under the axis halves by t = {halved:.3g} s; at "
          f"{t[last]:g} s it is {m['probe'][2.0][last] / 1e3:.2f} kPa, the largest "
          f"{cells[last] / 1e3:.2f} kPa")
    print(f"  water expelled from the foundation ({t[1]:g} .. {t[last]:g} s): "
          f"{1e3 * m['expelled'][last]:.1f} litres per metre of levee (half section)")
    drained = m["drained"]
    if not drained:
        print("drained check: no results of levee_settlement_drained.yaml found")
        return
    print(f"drained check: the levee alone settles the crest {1e3 * drained['crest']:.2f} mm, "
          f"the levee base {1e3 * drained['base']:.2f} mm (foundation self-weight "
          f"{1e3 * drained['self_weight']:.2f} mm; 1D formula 5.95 mm)")
    gap = np.abs(run.surface_settlement(last, m["x_bins"]) - drained["surface"]).max()
    print(f"  foundation surface at {t[last]:g} s within {1e3 * gap:.2f} mm of the drained one")
    for name in ("base", "crest"):
        start = m[name][k]
        degree = (m[name] - start) / (drained[name] - start)
        times = {u: first_time(t, degree, u, k) - t[k] for u in T_V}
        print(f"  degree of consolidation U of the {name} (from the end of construction): "
              + ", ".join(f"{int(100 * u)} % after {times[u]:.2f} s (Terzaghi 1D "
                          f"{T_V[u] * DRAINAGE_LENGTH ** 2 / C_V:.2f} s)" for u in T_V)
              + f"; {100 * degree[last]:.1f} % at {t[last]:g} s")


def plot_history(run, m, diag, path):
    t, k = m["t"], m["k_built"]
    drained = m["drained"]
    fig, axes = plt.subplots(3, 2, figsize=(11, 10.5))

    ax = axes[0][0]
    ax.plot(t, 1e3 * m["crest"], "o-", ms=3, label="crest (axis)")
    ax.plot(t, 1e3 * m["base"], "s-", ms=3, label="levee base (axis)")
    if drained:
        ax.axhline(1e3 * drained["crest"], color="C0", ls="--", lw=1, label="crest, drained")
        ax.axhline(1e3 * drained["base"], color="C1", ls="--", lw=1, label="base, drained")
    ax.axvline(t[k], color="0.5", lw=0.8)
    ax.text(t[k], 0.5, "  end of construction", color="0.4", fontsize=8)
    ax.set(xlabel="time t (s)", ylabel="settlement (mm)", title="settlement on the axis")
    ax.invert_yaxis()
    ax.legend(fontsize=8)

    ax = axes[0][1]
    for d in AXIS_DEPTHS:
        ax.plot(t, m["probe"][d] / 1e3, "o-", ms=3, label=f"axis, {d:g} m below surface")
    ax.axvline(t[k], color="0.5", lw=0.8)
    ax.set(xlabel="time t (s)", ylabel="excess pore pressure (kPa)",
           title="excess pore pressure under the crest")
    ax.legend(fontsize=8)

    shown = sorted({k, *np.searchsorted(t, t[k] + np.array([5, 10, 20])).clip(0, len(t) - 1),
                    len(t) - 1})
    ax = axes[1][0]
    bins = np.arange(0.0, WATER_TABLE + 1e-9, 0.2)
    axis_points = np.isin(run.material, run.foundation) & (run.x0 < 2 * PROBE_RADIUS)
    for j in shown:
        depth = WATER_TABLE - run.position(j)[1]
        rows = [(0.5 * (lo + hi), np.mean(m["excess"][j][axis_points & (depth >= lo)
                                                          & (depth < hi)]) / 1e3)
                for lo, hi in zip(bins[:-1], bins[1:])]
        ax.plot([r[1] for r in rows], [r[0] for r in rows], "o-", ms=3, label=f"t = {t[j]:.3g} s")
    ax.invert_yaxis()
    ax.set(xlabel="excess pore pressure (kPa)", ylabel="depth below the foundation surface (m)",
           title=f"isochrones on the axis (points with x < {2 * PROBE_RADIUS:g} m)")
    ax.legend(fontsize=8)

    ax = axes[1][1]
    centres = m["x_bins"][:-1] + 0.25
    for j in shown:
        ax.plot(centres, 1e3 * run.surface_settlement(j, m["x_bins"]), "o-", ms=3,
                label=f"t = {t[j]:.3g} s")
    if drained:
        ax.plot(centres, 1e3 * drained["surface"], "k--", lw=1.2, label="drained")
    ax.axvline(TOE, color="0.5", lw=0.8)
    ax.text(TOE, 0, " toe", color="0.4", fontsize=8)
    ax.invert_yaxis()
    ax.set(xlabel="x (m)", ylabel="settlement (mm), negative = heave",
           title="foundation surface (points within 0.25 m of it)")
    ax.legend(fontsize=8)

    ax = axes[2][0]
    ax.plot(diag["time"][1:], 1e3 * m["expelled"][1:], "o-", ms=3, color="C2")
    ax.set(xlabel="time t (s)", ylabel="water expelled (litres per m)",
           title="water leaving the foundation (diagnostics CSV: liquid_mass)")

    ax = axes[2][1]
    for phase in ("solid", "liquid"):
        ax.semilogy(diag["time"][1:], np.maximum(diag["kinetic_energy_" + phase][1:], 1e-12),
                    label=phase)
    ax.axvline(t[k], color="0.5", lw=0.8)
    ax.set(xlabel="time t (s)", ylabel="kinetic energy (J/m)",
           title="kinetic energy (diagnostics CSV)")
    ax.legend(fontsize=8)

    for ax in axes.flat:
        ax.grid(alpha=0.3)
    fig.suptitle("Levee on a saturated foundation: construction (gravity loading) and "
                 "consolidation", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def plot_excess(run, m, path):
    t, k = m["t"], m["k_built"]
    shown = sorted({k, min(int(np.searchsorted(t, t[k] + 10)), len(t) - 1), len(t) - 1})
    fig, axes = plt.subplots(len(shown), 1, figsize=(6.4, 2.3 * len(shown)), sharex=True,
                             layout="constrained")
    top = np.nanmax(cell_means(run, m["excess"], k)[1]) / 1e3
    levee = run.material == 0
    for ax, j in zip(np.atleast_1d(axes), shown):
        (edges_x, edges_y), means = cell_means(run, m["excess"], j)
        image = ax.pcolormesh(edges_x, edges_y, means.T / 1e3, cmap="viridis", vmin=0, vmax=top)
        x, y = run.position(j)
        ax.scatter(x[levee], y[levee], s=0.8, c="0.6", lw=0)
        ax.set_aspect("equal")
        ax.set_ylim(0, 7.2)
        ax.set_ylabel("y (m)")
        ax.set_title(f"t = {t[j]:.3g} s" + (" (end of construction)" if j == k else ""),
                     fontsize=9)
    fig.colorbar(image, ax=axes, label="excess pore pressure (kPa)", shrink=0.8)
    np.atleast_1d(axes)[-1].set_xlabel("x (m); symmetry axis at x = 0; levee points in grey")
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", default=os.path.join(ROOT, "results", NAME))
    parser.add_argument("--drained", default=os.path.join(ROOT, "results", NAME + "_drained"))
    parser.add_argument("--figures", default=HERE)
    args = parser.parse_args()

    run = Points(os.path.join(args.results, NAME + "_points.e"))
    diag = read_diagnostics(os.path.join(args.results, NAME + "_diagnostics.csv"))
    m = measure(run, diag, drained_settlement(args.drained, np.arange(0.0, WIDTH + 1e-9, 0.5)))
    report(run, m)
    history = os.path.join(args.figures, NAME + "_history.png")
    excess = os.path.join(args.figures, NAME + "_excess.png")
    plot_history(run, m, diag, history)
    plot_excess(run, m, excess)
    print(f"wrote {history} and {excess}")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Mesh convergence of a levee scene's run-out (issue P11 item 3).

  levee_convergence.py [--times T ...] [--start S] [--figure PATH] [--chart Q1,Q2,...]
                       [--wall H=SECONDS ...]
                       H:DIR:NAME[:SERIES] ...

Each H:DIR:NAME is one resolution: element size H (m), the results folder DIR and the deck's
Output Name NAME (DIR/NAME_points.e, DIR/NAME.log from scripts/convergence.sh for the wall
time); SERIES (optional) groups the runs of one scheme (e.g. FLIP, TPIC), each tabulated
and charted on its own. For every resolution and every time (s since the event started, the simulation time
minus --start) it measures, from the material points (Exodus II, read with SciPy):

  crest settlement   mean -u_y of the points that started within 0.3 m of the crest surface
                     and 0.3 m of the symmetry axis (m)
  toe run-out        how far the slid mass passed the initial toe x = 6 m: the mass-weighted
                     99th percentile of the current x of the points that moved > 10 cm,
                     minus 6 m (m; objective under refinement, unlike the farthest point)
  slip depth         under the crest, x0 in [0.8, 1.2] m: the depth below the crest (y = 3 m)
                     of the lowest point whose displacement is at least half that of the
                     column's top point (m)
  mobilised volume   the volume of the points that moved > 10 cm (m^3 per m)
  probe |u|          the displacement of the scene's probes MP1-MP3 (DIR/NAME_probe_*.csv, the
                     material point nearest each probe's position at the start; m)
  probe at position  the displacement of the material that started at each probe's position
                     (PROBE_POSITIONS), interpolated linearly between the points' initial
                     positions (m): the same material on every mesh, where the nearest point
                     lies up to half a point spacing away and elsewhere on each mesh (MP3:
                     2-4 cm apart in y between meshes, in the toe's steep gradient)
  crest settlement at MP1  -u_y of that material at MP1's position (1.6, 2.9 m), the crest's
                     edge (m)

and, for a run with a strength-reduction stage (DIR/NAME_strength_reduction.csv), FS_SRM of
each search with its bracket and the limit equilibrium's F on the same state (one table per
search, not charted), and, as diagnostics of the moving mass's water (one table per time, not
charted):

  volume gain        the summed change of volume since the start of the points that moved
                     > 10 cm (L per m); with dilatancy angle 0 nearly nil in a converged slide
  of it near the surface  the part of that gain in points now within 0.2 m below the
                     body's surface (the highest point of each 0.1 m wide column; L per m)
  gain per cell      the mean over those points of their volumetric strain since the start
                     divided by the cells they crossed, |u - u_start| / H (1e-3): a constant
                     here means the gain is made a little at each cell crossed, and so grows as
                     1/H under refinement
  water drawn        the change of the liquid stored in the model since the start, from
                     DIR/NAME_boundary_flux.csv (L per m)
  made inside        the part of it the point mass balance made at the nodes on no side of
                     the free boundary (column net_inflow_interior_nodes; L per m), where a
                     conservative balance makes none
  mass p_L           the volume-weighted mean liquid pressure of those points (kPa)
  crest core swelling  the relative volume change since the start of the points that started
                     under the crest (x0 < 1.5 m, y0 > 2 m), moved or not (1e-3)
  of it in its most swollen tenth  the share of that change in the tenth of those points
                     that swelled most (near 0.1 if it is spread evenly, near 1 if a few bands
                     or cracks carry it)
  crest core p_L     the volume-weighted mean liquid pressure of the crest core (kPa): the
                     suction that its swelling makes strengthens it

A full section (points that start at x < 0, the levee mirrored about its axis) is measured on
its right half, the points that start at x >= 0, so its numbers compare with a half section's
(but for water drawn, which is the whole model's).

It prints them with the change against the next finer resolution and, with three, the observed
order p (observed_order: log(|q_3 - q_2| / |q_2 - q_1|) / log r for one refinement ratio r,
Celik et al.'s equation for two, e.g. 0.1, 0.05 and 1/28 m), the Richardson limit and the
finest value's error bar (error_bar: Roache's grid convergence index where the changes keep
their sign, with the order capped at the method's first order). With --figure it charts each
quantity at the last time against the wall time of its run, one line per series: the
coarsest model that is still right is the leftmost point near where the lines end.
"""
import argparse
import math
import os
import re
import sys

import numpy as np

CREST_Y, TOE_X = 3.0, 6.0  # the levee_drawdown / levee_rainfall geometry (m)
MOVED = 0.10  # a point has "moved" beyond this displacement (m)
NEAR_SURFACE = 0.2  # a point lies "near the surface" within this depth below it (m)
SURFACE_BIN = 0.1  # the surface: the highest point of each column of this width (m)
QUANTITIES = ("crest settlement", "toe run-out", "slip depth", "mobilised volume")
STRENGTH = ("FS_SRM", "limit equilibrium F")  # of a run with a strength-reduction stage
WATER = ("volume gain (L/m)", "of it near the surface (L/m)", "gain per cell (1e-3)",
         "water drawn (L/m)", "made inside (L/m)",
         "mass p_L (kPa)", "crest core swelling (1e-3)", "of it in its most swollen tenth",
         "crest core p_L (kPa)")
CREST_CORE_DEPTH = 1.0  # the crest core: the points that start at x < 1.5 m within this of y = 3 m
# the scenes' probes and their positions in the levee_drawdown and levee_rainfall decks
# (Probes/Points/Position, m)
PROBE_POSITIONS = {"MP1_crest": (1.6, 2.9), "MP2_slope": (3.75, 1.4), "MP3_toe": (5.8, 0.05)}
PROBES = tuple(PROBE_POSITIONS)
# -u_y of the material at MP1's position: the settlement of the crest's edge, on every mesh
# the same material (the crest settlement above averages a column at the axis, where the
# back scarp of a slide that takes the crest's edge lies: a step, not a field, there)
CREST_PROBE_SETTLEMENT = "crest settlement at MP1"


def probe_displacements(directory, name, times):
    """|u| of each probe (DIR/NAME_probe_<probe>.csv) at the simulation times `times` (the
    row nearest in time, within 1e-6 s); missing probes or times are left out."""
    out = {}
    for probe in PROBES:
        path = os.path.join(directory, f"{name}_probe_{probe}.csv")
        if not os.path.exists(path):
            continue
        data = np.genfromtxt(path, delimiter=",", names=True)
        for t in times:
            k = int(np.argmin(np.abs(data["time"] - t)))
            if abs(data["time"][k] - t) <= 1e-6:
                out.setdefault(t, {})[f"probe {probe} |u|"] = float(
                    np.hypot(data["displacement_x"][k], data["displacement_y"][k]))
    return out


def read_points(path, want=("displ_x", "displ_y", "volume", "pressure_liquid")):
    """Time, initial x and y, and the point variables `want` (those present) of an argine
    points file (Exodus II)."""
    from scipy.io import netcdf_file

    with netcdf_file(path, "r", mmap=False) as f:
        names = ["".join(c.decode() for c in row).strip("\x00 ")
                 for row in f.variables["name_nod_var"][:]]
        values = {n: f.variables["vals_nod_var%d" % (k + 1)][:].copy()
                  for k, n in enumerate(names) if n in want}
        x0, y0 = f.variables["coordx"][:].copy(), f.variables["coordy"][:].copy()
        time = f.variables["time_whole"][:].copy()
    return time, x0, y0, values


def output_index(time, t):
    """The index of the output at time t (s) in `time`; exits if the run has none there."""
    k = int(np.argmin(np.abs(time - t)))
    if abs(time[k] - t) > 1e-6:
        sys.exit(f"no output at t = {t:g} s")
    return k


def crest_core(x0, y0):
    """The points that start under the crest: x0 < 1.5 m, within CREST_CORE_DEPTH of y = 3 m."""
    return (x0 < 1.5) & (y0 > CREST_Y - CREST_CORE_DEPTH)


def right_half(time, x0, y0, values):
    """read_points' output for the points that start at x >= 0: a full section's right half,
    all of a half section."""
    keep = x0 >= 0.0
    return time, x0[keep], y0[keep], {n: v[:, keep] for n, v in values.items()}


def weighted_percentile(x, w, q):
    order = np.argsort(x)
    cumulative = np.cumsum(w[order])
    return x[order][np.searchsorted(cumulative, q * cumulative[-1])]


def measure(x0, y0, ux, uy, volume):
    u = np.hypot(ux, uy)
    crest = (x0 < 0.3) & (y0 > CREST_Y - 0.3)
    moved = u > MOVED
    out = {"crest settlement": float(-uy[crest].mean()) if crest.any() else math.nan,
           "mobilised volume": float(volume[moved].sum())}
    out["toe run-out"] = (float(weighted_percentile(x0[moved] + ux[moved], volume[moved], 0.99))
                          - TOE_X) if moved.sum() > 10 else 0.0
    column = (x0 > 0.8) & (x0 < 1.2)
    top = u[column][np.argmax(y0[column])]
    sliding = column & (u >= 0.5 * top)
    out["slip depth"] = float(CREST_Y - y0[sliding].min()) if top > MOVED else 0.0
    return out


def displacement_at(x0, y0, positions):
    """A function of (ux, uy) giving |u| at each of `positions` (initial coordinates, m),
    linear on the Delaunay triangulation of the initial positions (x0, y0), built once; nan
    outside their hull."""
    from scipy.interpolate import LinearNDInterpolator
    from scipy.spatial import Delaunay

    triangulation = Delaunay(np.column_stack([x0, y0]))
    where = np.asarray(positions, dtype=float)

    def at(ux, uy, components=False):
        u = LinearNDInterpolator(triangulation, np.column_stack([ux, uy]))(where)
        return u if components else np.hypot(u[:, 0], u[:, 1])
    return at


def depth_below_surface(x, y):
    """Each point's depth below the body's surface above it: the highest point of its column
    of width SURFACE_BIN, minus its own y (m)."""
    column = np.floor(x / SURFACE_BIN).astype(int)
    column -= column.min()
    top = np.full(column.max() + 1, -np.inf)
    np.maximum.at(top, column, y)
    return top[column] - y


def water_of_moving_mass(h, x0, y0, ux, uy, volume, p_liquid, k0, k):
    """The moving mass's water diagnostics (module docstring) at output k against the start
    output k0: initial positions x0, y0, point displacements ux, uy and volumes per output,
    p_liquid (None if the run has no liquid)."""
    moved = np.hypot(ux[k], uy[k]) > MOVED
    if moved.sum() == 0:
        return {}
    gain = volume[k][moved] - volume[k0][moved]
    near = depth_below_surface(x0 + ux[k], y0 + uy[k])[moved] < NEAR_SURFACE
    cells = np.hypot(ux[k][moved] - ux[k0][moved], uy[k][moved] - uy[k0][moved]) / h
    crossed = cells > 1.0  # a point still in its first cell says nothing per cell
    out = {"volume gain (L/m)": 1e3 * float(gain.sum()),
           "of it near the surface (L/m)": 1e3 * float(gain[near].sum())}
    if crossed.any():
        out["gain per cell (1e-3)"] = 1e3 * float(
            np.mean(gain[crossed] / volume[k0][moved][crossed] / cells[crossed]))
    core = crest_core(x0, y0)
    if core.any():
        swelling = volume[k][core] - volume[k0][core]
        out["crest core swelling (1e-3)"] = 1e3 * float(swelling.sum() / volume[k0][core].sum())
        if swelling.sum() > 0:
            tenth = np.sort(swelling)[::-1][:max(1, core.sum() // 10)]
            out["of it in its most swollen tenth"] = float(tenth.sum() / swelling.sum())
    if p_liquid is not None:
        out["mass p_L (kPa)"] = 1e-3 * float(np.average(p_liquid[k][moved],
                                                         weights=volume[k][moved]))
        if core.any():
            out["crest core p_L (kPa)"] = 1e-3 * float(np.average(p_liquid[k][core],
                                                                   weights=volume[k][core]))
    return out


def water_drawn(directory, name, start, times):
    """Per time of `times`: the liquid stored in the model minus that at `start` ("water
    drawn") and, where the file has the column, the part of it made at the nodes on no side
    of the free boundary ("made inside"), both in L/m, from DIR/NAME_boundary_flux.csv
    (columns storage_change, net_inflow_interior_nodes); {} where the file or a row is
    missing."""
    path = os.path.join(directory, f"{name}_boundary_flux.csv")
    if not os.path.exists(path):
        return {}
    data = np.genfromtxt(path, delimiter=",", names=True)
    columns = {"water drawn (L/m)": "storage_change",
               "made inside (L/m)": "net_inflow_interior_nodes"}

    def at(column, t):
        k = int(np.argmin(np.abs(data["time"] - t)))
        return data[column][k] if abs(data["time"][k] - t) <= 1e-6 else math.nan

    out = {}
    for t in times:
        for label, column in columns.items():
            if column in data.dtype.names and not math.isnan(at(column, t) - at(column, start)):
                out.setdefault(t, {})[label] = 1e3 * float(at(column, t) - at(column, start))
    return out


def strength_reductions(directory, name):
    """The strength-reduction searches of a run (DIR/NAME_strength_reduction.csv; {} without
    one), keyed by the simulation time each started from: FS_SRM, the mean of the highest
    holding and the lowest failing factor by the search's own criterion (column `failed`),
    half their gap (the search's tolerance once it bisected), and the limit equilibrium's F
    on the same state (DIR/NAME_factor_of_safety.csv at that time, the deck's method; nan
    where the run has no evaluation there). A search whose trials all held or all failed
    gives nan."""
    path = os.path.join(directory, f"{name}_strength_reduction.csv")
    if not os.path.exists(path):
        return {}
    trials = np.atleast_1d(np.genfromtxt(path, delimiter=",", names=True))
    lem_path = os.path.join(directory, f"{name}_factor_of_safety.csv")
    lem = (np.atleast_1d(np.genfromtxt(lem_path, delimiter=",", names=True))
           if os.path.exists(lem_path) else None)
    out = {}
    for start in np.unique(trials["time"]):
        search = trials[trials["time"] == start]
        held = search["factor"][search["failed"] == 0]
        failed = search["factor"][search["failed"] == 1]
        fs = bracket = math.nan
        if held.size and failed.size:
            low = held.max()
            high = failed[failed > low].min() if (failed > low).any() else math.nan
            fs, bracket = 0.5 * (low + high), 0.5 * (high - low)
        f_lem = math.nan
        if lem is not None:
            k = int(np.argmin(np.abs(lem["time"] - start)))
            if abs(lem["time"][k] - start) <= 1e-6:
                f_lem = float(lem["factor_of_safety"][k])
        out[float(start)] = {"FS_SRM": float(fs), "bracket": float(bracket),
                             "limit equilibrium F": f_lem}
    return out


def strength_error_bar(values, sizes, brackets):
    """error_bar of FS_SRM values, whose every value is known only to its search's bracket
    (half-width): the finest value's error bar is at least its own bracket, so changes
    smaller than the brackets (or none) do not make it vanish."""
    order, limit, bar = error_bar(values, sizes)
    if brackets and not math.isnan(brackets[-1]) and not math.isnan(bar):
        bar = max(bar, brackets[-1])
    return order, limit, bar


def chart_strength(ax, q, label, group):
    """One series of `q` (FS_SRM with its brackets as error bars, or the limit equilibrium's
    F) of the group's first strength-reduction search against each run's wall time."""
    starts = sorted({t for r in group for t in r["strength"]})
    if not starts:
        return
    found = [r["strength"].get(starts[0], {}) for r in group]
    walls = [r["wall"] for r in group]
    values = [f.get(q, math.nan) for f in found]
    bars = [f.get("bracket", 0.0) if q == "FS_SRM" else 0.0 for f in found]
    ax.errorbar(walls, values, yerr=bars, fmt="o-", capsize=3,
                label=f"{label or 'runs'} (from t = {starts[0]:g} s)")
    ax.set_xscale("log")
    for r, w, value in zip(group, walls, values):
        ax.annotate(f"{r['h']:.2g} m", (w, value), fontsize=7)


def strength_table(label, runs):
    """FS_SRM and the limit equilibrium's F on the same state per resolution, with the
    changes, observed order, Richardson limit and error bar (error_bar) of each."""
    starts = sorted({t for r in runs for t in r["strength"]})
    sizes = [r["h"] for r in runs]
    for start in starts:
        print(f"\n{label} strength reduction from t = {start:g} s (FS_SRM: the bracket's "
              "middle, +- half its width)")
        print("| quantity | " + " | ".join(f"h = {r['h']:.3g} m" for r in runs)
              + " | changes to the next finer | observed order | Richardson limit "
              "| finest with error bar |")
        print("|---|" + "---|" * (len(runs) + 4))
        found = [r["strength"].get(start, {}) for r in runs]
        brackets = [f.get("bracket", math.nan) for f in found]
        for q in STRENGTH:
            values = [f.get(q, math.nan) for f in found]
            cells = [f"{v:.4f}" for v in values]
            if q == "FS_SRM":
                cells = [f"{c} ± {w:.4f}" for c, w in zip(cells, brackets)]
                order, limit, bar = strength_error_bar(values, sizes, brackets)
            else:
                order, limit, bar = error_bar(values, sizes)
            changes = [b - a for a, b in zip(values, values[1:])]
            print(f"| {q} | " + " | ".join(cells) + " | "
                  + ", ".join(f"{c:+.4f}" for c in changes) + f" | {order:.2f} | {limit:.4f} | "
                  + (f"{values[-1]:.4f} ± {bar:.4f}" if not math.isnan(bar) else "-") + " |")


def wall_time(directory, name):
    log = os.path.join(directory, name + ".log")
    if not os.path.exists(log):
        return math.nan
    with open(log) as handle:
        match = re.findall(r"simulated in ([0-9.e+]+) s wall", handle.read())
    return float(match[-1]) if match else math.nan


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("runs", nargs="+", help="H:DIR:NAME")
    parser.add_argument("--times", type=float, nargs="+", default=[2.0, 3.0, 20.0])
    parser.add_argument("--start", type=float, default=1.0,
                        help="simulation time at which the event starts (s)")
    parser.add_argument("--figure", help="accuracy-against-wall-time chart (PNG)")
    parser.add_argument("--chart", type=lambda text: text.split(","), metavar="Q1,Q2,...",
                        help="the quantities the figure charts, comma-separated, as the tables "
                        "name them without the unit (default: the four run-out quantities; "
                        "FS_SRM and the limit equilibrium's F of the first search where the "
                        "runs reduce strength)")
    parser.add_argument("--wall", action="append", default=[], metavar="H=SECONDS",
                        help="wall time of the run of size H where its log does not hold it "
                        "(a run resumed from a checkpoint: the sum of its parts); repeatable")
    args = parser.parse_args()
    wall_given = {}
    for item in args.wall:
        h, _, seconds = item.partition("=")
        try:
            wall_given[float(h)] = float(seconds)
        except ValueError:
            sys.exit(f"--wall {item}: expected H=SECONDS, e.g. 0.025=9000")
    runs = []
    for spec in args.runs:
        h, directory, name, *series = spec.split(":")
        path = os.path.join(directory, name + "_points.e")
        if not os.path.exists(path):
            sys.exit(f"no {path}")
        time, x0, y0, v = right_half(*read_points(path))
        rows, water = {}, {}
        k0 = int(np.argmin(np.abs(time - args.start)))
        drawn = water_drawn(directory, name, args.start, [args.start + t for t in args.times])
        at_positions = displacement_at(x0, y0, list(PROBE_POSITIONS.values()))
        for t in args.times:
            k = int(np.argmin(np.abs(time - (args.start + t))))
            if abs(time[k] - (args.start + t)) > 1e-6:
                continue  # this run did not reach t
            rows[t] = measure(x0, y0, v["displ_x"][k], v["displ_y"][k], v["volume"][k])
            u = at_positions(v["displ_x"][k], v["displ_y"][k], components=True)
            rows[t].update({f"probe {p} at position |u|": float(np.hypot(*value))
                            for p, value in zip(PROBES, u)})
            rows[t][CREST_PROBE_SETTLEMENT] = float(-u[PROBES.index("MP1_crest")][1])
            water[t] = water_of_moving_mass(float(h), x0, y0, v["displ_x"], v["displ_y"],
                                            v["volume"], v.get("pressure_liquid"), k0, k)
            water[t].update(drawn.get(args.start + t, {}))
        probes = probe_displacements(directory, name, [args.start + t for t in rows])
        for t in rows:
            rows[t].update(probes.get(args.start + t, {}))
        wall = wall_given.get(float(h), wall_time(directory, name))
        runs.append({"h": float(h), "points": len(x0), "wall": wall,
                     "rows": rows, "water": water, "series": series[0] if series else "",
                     "strength": strength_reductions(directory, name)})
    groups = {}
    for r in runs:
        groups.setdefault(r["series"], []).append(r)
    for label, group in groups.items():
        group.sort(key=lambda r: -r["h"])  # coarse to fine
        table(label, group, args.times)
        if any(r["strength"] for r in group):
            strength_table(label, group)

    if args.figure:
        chart = args.chart or (list(STRENGTH) if any(r["strength"] for r in runs)
                               else list(QUANTITIES))
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        last = max(args.times)
        fig, axes = plt.subplots(1, len(chart), figsize=(13, 3.2), layout="constrained",
                                 squeeze=False)
        axes = axes[0]
        for ax, q in zip(axes, chart):
            for label, group in groups.items():
                if q in STRENGTH:
                    chart_strength(ax, q, label, group)
                    continue
                t = max((t for t in args.times if all(t in r["rows"] for r in group)),
                        default=None)
                if t is None:
                    continue
                walls = [r["wall"] for r in group]
                values = [r["rows"][t].get(q, math.nan) for r in group]
                ax.semilogx(walls, values, "o-", label=f"{label or 'runs'} ({t:g} s)")
                for r, w, value in zip(group, walls, values):
                    ax.annotate(f"{r['h']:.2g} m", (w, value), fontsize=7)
            unit = " (-)" if q in STRENGTH else " (m3/m)" if q == "mobilised volume" else " (m)"
            ax.set_title(q + unit, fontsize=9)
            ax.set_xlabel("wall time (s)")
        axes[0].legend(fontsize=7)
        fig.suptitle("factors of safety of the state each strength reduction starts from "
                     "against the run's wall time" if set(chart) <= set(STRENGTH) else
                     f"values after the event started (last common time up to {last:g} s) "
                     "against the run's wall time", fontsize=9)
        fig.savefig(args.figure, dpi=110)
        print(f"\nwrote {args.figure}")


def observed_order(sizes, values):
    """Observed order p of the last three values (coarse to fine) on the last three element
    sizes, for q(h) = q0 + C h^p: with e32 = q2 - q3 and e21 = q1 - q2 (q1 the finest, both of
    one sign), e32 / e21 = (h3^p - h2^p) / (h2^p - h1^p). One refinement ratio r: p =
    log(e32 / e21) / log r. Two ratios (e.g. 0.1, 0.05 and 1/28 m; the equation of Celik et
    al. 2008, J. Fluids Eng. 130, 078001, Eqs. 3-5): the right-hand side grows with p from
    log(h3 / h2) / log(h2 / h1) at p -> 0, so p is found by bisection; nan where e32 / e21 is
    below that (no positive order), inf where it lies above its value at p = 50."""
    h3, h2, h1 = sizes[-3:]
    q3, q2, q1 = values[-3:]
    e32, e21 = q2 - q3, q1 - q2
    if e32 == 0 or e21 == 0 or e32 * e21 < 0:
        return math.nan
    target = math.log(e32 / e21)
    if math.isclose(h3 / h2, h2 / h1, rel_tol=1e-9):
        return target / math.log(h2 / h1)

    def of(p):  # log of the ratio of the changes at order p
        return math.log((h3**p - h2**p) / (h2**p - h1**p))

    low, high = 0.0, 50.0
    if target <= math.log(math.log(h3 / h2) / math.log(h2 / h1)):
        return math.nan
    if target >= of(high):
        return math.inf
    for _ in range(200):
        middle = 0.5 * (low + high)
        if of(middle) < target:
            low = middle
        else:
            high = middle
    return 0.5 * (low + high)


def error_bar(values, sizes, formal_order=1.0):
    """Observed order, Richardson limit and error bar of the finest of the last three values
    (coarse to fine, on element sizes `sizes`; observed_order). Where the changes keep their
    sign and the observed order p is at least 0.5: Roache's grid convergence index with
    safety factor 1.25, GCI = 1.25 |q_1 - q_2| / (r21^p' - 1), and the limit q_1 + (q_1 - q_2)
    / (r21^p' - 1), with r21 the last refinement ratio and p' = min(p, formal_order): an order
    above the method's is taken for a coarse mesh outside the asymptotic range, not for a
    faster convergence (linear-shape MPM with FLIP is at best first order in the
    displacements). Otherwise (the changes oscillate, or p < 0.5) no limit and, as the error
    bar, 1.25 x the larger of the last two changes."""
    if len(values) < 3 or any(math.isnan(v) for v in values[-3:]):
        return math.nan, math.nan, math.nan
    q3, q2, q1 = values[-3:]
    e32, e21 = q2 - q3, q1 - q2
    if e21 == 0:
        return math.inf, q1, 0.0
    if e32 == 0 or e32 * e21 < 0:
        return math.nan, math.nan, 1.25 * max(abs(e32), abs(e21))
    order = observed_order(sizes, values)
    if not order >= 0.5:
        return order, math.nan, 1.25 * max(abs(e32), abs(e21))
    used = min(order, formal_order)
    r21 = sizes[-2] / sizes[-1]
    return order, q1 + e21 / (r21**used - 1), 1.25 * abs(e21) / (r21**used - 1)


def table(label, runs, times):
    print(f"\n{label or 'runs'}: element size (m), points, wall time (s)")
    for r in runs:
        print(f"  {r['h']:.3g} m  {r['points']:6d} points  {r['wall']:.0f} s")
    sizes = [r["h"] for r in runs]
    for t in times:
        print(f"\n{label} t = {t:g} s after the event started")
        print("| quantity | " + " | ".join(f"h = {r['h']:.3g} m" for r in runs)
              + " | changes to the next finer | observed order | Richardson limit "
              "| finest with error bar |")
        print("|---|" + "---|" * (len(runs) + 4))
        probes = [q for p in PROBES for q in (f"probe {p} |u|", f"probe {p} at position |u|")
                  if any(q in r["rows"].get(t, {}) for r in runs)]
        extra = [q for q in (CREST_PROBE_SETTLEMENT,)
                 if any(q in r["rows"].get(t, {}) for r in runs)]
        for q in list(QUANTITIES) + extra + probes:
            values = [r["rows"][t].get(q, math.nan) if t in r["rows"] else math.nan
                      for r in runs]
            changes = [b - a for a, b in zip(values, values[1:])]
            order, limit, bar = error_bar(values, sizes)
            unit = "m3/m" if q == "mobilised volume" else "m"
            print(f"| {q} ({unit}) | " + " | ".join(f"{v:.3f}" for v in values) + " | "
                  + ", ".join(f"{c:+.3f}" for c in changes) + f" | {order:.2f} | {limit:.3f} | "
                  + (f"{values[-1]:.3f} ± {bar:.3f}" if not math.isnan(bar) else "-") + " |")
        diagnostics = [q for q in WATER if any(q in r["water"].get(t, {}) for r in runs)]
        if diagnostics:
            print(f"\n{label} t = {t:g} s: the moving mass's water (diagnostics)")
            print("| diagnostic | " + " | ".join(f"h = {r['h']:.3g} m" for r in runs) + " |")
            print("|---|" + "---|" * len(runs))
            for q in diagnostics:
                print(f"| {q} | " + " | ".join(
                    f"{r['water'].get(t, {}).get(q, math.nan):.3f}" for r in runs) + " |")


if __name__ == "__main__":
    main()

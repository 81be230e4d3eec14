#!/usr/bin/python3
"""Runs one V7 granular column collapse with `argine run` and measures it.

  collapse_run.py --deck collapse_a2.yaml [--cells 20] [--shape linear|GIMP|B-spline]
                  [--transfer FLIP|APIC|TPIC|XPIC] [--work DIR] [--csv FILE] [--profiles DIR]
                  [--set 'KEY=VALUE' ...] [--without-side-walls] [--tag-suffix S]
                  [--argine build/argine] [--keep]
                  [--skip-existing] [--new-csv]

Writes a copy of the deck with the cell size L0/cells, the shape functions and the velocity
transfer replaced (nothing else changes; --set replaces the first value of any other key, for
sensitivity runs, e.g. --set "Young's Modulus (Pa)=4.0e6"; --without-side-walls drops the
channel's side walls: plane strain, frictionless walls), runs it into WORK/<tag>/, measures it
(collapse_results.measure), appends one row to --csv (created with a header) and writes the
final deposit profile to PROFILES/<tag>_profile.csv and the point kinetic energy at the
outputs to PROFILES/<tag>_energy.csv. Prints the row. Without --cells,
--shape or --transfer the deck's own value is kept, so that `--deck X` alone measures what
`argine run X` gives. The Exodus files are deleted after the measurement unless --keep.
With --skip-existing nothing is run when --csv has a row of the same deck, mesh, shape
functions and transfer already; with --new-csv the file is written afresh with this row only.
"""
import argparse
import csv
import os
import re
import resource
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from collapse_results import measure, read_diagnostics  # noqa: E402

ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
COLUMNS = ["deck", "a", "cells", "h", "shape", "transfer", "points", "steps", "wall_seconds",
           "cpu_seconds", "runout_L95", "runout_L99", "runout_L100", "runout_front",
           "runout_front_fixed", "height", "volume_ratio", "porosity_min", "porosity_max",
           "t_stop", "t_end", "energy_scale", "ke_peak", "ke_points", "ke_grid", "lost_points",
           "status"]


def deck_value(text, key):
    match = re.search(r"[\s{,]" + re.escape(key) + r":\s*([^\s,}#]+)", text)
    if not match:
        sys.exit(f"collapse_run: no '{key}' in the deck")
    return match.group(1)


def column_of(text):
    """L0, H0 from the column region's vertices, and the other numbers the measures need."""
    match = re.search(r"column:\s*\{Vertices \(m\):\s*\[([^\]]*)\]", text)
    if not match:
        sys.exit("collapse_run: the deck needs a region 'column: {Vertices (m): [...]}'")
    xy = [float(v) for v in match.group(1).split(",")]
    per_element = int(deck_value(text, "Points Per Element"))
    return {"L0": max(xy[0::2]) - min(xy[0::2]), "H0": max(xy[1::2]) - min(xy[1::2]),
            "h": float(deck_value(text, "Element Size (m)")),
            "per_direction": int(round(per_element ** 0.5)),
            "density": float(deck_value(text, "Solid Density (kg/m3)")),
            "g": float(deck_value(text, "Gravity (m/s2)"))}


def replace(text, key, value):
    """The first value of `key`, on a line of its own or in a flow map ({..., key: value})."""
    return re.sub(r"((?:^\s*|[{,]\s*)" + re.escape(key) + r":\s*)[^\s,}#]+",
                  lambda m: m.group(1) + value, text, count=1, flags=re.M)


def variant(text, cells, shape, transfer, settings=(), without_side_walls=False):
    if without_side_walls:
        text, count = re.subn(r"^[^\n]*\{Type: side walls[^\n]*\n", "", text, flags=re.M)
        if count != 1:
            sys.exit("collapse_run: --without-side-walls: no one-line side walls condition")
    for setting in settings:
        key, value = setting.split("=", 1)
        if not re.search(r"(?:^\s*|[{,]\s*)" + re.escape(key) + r":", text, re.M):
            sys.exit(f"collapse_run: --set {setting}: no '{key}' line in the deck")
        text = replace(text, key, value)
    column = column_of(text)
    if cells:
        text = replace(text, "Element Size (m)", repr(column["L0"] / cells))
    if shape:
        text = replace(text, "Shape Functions", shape)
    if transfer:
        text = replace(text, "Velocity Transfer", transfer)
    return text


def run(argine, deck, directory):
    os.makedirs(directory, exist_ok=True)
    start = time.perf_counter()
    cpu_before = resource.getrusage(resource.RUSAGE_CHILDREN)
    done = subprocess.run([argine, "run", deck, "--output", directory], capture_output=True,
                          text=True)
    wall = time.perf_counter() - start
    cpu_after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (cpu_after.ru_utime - cpu_before.ru_utime) + (cpu_after.ru_stime - cpu_before.ru_stime)
    with open(os.path.join(directory, "argine.log"), "w") as log:
        log.write(done.stdout + done.stderr)
    if done.returncode != 0:
        print(f"collapse_run: argine run {deck} failed ({done.returncode}):\n"
              + done.stderr[-2000:], file=sys.stderr)
        stopped = re.search(r"run stopped: (\w+) at t = ([0-9.eE+-]+) s \(step (\d+)",
                            done.stderr)
        if stopped:
            return wall, cpu, int(stopped.group(3)), (f"failed: {stopped.group(1)} at "
                                                     f"t = {float(stopped.group(2)):.4g} s")
        return wall, cpu, -1, f"failed: exit code {done.returncode}"
    steps = re.search(r"argine: (\d+) steps, (\d+) points", done.stdout)
    return wall, cpu, int(steps.group(1)) if steps else -1, "ok"


def write_row(path, row):
    new = not os.path.exists(path)
    with open(path, "a", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=COLUMNS, extrasaction="ignore")
        if new:
            writer.writeheader()
        writer.writerow(row)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--deck", required=True)
    parser.add_argument("--cells", type=int, help="cells per column length L0")
    parser.add_argument("--shape", choices=["linear", "GIMP", "B-spline"])
    parser.add_argument("--transfer", choices=["FLIP", "APIC", "TPIC", "XPIC"])
    parser.add_argument("--work", default=os.path.join(ROOT, "build", "verification",
                                                       "granular_collapse", "runs"))
    parser.add_argument("--csv")
    parser.add_argument("--profiles")
    parser.add_argument("--argine", default=os.path.join(ROOT, "build", "argine"))
    parser.add_argument("--set", action="append", default=[], metavar="KEY=VALUE")
    parser.add_argument("--without-side-walls", action="store_true",
                        help="drop the channel's side walls (plane strain, frictionless walls)")
    parser.add_argument("--tag-suffix", default="", help="appended to the run's name")
    parser.add_argument("--keep", action="store_true")
    parser.add_argument("--skip-existing", action="store_true")
    parser.add_argument("--new-csv", action="store_true")
    args = parser.parse_args()

    with open(args.deck) as handle:
        text = variant(handle.read(), args.cells, args.shape, args.transfer, args.set,
                       args.without_side_walls)
    column = column_of(text)
    name = deck_value(text, "Name")
    shape = deck_value(text, "Shape Functions")
    transfer = deck_value(text, "Velocity Transfer")
    cells = int(round(column["L0"] / column["h"]))
    tag = f"{name}_h{cells}_{shape}_{transfer}{args.tag_suffix}"
    label = (os.path.basename(args.deck) + "".join(" " + s for s in args.set)
             + (" without side walls" if args.without_side_walls else ""))
    if args.skip_existing and args.csv and os.path.exists(args.csv):
        with open(args.csv, newline="") as handle:
            for row in csv.DictReader(handle):
                if (row["deck"], row["cells"], row["shape"], row["transfer"]) == (
                        label, str(cells), shape, transfer):
                    print(f"collapse_run: {tag} is in {args.csv} already")
                    return 0
    if args.new_csv and args.csv and os.path.exists(args.csv):
        os.remove(args.csv)  # before the run: a failed run leaves no row of an earlier one
    directory = os.path.join(args.work, tag)
    os.makedirs(directory, exist_ok=True)
    deck = os.path.join(directory, tag + ".yaml")
    with open(deck, "w") as handle:
        handle.write(text)
    wall, cpu, steps, status = run(args.argine, deck, directory)
    if status != "ok":
        # The failure is a result of the study (an unstable pair): one row with the run's
        # identity, cost and status, the measures empty; the exit code says it failed.
        row = {k: float("nan") for k in COLUMNS}
        row.update(deck=label, a=column["H0"] / column["L0"], cells=cells, h=column["h"],
                   shape=shape, transfer=transfer, steps=steps, wall_seconds=round(wall, 2),
                   cpu_seconds=round(cpu, 2), status=status)
        if args.csv:
            write_row(args.csv, row)
        print(f"collapse_run: {tag}: {status}")
        return 1
    result, profile = measure(directory, name, column)
    row = dict(result, deck=label, a=column["H0"] / column["L0"],
               cells=cells, h=column["h"], shape=shape, transfer=transfer, steps=steps,
               wall_seconds=round(wall, 2), cpu_seconds=round(cpu, 2), status="ok")
    if args.csv:
        write_row(args.csv, row)
    if args.profiles:
        os.makedirs(args.profiles, exist_ok=True)
        with open(os.path.join(args.profiles, tag + "_profile.csv"), "w") as handle:
            handle.write("x_over_L0,h_over_L0\n")
            for x, h in zip(profile["x"], profile["h"]):
                handle.write(f"{x / column['L0']:.5f},{h / column['L0']:.5f}\n")
        diagnostics = read_diagnostics(os.path.join(directory, name + "_diagnostics.csv"))
        with open(os.path.join(args.profiles, tag + "_energy.csv"), "w") as handle:
            handle.write("t_over_Tc,ke_over_pe\n")
            t_c = (column["H0"] / column["g"]) ** 0.5
            for t, ke in zip(diagnostics["time"], diagnostics["kinetic_energy_solid"]):
                handle.write(f"{t / t_c:.4f},{ke / result['energy_scale']:.4e}\n")
    if not args.keep:
        for suffix in ("_points.e", "_grid.e"):
            path = os.path.join(directory, name + suffix)
            if os.path.exists(path):
                os.remove(path)
    print(",".join(f"{k}={row[k]:.4g}" if isinstance(row[k], float) else f"{k}={row[k]}"
                   for k in COLUMNS))
    return 0


if __name__ == "__main__":
    sys.exit(main())

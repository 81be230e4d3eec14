#!/usr/bin/env python3
"""How sharply a weakened slope chooses the depth of its slip surface (issue P11 item 3).

For each element size, the deck is weakened as scripts/strength_sensitivity.py weakens it
(c' and tan(phi') of the last stage times --factor), its last stage cut to --duration with an
output every --interval, and run once for each --depths value with Bishop's critical-circle
search restricted to circles reaching at least that far below the ground (`Factor Of Safety:
Minimum Depth (m)`), on a fixed ground line and a fixed raster so that only the points'
state differs between the meshes. At --time the table gives, per mesh, the lowest F of each
restriction, its circle's greatest depth and where it enters the crest: a flat F over the
depths means the slope's limit equilibrium barely prefers one depth of mechanism over
another, so which one the slide takes is weakly determined.

  scripts/slip_depth_lem.py DECK --sizes 0.2 0.1 0.05 --depths 0.5 1.4 1.6 1.8
      [--factor 0.75] [--duration 0.2] [--interval 0.1] [--time 1.1] [--jobs 2] [--ranks 1]

Results in results/slip_depth_lem/<scene>_h<size>_d<depth>/ (a finished run is reused while
its kept deck is the one the command would write now). Needs build/argine.
"""

import argparse
import concurrent.futures
import csv
import math
import os
import sys

import yaml

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import strength_sensitivity as ss  # noqa: E402  (one definition of the weakening)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def deck_text(path, h, factor, duration, interval, depth, ground, name):
    """The weakened deck at element size h with the search restricted to `depth` (m)."""
    deck = yaml.safe_load(ss.deck_text(path, h, factor, duration, name))
    argine = deck["argine"]
    list(argine["Stages"].values())[-1]["Output Interval (s)"] = interval
    argine["Factor Of Safety"] = {"Minimum Depth (m)": depth, "Slice Table": False,
                                  "Grid Count": 15, "Ground Surface (m)": ground,
                                  "Cell Size (m)": 0.1}
    return yaml.safe_dump(deck, sort_keys=False, default_flow_style=None, width=1000)


def initial_ground(path):
    """The K0 procedure's ground line of the deck (x0, y0, x1, y1, ...)."""
    with open(path) as handle:
        return list(yaml.safe_load(handle)["argine"]["Initialisation"]["Ground Surface (m)"])


def run(argine, path, h, depth, args, ground, out):
    scene = os.path.splitext(os.path.basename(path))[0]
    name = f"{scene}_h{h:g}_d{depth:g}"
    directory = os.path.join(out, name)
    text = deck_text(path, h, args.factor, args.duration, args.interval, depth, ground, name)
    if not ss.reusable(directory, name, text):
        status = ss.run_deck_text(argine, path, text, directory, name, args.ranks, ".slip_depth_")
        if status != 0:
            print(f"{name}: argine failed ({status})", file=sys.stderr)
    return h, depth, directory, name


def circle_at(directory, name, time):
    """(F, greatest depth, entry x) of the critical circle at `time` (s), or None."""
    path = os.path.join(directory, name + "_factor_of_safety.csv")
    if not os.path.exists(path):
        return None
    for row in csv.DictReader(open(path)):
        if abs(float(row["time"]) - time) < 1e-9:
            return (float(row["factor_of_safety"]), float(row["max_depth"]),
                    float(row["entry_x"]))
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("deck")
    parser.add_argument("--sizes", type=float, nargs="+", required=True)
    parser.add_argument("--depths", type=float, nargs="+", required=True)
    parser.add_argument("--factor", type=float, default=0.75)
    parser.add_argument("--duration", type=float, default=0.2,
                        help="the last stage's Duration (s)")
    parser.add_argument("--interval", type=float, default=0.1,
                        help="the last stage's Output Interval (s)")
    parser.add_argument("--time", type=float, default=1.1,
                        help="the output (simulation time, s) the table reads")
    ss.add_run_options(parser)
    args = parser.parse_args()
    path = os.path.abspath(args.deck)
    ground = initial_ground(path)
    out = os.path.join(ROOT, "results", "slip_depth_lem")
    cases = [(h, d) for h in args.sizes for d in args.depths]
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        done = list(pool.map(lambda c: run(args.argine, path, c[0], c[1], args, ground, out),
                             cases))
    print(f"Bishop's F at t = {args.time:g} s, f = {args.factor:g}; each restriction's critical "
          "circle: F (its change from the mesh's lowest), greatest depth, entry x")
    print("| h (m) | min depth (m) | F | vs lowest | greatest depth (m) | entry x (m) |")
    print("|---|---:|---:|---:|---:|---:|")
    for h in args.sizes:
        rows = [(d, circle_at(directory, name, args.time))
                for hh, d, directory, name in done if hh == h]
        found = [r for _, r in rows if r]
        lowest = min(r[0] for r in found) if found else math.nan
        for d, r in rows:
            if r is None:
                print(f"| {h:g} | {d:g} | – | | | |")
                continue
            print(f"| {h:g} | {d:g} | {r[0]:.4f} | {100 * (r[0] / lowest - 1):+.2f} % | "
                  f"{r[1]:.3f} | {r[2]:.3f} |")


if __name__ == "__main__":
    main()

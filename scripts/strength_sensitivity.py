#!/usr/bin/env python3
"""Run-out against the soil's strength, on several meshes (issue P11 item 3).

A slide that stops by itself is a margin problem: it moves until the geometry it reaches is
stable again, so how far it runs is set by how far the strength lies below what the slope
needed. This study multiplies the effective cohesion c' and tan(phi') of every Mohr-Coulomb
material in the deck's last stage by a strength factor f (f < 1 weaker, as in strength
reduction with F = 1/f), runs the deck at each element size and each f, nothing else
changed, and tabulates the probes and the run-out quantities of scripts/levee_convergence.py
against f. Per mesh it gives the slope of the run-out against f (how many metres of
run-out one per cent of strength is worth) and f_c, the factor at which the slide vanishes
(the crest probe below --vanish metres): a mesh that moves the run-out by d moves f_c by
about d / slope, and comparing f_c across meshes says whether a mesh changes the slide's
driving state or only its resistance.

  scripts/strength_sensitivity.py DECK --sizes 0.4 0.2 0.1 --factors 0.9 0.95 1 1.05 1.1
      [--duration S] [--times T ...] [--flow-rule deck|associated] [--jobs N] [--ranks R]
      [--figure PNG]

Each run's deck is a copy beside DECK (relative file keys keep working, removed afterwards)
with the element size, the last stage's Material Changes and Duration, a Factor Of Safety
section (Bishop, critical circle at every output, unless the deck has one) and the output
name changed. --ranks R runs each deck on R MPI ranks (mpiexec; the same bits as one rank,
doc/parallel.md). Results in results/strength_sensitivity/<scene>_h<size>_f<factor>/, with
the deck that made them (<name>.deck.yaml). A run whose log says it finished is not repeated
while its kept deck is the one the command would write now; a run whose deck changed is made
again, and one made before decks were kept is reused with a warning (its deck unchecked).
Needs build/argine (./scripts/build.sh).
"""

import argparse
import concurrent.futures
import math
import os
import subprocess
import sys

import numpy as np
import yaml

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import levee_convergence as lc  # noqa: E402  (one definition of the run-out quantities)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def strength_in_last_stage(deck):
    """c' (Pa) and phi' (deg) of each Mohr-Coulomb material as the last stage starts: the
    material's own values with every stage's Material Changes applied in order."""
    materials, stages = deck["argine"]["Materials"], deck["argine"]["Stages"]
    out = {}
    for name, material in materials.items():
        solid = material.get("Solid", {})
        if "Mohr-Coulomb" not in str(solid.get("Model", "")):
            continue
        c, phi = solid.get("Cohesion (Pa)", 0.0), solid["Friction Angle (deg)"]
        for stage in stages.values():
            change = (stage.get("Material Changes") or {}).get(name, {})
            c = change.get("Cohesion (Pa)", c)
            phi = change.get("Friction Angle (deg)", phi)
        out[name] = (float(c), float(phi))
    return out


def deck_text(path, h, f, duration, name, associated=False):
    """The text of the deck at element size h with strength factor f in its last stage (the
    values: c' to 6 and phi' to 10 significant digits); with `associated` the last stage
    also sets each material's dilatancy angle to its reduced phi' (associated flow from the
    state the stage starts from, as a strength reduction's associated trials)."""
    with open(path) as handle:
        deck = yaml.safe_load(handle)
    argine = deck["argine"]
    argine["Mesh"]["Generate"]["Element Size (m)"] = h
    strength = strength_in_last_stage(deck)
    last = list(argine["Stages"].values())[-1]
    changes = last.setdefault("Material Changes", {})
    for material, (c, phi) in strength.items():
        entry = changes.setdefault(material, {})
        entry["Cohesion (Pa)"] = float(f"{c * f:.6g}")
        entry["Friction Angle (deg)"] = float(
            f"{math.degrees(math.atan(math.tan(math.radians(phi)) * f)):.10g}")
        if associated:
            entry["Dilatancy Angle (deg)"] = entry["Friction Angle (deg)"]
    if duration is not None:
        last["Duration (s)"] = duration
    argine.setdefault("Factor Of Safety", {"Minimum Depth (m)": 0.5, "Slice Table": False})
    argine["Output"]["Name"] = name
    return yaml.safe_dump(deck, sort_keys=False, default_flow_style=None, width=1000)


def reusable(directory, name, text):
    """Whether the finished run in `directory` was made from the deck `text` (file comment)."""
    log = os.path.join(directory, name + ".log")
    if not (os.path.exists(log) and "simulated in" in open(log).read()):
        return False
    kept = os.path.join(directory, name + ".deck.yaml")
    if not os.path.exists(kept):
        print(f"{name}: made before decks were kept, reused unchecked", file=sys.stderr)
        return True
    with open(kept) as handle:
        if handle.read() == text:
            return True
    print(f"{name}: its deck changed since, made again", file=sys.stderr)
    return False


def add_run_options(parser):
    """The options of how the weakened decks run (run_deck_text): runs at once, MPI ranks a
    run, and the argine binary."""
    parser.add_argument("--jobs", type=int, default=1, help="runs at once")
    parser.add_argument("--ranks", type=int, default=1, help="MPI ranks a run")
    parser.add_argument("--argine", default=os.path.join(ROOT, "build", "argine"))


def run_deck_text(argine, path, text, directory, name, ranks=1, prefix=".run_"):
    """Runs the deck `text` as a copy beside the deck at `path` (relative file keys keep
    working; removed afterwards) into `directory`, keeping the deck there as
    <name>.deck.yaml and the log as <name>.log; argine's exit status."""
    os.makedirs(directory, exist_ok=True)
    copy = os.path.join(os.path.dirname(path), f"{prefix}{name}.yaml")
    with open(copy, "w") as handle:
        handle.write(text)
    with open(os.path.join(directory, name + ".deck.yaml"), "w") as handle:
        handle.write(text)
    env = dict(os.environ)
    if ranks > 1 and os.geteuid() == 0:  # Open MPI refuses root unless told (as convergence.sh)
        env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    try:
        with open(os.path.join(directory, name + ".log"), "w") as handle:
            launcher = ["mpiexec", "-n", str(ranks), "--oversubscribe"] if ranks > 1 else []
            return subprocess.call(launcher + [argine, "run", copy, "--output", directory],
                                   stdout=handle, stderr=subprocess.STDOUT, env=env)
    finally:
        os.remove(copy)


def run(argine, path, h, f, duration, out, existing=False, ranks=1, associated=False):
    scene = os.path.splitext(os.path.basename(path))[0]
    name = f"{scene}_h{h:g}_f{f:g}" + ("_associated" if associated else "")
    directory = os.path.join(out, name)
    log = os.path.join(directory, name + ".log")
    text = deck_text(path, h, f, duration, name, associated)
    if existing or reusable(directory, name, text):
        return h, f, directory, name
    status = run_deck_text(argine, path, text, directory, name, ranks, ".strength_")
    if status != 0:
        print(f"h = {h:g} m, f = {f:g}: argine failed ({status}), see {log}", file=sys.stderr)
    return h, f, directory, name


def lowest_factor_of_safety(directory, name, start, end):
    """Lowest Bishop F of the deck's Factor Of Safety CSV over outputs in (start, end]."""
    path = os.path.join(directory, name + "_factor_of_safety.csv")
    if not os.path.exists(path):
        return math.nan
    data = np.atleast_1d(np.genfromtxt(path, delimiter=",", names=True))
    inside = (data["time"] > start + 1e-9) & (data["time"] <= end + 1e-9)
    return float(data["factor_of_safety"][inside].min()) if inside.any() else math.nan


def vanishing_factor(factors, crest, vanish):
    """f at which the crest probe's |u| falls to `vanish` (linear between the bracketing
    factors); nan when no factor brackets it."""
    for (f0, d0), (f1, d1) in zip(zip(factors, crest), zip(factors[1:], crest[1:])):
        if d0 >= vanish > d1:
            return f0 + (d0 - vanish) * (f1 - f0) / (d0 - d1)
    return math.nan


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("deck")
    parser.add_argument("--sizes", type=float, nargs="+", default=[0.4, 0.2, 0.1])
    parser.add_argument("--factors", type=float, nargs="+",
                        default=[0.9, 0.95, 1.0, 1.05, 1.1])
    parser.add_argument("--duration", type=float,
                        help="the last stage's Duration (s); default: the deck's")
    parser.add_argument("--times", type=float, nargs="+", default=[2.0, 3.0],
                        help="times after the event started (s) to tabulate")
    parser.add_argument("--start", type=float, default=1.0,
                        help="simulation time at which the event starts (s)")
    parser.add_argument("--window", type=float, default=0.5,
                        help="the lowest factor of safety is taken over this long after --start (s)")
    parser.add_argument("--vanish", type=float, default=0.05,
                        help="crest probe |u| (m) below which the slide counts as vanished")
    parser.add_argument("--flow-rule", choices=["deck", "associated"], default="deck",
                        help="the last stage's dilatancy: the deck's, or each material's "
                             "reduced phi' (associated); runs named ..._associated")
    add_run_options(parser)
    parser.add_argument("--existing", action="store_true",
                        help="run nothing: tabulate the (size, factor) pairs whose results exist")
    parser.add_argument("--figure")
    args = parser.parse_args()
    if args.ranks > 1 and os.geteuid() == 0:
        os.environ.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    if not args.existing and not os.path.exists(args.argine):
        sys.exit(f"{args.argine}: not built (run ./scripts/build.sh)")
    out = os.path.join(ROOT, "results", "strength_sensitivity")
    factors = sorted(args.factors)
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        jobs = [pool.submit(run, args.argine, os.path.abspath(args.deck), h, f, args.duration, out,
                            args.existing, args.ranks, args.flow_rule == "associated")
                for h in args.sizes for f in factors]
        done = [job.result() for job in jobs]
    last = max(args.times)
    results = {}
    for h, f, directory, name in done:
        path = os.path.join(directory, name + "_points.e")
        if not os.path.exists(path):
            continue
        time, x0, y0, v = lc.right_half(*lc.read_points(path))
        k = int(np.argmin(np.abs(time - (args.start + last))))
        if abs(time[k] - (args.start + last)) > 1e-6:
            continue
        row = lc.measure(x0, y0, v["displ_x"][k], v["displ_y"][k], v["volume"][k])
        probes = lc.probe_displacements(directory, name, [args.start + t for t in args.times])
        for t in args.times:
            for q, value in probes.get(args.start + t, {}).items():
                row[f"{q} at {t:g} s"] = value
        row["lowest F"] = lowest_factor_of_safety(directory, name, args.start,
                                                  args.start + args.window)
        row["wall (s)"] = lc.wall_time(directory, name)
        results[(h, f)] = row
    sizes = sorted({h for h, _ in results}, reverse=True)
    crest_key = f"probe MP1_crest |u| at {last:g} s"
    keys = sorted({q for row in results.values() for q in row},
                  key=lambda q: (not q.startswith("probe"), q))
    print(f"values {last:g} s after the event started (probes at every --times)")
    for h in sizes:
        print(f"\nh = {h:g} m")
        print("| quantity | " + " | ".join(f"f = {f:g}" for f in factors) + " |")
        print("|---|" + "---:|" * len(factors))
        for q in keys:
            print(f"| {q} | " + " | ".join(
                f"{results[(h, f)].get(q, math.nan):.3f}" if (h, f) in results else "-"
                for f in factors) + " |")
    print("\n| h (m) | crest probe at f = 1 (m) | slope d|u|/df around f = 1 (m) | f_c "
          f"(crest probe < {args.vanish:g} m) | lowest F over {args.window:g} s at f = 1 |")
    print("|---:|---:|---:|---:|---:|")
    summary = {}
    for h in sizes:
        have = [f for f in factors if (h, f) in results]
        crest = [results[(h, f)].get(crest_key, math.nan) for f in have]
        near = [f for f in have if abs(f - 1.0) <= 0.051]
        slope = math.nan
        if len(near) >= 2:
            d = [results[(h, f)][crest_key] for f in near]
            slope = float(np.polyfit(near, d, 1)[0])
        fc = vanishing_factor(have, crest, args.vanish)
        base = results.get((h, 1.0), {})
        summary[h] = (have, crest, fc)
        print(f"| {h:g} | {base.get(crest_key, math.nan):.3f} | {slope:.2f} | {fc:.3f} | "
              f"{base.get('lowest F', math.nan):.3f} |")
    if args.figure:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, axes = plt.subplots(1, len(args.times), figsize=(4.2 * len(args.times), 3.6),
                                 layout="constrained", sharey=True, squeeze=False)
        for ax, t in zip(axes[0], args.times):
            key = f"probe MP1_crest |u| at {t:g} s"
            for h in sizes:
                have, _, fc = summary[h]
                have = [f for f in have if key in results[(h, f)]]
                label = f"h = {h:g} m" + (f", f_c = {fc:.3f}"
                                          if t == last and not math.isnan(fc) else "")
                ax.plot(have, [results[(h, f)][key] for f in have], "o-", label=label)
            ax.axvline(1.0, color="0.6", lw=0.8)
            ax.set_xlabel("strength factor f (c' and tan phi' times f)")
            ax.set_title(f"{t:g} s after the start", fontsize=9)
            ax.legend(fontsize=7)
        axes[0][0].set_ylabel("crest probe MP1 |u| (m)")
        fig.savefig(args.figure, dpi=110)
        print(f"\nwrote {args.figure}")


if __name__ == "__main__":
    main()

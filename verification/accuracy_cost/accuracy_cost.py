#!/usr/bin/env python3
"""Accuracy against cost of the explicit and implicit paths on V3 and V4 (scripts/accuracy_cost.sh).

  accuracy_cost.py merge-v3 --work DIR --output v3_cost.csv
  accuracy_cost.py merge-v4 --work DIR --output v4_cost.csv
  accuracy_cost.py plot --results DIR --figures DIR

merge-v3 reads the implicit study (infiltration_column_study.csv of
infiltration_column_verification) and the explicit runs (v3_explicit_*_cost.csv of
infiltration_column_explicit_verification); merge-v4 reads the implicit study
(v4_implicit_cost.csv of levee_seepage_implicit_verification --study) and the comparison of
the explicit runs with the same reference (v4_compare_cost.csv). Both write one row per run:
case, path, run, element_size, max_step, theta, mass_scaling, cpu_seconds, wall_seconds,
steps, p_error, s_error (fractions of the reference's range), and for the V3 explicit runs
also the element-mean errors. The errors are computed by the C++ drivers; this script only
gathers and draws them.
"""
import argparse
import csv
import glob
import os

COLUMNS = ["case", "path", "run", "element_size", "max_step", "theta", "mass_scaling",
           "cpu_seconds", "wall_seconds", "steps", "p_error", "s_error", "p_error_means",
           "s_error_means"]


def read(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def write(path, rows):
    with open(path, "w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=COLUMNS, extrasaction="ignore")
        writer.writeheader()
        for row in rows:
            writer.writerow({key: row.get(key, "") for key in COLUMNS})
    print(f"accuracy_cost: {len(rows)} runs in {path}")


def merge_v3(work, output):
    rows = []
    for r in read(os.path.join(work, "infiltration_column_study.csv")):
        rows.append({"case": "V3", "path": "implicit",
                     "run": f"implicit h {r['element_size']} dt<={r['max_step']} theta {r['theta']}",
                     "element_size": r["element_size"], "max_step": r["max_step"],
                     "theta": r["theta"], "cpu_seconds": r["cpu_seconds"],
                     "wall_seconds": r["wall_seconds"], "steps": r["steps"],
                     "p_error": r["error_p"], "s_error": r["error_S"]})
    for path in sorted(glob.glob(os.path.join(work, "v3_explicit_*_cost.csv"))):
        for r in read(path):
            rows.append(dict(r, case="V3"))
    write(output, rows)


def merge_v4(work, output):
    rows = []
    for r in read(os.path.join(work, "v4_implicit_cost.csv")):
        rows.append(dict(r, case="V4"))
    for r in read(os.path.join(work, "v4_compare_cost.csv")):
        if r["path"] == "explicit":
            rows.append(dict(r, case="V4"))
    write(output, rows)


def plot(results, figures):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    # The bound of VERIFICATION.md and the quantities it is for: V3 p_L and S_L (2 % of
    # their range), V4 p_L only (3 % of the p_L range).
    charts = [("v3_cost.csv", "infiltration_column_accuracy_cost.png", 0.02, ("p", "s"),
               "V3 infiltration column, 600 s"),
              ("v4_cost.csv", "levee_seepage_accuracy_cost.png", 0.03, ("p",),
               "V4 levee seepage, 300 s")]
    for name, figure, bound, bounded, title in charts:
        path = os.path.join(results, name)
        if not os.path.exists(path):
            continue
        rows = [r for r in read(path) if r["cpu_seconds"] and r["p_error"]]
        fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
        for ax, key, label in ((axes[0], "p", "p_L"), (axes[1], "s", "S_L")):
            implicit = [r for r in rows if r["path"] == "implicit"]
            sizes = sorted({r["element_size"] for r in implicit}, key=float, reverse=True)
            colours = dict(zip(sizes, ["#9ecae1", "#4292c6", "#08519c", "#08306b"]))
            for size in sizes:
                for theta, marker in (("1", "o"), ("0.5", "D")):
                    sel = [r for r in implicit if r["element_size"] == size
                           and float(r["theta"]) == float(theta)]
                    if sel:
                        ax.loglog([float(r["cpu_seconds"]) for r in sel],
                                  [100 * float(r[f"{key}_error"]) for r in sel], marker,
                                  color=colours[size], ls="none",
                                  label=f"implicit h {size} m, theta {theta}")
            # V4: runs named *unstabilised* use the thesis' scheme (no liquid head
            # stabilisation); the others the V4 deck's.
            every_explicit = [r for r in rows if r["path"] == "explicit"]
            plain = [r for r in every_explicit if "unstabilised" in r["run"]]
            explicit = [r for r in every_explicit if "unstabilised" not in r["run"]]
            means = [r for r in explicit if r.get("p_error_means")]
            ax.loglog([float(r["cpu_seconds"]) for r in explicit],
                      [100 * float(r[f"{key}_error"]) for r in explicit], "s", color="tab:red",
                      ls="none", label="explicit (point values)" if means else
                      "explicit" if not plain else "explicit, head stabilisation 0.1")
            if plain:
                ax.loglog([float(r["cpu_seconds"]) for r in plain],
                          [100 * float(r[f"{key}_error"]) for r in plain], "x",
                          color="tab:orange", ls="none",
                          label="explicit, thesis scheme (unstabilised)")
            if means:
                ax.loglog([float(r["cpu_seconds"]) for r in means],
                          [100 * float(r[f"{key}_error_means"]) for r in means], "s",
                          mfc="none", color="tab:red", label="explicit (element means)")
            for r in explicit + plain:
                ax.annotate(f"h {r['element_size']}, ms {float(r['mass_scaling']):.0e}",
                            (float(r["cpu_seconds"]), 100 * float(r[f"{key}_error"])),
                            fontsize=6, xytext=(3, 2), textcoords="offset points")
            if key in bounded:
                ax.axhline(100 * bound, color="grey", lw=0.8, ls="--",
                           label=f"bound {100 * bound:.0f} %")
            ax.set_xlabel("CPU time of the run (s) = wall time on an idle core")
            ax.set_ylabel(f"max |{label} - reference| / range (%)")
            ax.legend(fontsize=6)
        fig.suptitle(f"{title}: error against cost; explicit: mesh h (m), mass scaling ms; "
                     "implicit: h, steps, theta", fontsize=9)
        fig.tight_layout()
        fig.savefig(os.path.join(figures, figure), dpi=120)
        print(f"accuracy_cost: {os.path.join(figures, figure)}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("command", choices=["merge-v3", "merge-v4", "plot"])
    parser.add_argument("--work")
    parser.add_argument("--output")
    parser.add_argument("--results")
    parser.add_argument("--figures")
    args = parser.parse_args()
    if args.command == "merge-v3":
        merge_v3(args.work, args.output)
    elif args.command == "merge-v4":
        merge_v4(args.work, args.output)
    else:
        plot(args.results, args.figures)


if __name__ == "__main__":
    main()

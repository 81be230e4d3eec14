#!/usr/bin/env python3
"""V5 critical time-step study: merges the shard CSV files of argine_stability, draws the
charts (doc/figures/stability_*.png) and prints the summary tables (markdown) of
doc/stability.md.

  plot_stability.py --merge DIR --results RESULTS --figures FIGURES
  plot_stability.py --results RESULTS --figures FIGURES     (re-plot results/stability_cases.csv)
"""
import argparse
import csv
import glob
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

CRITERIA = ["cfl_dry", "cfl_undrained", "consolidation", "infiltration", "liquid", "mixture",
            "coupled", "mieremet", "mieremet_liquid_drag"]
LABELS = {"cfl_dry": "CFL dry (4.62)", "cfl_undrained": "CFL undrained (4.64)",
          "consolidation": "consolidation (4.61)", "infiltration": "infiltration (4.63)",
          "liquid": "liquid (T4.4)", "mixture": "mixture (T4.4)", "coupled": "coupled (T4.4)",
          "mieremet": "Mieremet adapted (4.67)", "mieremet_saturated": "Mieremet saturated",
          "mieremet_liquid_drag": "Mieremet liquid drag"}
STYLE = {"cfl_dry": ("0.6", ":"), "cfl_undrained": ("0.3", ":"), "consolidation": ("tab:olive", "--"),
         "infiltration": ("tab:cyan", "--"), "liquid": ("tab:blue", "-."), "mixture": ("tab:purple", "-."),
         "coupled": ("tab:red", "-"), "mieremet": ("tab:green", "-"),
         "mieremet_liquid_drag": ("tab:orange", "-"),
         "mieremet_saturated": ("k", "--")}


def number(row, key):
    return float(row[key])


def read(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def merge(directory, out):
    rows, header = [], None
    for path in sorted(glob.glob(os.path.join(directory, "stability_*of*.csv"))):
        with open(path) as f:
            reader = csv.DictReader(f)
            header = reader.fieldnames
            rows += list(reader)
    key = lambda r: (r["family"], r["soil"], number(r, "porosity"), number(r, "youngs_modulus_Pa"),
                     -number(r, "permeability_m2"), -number(r, "target_saturation"))
    rows.sort(key=key)
    with open(out, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=header)
        writer.writeheader()
        writer.writerows(rows)
    return rows


def production(row):
    """The proposed production criterion: Mieremet liquid drag (4.67, b and d of Sec. 7.2, the
    drag q_L of Eq. 7.7 once in a), the step an automatic run takes = its minimum over the
    states of the run (TimeStepControl recomputes it every step)."""
    return min(number(row, "crit_mieremet_liquid_drag"), number(row, "run_mieremet_liquid_drag"))


def label_of(row):
    return "n=%g, E=%g kPa" % (number(row, "porosity"), number(row, "youngs_modulus_Pa") / 1e3)


def soil_chart(rows, soil, figures, family="saturation", tag=None):
    sel = [r for r in rows if r["family"] == family and r["soil"] == soil]
    groups = sorted({(number(r, "porosity"), number(r, "youngs_modulus_Pa")) for r in sel})
    if not groups:
        return
    fig, axes = plt.subplots(1, len(groups), figsize=(4.2 * len(groups), 4.2), sharey=True,
                             squeeze=False)
    for ax, (n, e) in zip(axes[0], groups):
        g = [r for r in sel if number(r, "porosity") == n and number(r, "youngs_modulus_Pa") == e]
        g.sort(key=lambda r: number(r, "saturation"))
        s = [number(r, "saturation") for r in g]
        for c in CRITERIA + ["mieremet_saturated"]:
            color, ls = STYLE[c]
            ax.plot(s, [number(r, "crit_" + c) for r in g], ls, color=color, lw=1.2,
                    label=LABELS[c])
        ax.plot(s, [number(r, "run_mieremet") for r in g], "v", color="tab:green", ms=5,
                mfc="none", label="Mieremet adapted, min over run")
        ax.plot(s, [production(r) for r in g], "^", color="tab:orange", ms=5,
                mfc="none", label="Mieremet liquid drag, min over run (production)")
        ax.plot(s, [number(r, "dt_c_s") for r in g], "o", color="k", ms=6,
                label="empirical $\\Delta t_c$")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("$S_L$ (initial)")
        ax.set_title("%s, n=%g, E=%g kPa" % (soil, n, e / 1e3), fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
    axes[0][0].set_ylabel("$\\Delta t$ (s)")
    axes[0][-1].legend(fontsize=6, loc="lower right")
    fig.tight_layout()
    fig.savefig(os.path.join(figures, "stability_%s.png" % (tag or soil)), dpi=110)
    plt.close(fig)


def ratio_chart(rows, figures):
    sel = [r for r in rows if r["family"] in ("saturation", "permeability", "mesh", "quick")
           and number(r, "dt_c_s") > 0]
    names = CRITERIA + ["mieremet_saturated", "production"]
    fig, axes = plt.subplots(3, 4, figsize=(16, 10), sharex=True)
    colors = {"sand": "tab:orange", "silt": "tab:brown", "clay": "tab:blue"}
    for ax, c in zip(axes.flat, names):
        for r in sel:
            pred = production(r) if c == "production" else number(r, "crit_" + c)
            marker = {"saturation": "o", "permeability": "s", "mesh": "^", "quick": "o"}[r["family"]]
            ax.plot(number(r, "saturation"), number(r, "dt_c_s") / pred, marker, ms=3,
                    color=colors[r["soil"]], alpha=0.7)
        ax.axhline(1, color="k", lw=1)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(LABELS.get(c, "production: Mieremet liquid drag, min over run"), fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
    for ax in axes.flat[len(names):]:
        ax.axis("off")
    for ax in axes[-1]:
        ax.set_xlabel("$S_L$ (initial)")
    for ax in axes[:, 0]:
        ax.set_ylabel("empirical / predicted")
    fig.suptitle("empirical critical step / criterion (below 1 = criterion unsafe); "
                 "o 0.05 m, s permeability sweep, ^ 0.5 m; orange sand, brown silt, blue clay",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(figures, "stability_ratio.png"), dpi=110)
    plt.close(fig)


def permeability_chart(rows, figures):
    sel = [r for r in rows if r["soil"] == "silt" and r["family"] in ("saturation", "permeability")
           and number(r, "youngs_modulus_Pa") == 1e7]
    if not sel:
        return
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.2), sharey=True)
    levels = sorted({number(r, "target_saturation") for r in sel}, reverse=True)
    cmap = plt.get_cmap("viridis")
    for ax, n in zip(axes, (0.4, 0.6)):
        for i, s in enumerate(levels):
            g = sorted([r for r in sel if number(r, "porosity") == n and
                        number(r, "target_saturation") == s],
                       key=lambda r: number(r, "permeability_m2"))
            k = [number(r, "permeability_m2") for r in g]
            col = cmap(i / max(len(levels) - 1, 1))
            ax.plot(k, [number(r, "dt_c_s") for r in g], "o", color=col, label="S_L=%g" % s)
            ax.plot(k, [number(r, "crit_coupled") for r in g], "-", color=col, lw=0.8)
            ax.plot(k, [production(r) for r in g], "--", color=col, lw=0.8)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("intrinsic permeability (m$^2$)")
        ax.set_title("silt, n=%g, E=1e4 kPa: o empirical, - coupled, -- production" % n,
                     fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("$\\Delta t$ (s)")
    axes[1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(figures, "stability_permeability.png"), dpi=110)
    plt.close(fig)


def normalised_chart(rows, figures):
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    marks = {(0.4, 1e7): "o", (0.6, 1e7): "D", (0.4, 5e7): "s", (0.6, 5e7): "x"}
    colors = {"sand": "tab:orange", "silt": "tab:brown", "clay": "tab:blue"}
    for r in rows:
        if r["family"] not in ("saturation", "mesh"):
            continue
        m = marks[(number(r, "porosity"), number(r, "youngs_modulus_Pa"))]
        col = "k" if r["family"] == "mesh" else colors[r["soil"]]
        ax.plot(number(r, "saturation"), number(r, "dt_c_s") / number(r, "crit_mieremet_saturated"),
                m, color=col, mfc="none" if r["family"] == "mesh" else col, ms=5, alpha=0.8)
    ax.set_xscale("log")
    ax.set_xlabel("$S_L$ (initial)")
    ax.set_ylabel("empirical $\\Delta t_c$ / Mieremet saturated")
    ax.set_title("o n0.4 E1e4, D n0.6 E1e4, s n0.4 E5e4, x n0.6 E5e4;\n"
                 "orange sand, brown silt, blue clay (0.05 m); black open: silt 0.5 m", fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(figures, "stability_normalised.png"), dpi=110)
    plt.close(fig)


def summary(rows):
    sel = [r for r in rows if r["family"] in ("saturation", "permeability", "mesh", "quick")
           and number(r, "dt_c_s") > 0]
    none = [r for r in rows if number(r, "dt_c_s") <= 0]
    everything = [r for r in rows if r["family"] != "realistic"]
    out = ["cases with a critical step: %d; without any stable step: %d (%s)" % (
        len(sel), len(none), ", ".join("%s %s n=%g S_L=%.3g" % (
            r["family"], r["soil"], number(r, "porosity"), number(r, "saturation")) for r in none)),
        "",
        "| criterion | cases | unsafe (pred > dt_c) | min dt_c/pred | median | max |",
           "|---|---|---|---|---|---|"]

    def line(name, preds):
        ratios = sorted(number(r, "dt_c_s") / p for r, p in zip(sel, preds)
                        if number(r, "dt_c_s") > 0 and p > 0)
        if not ratios:
            return
        unsafe = sum(1 for q in ratios if q < 1)
        out.append("| %s | %d | %d | %.3f | %.3f | %.3f |" % (
            name, len(ratios), unsafe, ratios[0], ratios[len(ratios) // 2], ratios[-1]))

    for c in CRITERIA + ["mieremet_saturated"]:
        line(LABELS[c] + ", initial state", [number(r, "crit_" + c) for r in sel])
    for c in CRITERIA:
        line(LABELS[c] + ", min over run", [min(number(r, "crit_" + c), number(r, "run_" + c))
                                           for r in sel])
    line("min(coupled, Mieremet adapted), initial", [min(number(r, "crit_coupled"),
                                                         number(r, "crit_mieremet")) for r in sel])
    line("production x safety 0.5", [0.5 * production(r) for r in sel])
    line("min(production, consolidation over run) (proposed default set)",
         [min(production(r), number(r, "crit_consolidation"), number(r, "run_consolidation"))
          for r in sel])
    line("proposed default set x 0.5", [0.5 * min(production(r), number(r, "crit_consolidation"),
                                                  number(r, "run_consolidation")) for r in sel])
    line("default before (min(Mieremet adapted, consolidation), over run) x 0.5",
         [0.5 * min(number(r, "crit_mieremet"), number(r, "run_mieremet"),
                    number(r, "crit_consolidation"), number(r, "run_consolidation")) for r in sel])
    gain = sorted(production(r) / number(r, "crit_mieremet_saturated") for r in sel)
    waste = sorted(number(r, "dt_c_s") / production(r) for r in sel)
    out.append("")
    out.append("empirical / production: min %.3f, median %.3f, max %.3f" % (
        waste[0], waste[len(waste) // 2], waste[-1]))
    out.append("")
    out.append("production (Mieremet liquid drag, min over run) / Mieremet saturated: min %.3f, "
               "median %.3f, max %.3f over %d cases" % (gain[0], gain[len(gain) // 2], gain[-1],
                                                         len(gain)))
    # dt_c per case group against S_L (ms), and the production ratio dt_c / production.
    levels = sorted({number(r, "target_saturation") for r in sel}, reverse=True)
    groups = []
    for r in sel:
        g = (r["family"], r["soil"], number(r, "porosity"), number(r, "youngs_modulus_Pa"),
             number(r, "permeability_m2"), number(r, "element_size_m"))
        if g not in groups:
            groups.append(g)
    for title, value in (("empirical dt_c (ms); '-' = no stable step", lambda r: "%.4g" % (
            1e3 * number(r, "dt_c_s"))),
                         ("empirical dt_c / production step (Mieremet liquid drag, min over run)",
                          lambda r: "%.2f" % (number(r, "dt_c_s") / production(r)))):
        out.append("")
        out.append(title + ":")
        out.append("")
        out.append("| set | soil | n | E (kPa) | kappa (m2) | L (m) | " +
                   " | ".join("S_L %g" % s for s in levels) + " |")
        out.append("|---" * (6 + len(levels)) + "|")
        for g in groups:
            cells = []
            for lv in levels:
                hit = [r for r in rows if (r["family"], r["soil"], number(r, "porosity"),
                                           number(r, "youngs_modulus_Pa"),
                                           number(r, "permeability_m2"),
                                           number(r, "element_size_m")) == g
                       and number(r, "target_saturation") == lv]
                cells.append(value(hit[0]) if hit and number(hit[0], "dt_c_s") > 0 else "-")
            out.append("| %s | %s | %g | %g | %g | %g | " % (g[0], g[1], g[2], g[3] / 1e3, g[4],
                                                            g[5]) + " | ".join(cells) + " |")
    real = [r for r in rows if r["family"] == "realistic"]
    if real:
        out.append("")
        out.append("| realistic clay (k=%.3g m/s, L=%g m, K_L=%.3g Pa) S_L | dt_c (s) | Mieremet "
                   "liquid drag (s) | s/step (80 points) | steps for 1 h | wall for 1 h |" % (
                       number(real[0], "conductivity_m_per_s"), number(real[0], "element_size_m"),
                       number(real[0], "liquid_bulk_modulus_Pa")))
        out.append("|---|---|---|---|---|---|")
        for r in real:
            steps = 3600 / number(r, "dt_c_s")
            wall = steps * number(r, "seconds_per_step")
            out.append("| %.3g | %.3g | %.3g | %.3g | %.2g | %.2g years |" % (
                number(r, "saturation"), number(r, "dt_c_s"), production(r),
                number(r, "seconds_per_step"), steps, wall / 3.15e7))
    return "\n".join(out)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--merge", default="")
    parser.add_argument("--results", required=True)
    parser.add_argument("--figures", required=True)
    args = parser.parse_args()
    os.makedirs(args.results, exist_ok=True)
    os.makedirs(args.figures, exist_ok=True)
    path = os.path.join(args.results, "stability_cases.csv")
    rows = merge(args.merge, path) if args.merge else read(path)
    for soil in ("sand", "silt", "clay"):
        soil_chart(rows, soil, args.figures)
    soil_chart(rows, "silt", args.figures, family="mesh", tag="silt_mesh_0.5m")
    ratio_chart(rows, args.figures)
    permeability_chart(rows, args.figures)
    normalised_chart(rows, args.figures)
    text = summary(rows)
    with open(os.path.join(args.results, "stability_summary.md"), "w") as f:
        f.write(text + "\n")
    print(text)


if __name__ == "__main__":
    main()

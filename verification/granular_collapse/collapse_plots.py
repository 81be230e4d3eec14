"""Figures of the V7 study (called by collapse_study.py): granular_collapse_*.png."""
import csv
import os

import numpy as np

import collapse_reference as ref
from collapse_results import smoothed

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

MESH_COLOURS = {10: "#9ecae1", 20: "#3182bd", 40: "#08306b"}
RATIO_COLOURS = {0.5: "#1b9e77", 1.0: "#d95f02", 2.0: "black", 4.0: "#e7298a", 6.0: "#66a61e"}
SCHEME_STYLE = {("linear", "FLIP"): ("tab:orange", "v"), ("linear", "APIC"): ("tab:red", "^"),
                ("linear", "TPIC"): ("tab:pink", "P"),
                ("GIMP", "FLIP"): ("tab:olive", "<"), ("GIMP", "APIC"): ("tab:green", ">"),
                ("GIMP", "TPIC"): ("tab:cyan", "X"),
                ("B-spline", "FLIP"): ("tab:purple", "s"), ("B-spline", "APIC"): ("tab:blue", "o"),
                ("B-spline", "TPIC"): ("tab:brown", "D")}


def read_profile(folder, tag, suffix="_profile.csv"):
    path = os.path.join(folder, tag + suffix)
    if not os.path.exists(path):
        return None
    with open(path, newline="") as handle:
        rows = list(csv.reader(handle))[1:]
    data = np.array(rows, float)
    return data[:, 0], data[:, 1]


def tag(a, cells, shape, transfer):
    return f"collapse_a{a:g}_h{cells}_{shape}_{transfer}"


def draw_laws(ax_r, ax_h):
    a = np.logspace(np.log10(0.3), np.log10(10), 200)
    low, high = ref.runout_band(a)
    ax_r.fill_between(a, low, high, color="0.88", label="accepted band (SOURCES.md)")
    for branch, lo, hi in ((ref.lube_runout_low, 0.3, 1.8), (ref.lube_runout_high, 2.8, 10)):
        s = (a >= lo) & (a <= hi)
        ax_r.plot(a[s], branch(a[s]), "k-", lw=1.2)
        t = (a > 1.8) & (a < 2.8)
        ax_r.plot(a[t], branch(a[t]), "k--", lw=0.8)
    ax_r.plot([], [], "k-", label="Lube et al. 2005 (sand, channel)")
    ax_r.plot(a, ref.nguyen_runout(a), ":", color="0.4",
              label="Nguyen et al. 2015 (true 2-D rods, phi 20 deg)")
    low, high = ref.height_band(a)
    ax_h.fill_between(a, low, high, color="0.88", label="accepted band")
    ax_h.plot(a, ref.lube_height(a), "k-", lw=1.2, label="Lube et al. 2005")
    ax_h.plot(a, ref.lajeunesse_height(a), "k-.", lw=0.8,
              label="Lajeunesse et al. 2005 (secondary)")
    ax_h.plot(a, ref.nguyen_height(a), ":", color="0.4", label="Nguyen et al. 2015 (true 2-D)")


NO_WALLS = " without side walls"  # collapse_run.py --without-side-walls: plane strain


def without_walls(rows, scheme, cells=20):
    """The decks' runs without their side walls, sorted by a: [(a, row)]."""
    return sorted((r["a"], r) for r in rows
                  if r["deck"].endswith(NO_WALLS) and (r["shape"], r["transfer"]) == scheme
                  and int(r["cells"]) == cells and r["status"] == "ok")


def runout_figure(groups, scheme, path, rows=()):
    fig, (ax_r, ax_h) = plt.subplots(1, 2, figsize=(11, 4.6), layout="constrained")
    draw_laws(ax_r, ax_h)
    staron = [(0.5, 0.938, 0.499), (1.42, 3.503, 0.748), (6.26, 12.454, 1.272)]
    ax_r.plot([s[0] for s in staron], [s[1] for s in staron], "x", color="0.3",
              label="Staron 2-D contact dynamics (numerical)")
    ax_h.plot([s[0] for s in staron], [s[2] for s in staron], "x", color="0.3")
    series = [(scheme, 20, "o", "tab:blue", f"argine {scheme[0]}/{scheme[1]}, L0/20 (default)"),
              (scheme, 40, "D", "#08306b", f"argine {scheme[0]}/{scheme[1]}, L0/40"),
              (("linear", "FLIP"), 20, "v", "tab:orange", "argine linear/FLIP, L0/20")]
    for (shape, transfer), cells, marker, colour, label in series:
        pts = sorted((a, m[cells]) for (a, s, t), m in groups.items()
                     if (s, t) == (shape, transfer) and cells in m)
        if not pts:
            continue
        a = [p[0] for p in pts]
        ax_r.plot(a, [p[1]["runout_front_fixed"] for p in pts], marker, color=colour, ms=6,
                  label=label + ": front")
        ax_r.plot(a, [p[1]["runout_L99"] for p in pts], marker, mfc="none", color=colour, ms=8,
                  label=label + ": L99")
        ax_h.plot(a, [p[1]["height"] for p in pts], marker, color=colour, ms=6, label=label)
    plane = without_walls(rows, scheme)
    if plane:
        label = f"argine {scheme[0]}/{scheme[1]}, L0/20, no side walls (plane strain)"
        a = [p[0] for p in plane]
        ax_r.plot(a, [p[1]["runout_front_fixed"] for p in plane], "s", color="tab:gray", ms=5,
                  label=label + ": front")
        ax_h.plot(a, [p[1]["height"] for p in plane], "s", color="tab:gray", ms=5, label=label)
    for ax, what in ((ax_r, "run-out (L_inf - L0) / L0"), (ax_h, "final height H_inf / L0")):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("aspect ratio a = H0 / L0")
        ax.set_ylabel(what)
        ax.grid(True, which="both", lw=0.3)
        ax.legend(fontsize=6.5, loc="upper left")
    ax_r.set_title("run-out: front (h >= 0.03 L0, filled) and L99 (open)", fontsize=9)
    ax_h.set_title("height at the wall", fontsize=9)
    fig.savefig(path, dpi=110)
    plt.close(fig)


def profiles_figure(groups, scheme, folder, path):
    ratios = sorted({a for (a, s, t) in groups if (s, t) == scheme})
    if not ratios:
        return
    fig, axes = plt.subplots(len(ratios), 1, figsize=(9, 2.1 * len(ratios) + 0.5),
                             layout="constrained")
    for ax, a in zip(np.atleast_1d(axes), ratios):
        ax.plot([0, 1, 1], [a, a, 0], ":", color="0.5", lw=0.8, label="initial column")
        if a >= 2:
            x, h = ref.lube_profile(a)
            ax.plot(x, h, "k-", lw=1.6, label="Lube et al. 2005 self-similar deposit (derived)")
        else:
            low, high = ref.runout_band(a)
            ax.axvspan(1 + float(low), 1 + float(high), color="0.9",
                       label="experiments' run-out band")
            ax.axvline(1 + float(ref.lube_runout_low(a)), color="k", lw=1.2,
                       label="Lube et al. 2005 run-out 1.2 a")
            ax.plot([0, 0.3], [float(ref.lube_height(a))] * 2, "k-", lw=2.5,
                    label="Lube: H_inf = H0 (a < 1.15)" if a < 1.15 else "Lube H_inf")
        staron = ref.staron_profile(a)
        if staron is not None:
            ax.plot(*staron, "-", color="0.55", lw=0.9, label="Staron contact dynamics (numerical)")
        for cells in (10, 20, 40):
            p = read_profile(folder, tag(a, cells, *scheme))
            if p is not None:
                ax.plot(p[0], smoothed(p[1]), "-", color=MESH_COLOURS[cells], lw=1.1,
                        label=f"argine {scheme[0]}/{scheme[1]} L0/{cells}")
        p = read_profile(folder, tag(a, 20, "linear", "FLIP"))
        if p is not None:
            ax.plot(p[0], smoothed(p[1]), "--", color="tab:orange", lw=1,
                    label="argine linear/FLIP L0/20")
        p = read_profile(folder, tag(a, 20, *scheme) + "_nowalls")
        if p is not None:
            ax.plot(p[0], smoothed(p[1]), ":", color="tab:gray", lw=1.2,
                    label=f"argine {scheme[0]}/{scheme[1]} L0/20, no side walls")
        ax.set_ylim(0, max(1.05 * a if a < 1.15 else 1.4 * float(ref.lube_height(a)), 0.3))
        ax.set_xlim(0, max(1 + 1.6 * float(ref.runout_band(a)[1]), 2))
        ax.set_ylabel("h / L0")
        ax.set_title(f"a = {a:g}", fontsize=9, loc="left")
        ax.legend(fontsize=6, ncol=2, loc="upper right")
        ax.grid(True, lw=0.3)
    np.atleast_1d(axes)[-1].set_xlabel(
        "x / L0 (wall at 0); argine: mass-equivalent thickness in L0/20 columns, running mean "
        "over three")
    fig.savefig(path, dpi=100)
    plt.close(fig)


def convergence_figure(groups, scheme, path):
    fig, axes = plt.subplots(1, 3, figsize=(12, 3.8), layout="constrained")
    labels = {"runout_L99": "run-out L99", "runout_front_fixed": "run-out, front at 0.03 L0",
              "height": "H_inf / L0"}
    for ax, (q, label) in zip(axes, labels.items()):
        for (a, shape, transfer), meshes in sorted(groups.items()):
            if not all(c in meshes for c in (10, 20, 40)):
                continue
            if (shape, transfer) != scheme and a != 2.0:
                continue
            cells = [10, 20, 40]
            values = [meshes[c][q] for c in cells]
            colour, marker = SCHEME_STYLE[(shape, transfer)]
            if (shape, transfer) == scheme:  # one colour per aspect ratio
                colour = RATIO_COLOURS.get(round(a, 3), colour)
            style = "-" if (shape, transfer) == scheme else "--"
            ax.plot([1 / c for c in cells], values, style, marker=marker, color=colour,
                    alpha=1 if (shape, transfer) == scheme else 0.6,
                    label=f"a = {a:g}" if (shape, transfer) == scheme
                    else f"a = 2 {shape}/{transfer}")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("cell size h / L0")
        ax.set_title(label, fontsize=9)
        ax.grid(True, which="both", lw=0.3)
    axes[0].legend(fontsize=6)
    fig.suptitle(f"three meshes: {scheme[0]}/{scheme[1]} at every a (solid), the other pairs at "
                 "a = 2 (dashed)", fontsize=9)
    fig.savefig(path, dpi=110)
    plt.close(fig)


def accuracy_cost_figure(cost, path):
    if not cost:
        return
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.3), layout="constrained")
    for ax, key, title in ((axes[0], "error_experiment",
                            "a = 2 against the experiment: max(front vs 1.9 a^(2/3), "
                            "H_inf vs a^0.4)"),
                           (axes[1], "error_finest",
                            "a = 2 against the L0/40 run of the same pair: max over "
                            "L99, front, H_inf")):
        for scheme, (colour, marker) in SCHEME_STYLE.items():
            every = [r for r in cost if (r["shape"], r["transfer"]) == scheme]
            rows = [r for r in every if np.isfinite(r[key])]
            failed = [f"L0/{r['cells']}" for r in every if r["status"] != "ok"]
            label = f"{scheme[0]} / {scheme[1]}"
            if failed:
                label += f" (unstable on {', '.join(failed)})"
            if any(r["status"] == "ok" and r["v7_checks"] == "fail" for r in every):
                label += " (open: not at rest, KE points != grid)"
            if not rows:
                if every:
                    ax.plot([], [], marker, color=colour, label=label)
                continue
            ax.loglog([r["cpu_seconds"] for r in rows], [100 * r[key] for r in rows], "-",
                      color=colour, label=label)
            for r in rows:
                ax.plot(r["cpu_seconds"], 100 * r[key], marker, color=colour,
                        mfc=colour if r["v7_checks"] == "pass" else "none")
                ax.annotate(f"L0/{r['cells']}", (r["cpu_seconds"], 100 * r[key]), fontsize=6,
                            xytext=(3, 2), textcoords="offset points")
        ax.set_xlabel("CPU time of the run (s)")
        ax.set_ylabel("error (%)")
        ax.set_title(title, fontsize=8)
        ax.grid(True, which="both", lw=0.3)
        ax.legend(fontsize=6)
    fig.savefig(path, dpi=110)
    plt.close(fig)


def energy_figure(groups, scheme, folder, path):
    fig, ax = plt.subplots(figsize=(6.5, 3.6), layout="constrained")
    for (a, shape, transfer), meshes in sorted(groups.items()):
        for s, style in ((scheme, "-"), (("linear", "FLIP"), "--")):
            if (shape, transfer) == s and 20 in meshes:
                e = read_profile(folder, tag(a, 20, shape, transfer), "_energy.csv")
                if e is not None:
                    ax.semilogy(e[0], np.maximum(e[1], 1e-12), style, marker=".",
                                label=f"a = {a:g} {shape}/{transfer}")
    ax.axhline(1e-4, color="k", lw=0.6)
    ax.set_xlabel("t / sqrt(H0 / g)")
    ax.set_ylabel("point kinetic energy / (m g H0 / 2)")
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=6, ncol=2)
    fig.savefig(path, dpi=110)
    plt.close(fig)


def draw_all(rows, groups, conv, cost, scheme, profiles, figures):
    os.makedirs(figures, exist_ok=True)
    out = {k: os.path.join(figures, f"granular_collapse_{k}.png")
           for k in ("runout", "profiles", "convergence", "accuracy_cost", "energy")}
    runout_figure(groups, scheme, out["runout"], rows)
    profiles_figure(groups, scheme, profiles, out["profiles"])
    convergence_figure(groups, scheme, out["convergence"])
    accuracy_cost_figure(cost, out["accuracy_cost"])
    energy_figure(groups, scheme, profiles, out["energy"])
    for path in out.values():
        if os.path.exists(path):
            print(f"collapse_plots: {path}")

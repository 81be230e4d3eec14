#!/usr/bin/env python3
"""Figures and numbers of inputs/levee_layered/README.md from a run of levee_layered.yaml:

  /usr/bin/python3 inputs/levee_layered/plot_levee_layered.py [--results DIR]

Writes levee_layered_mesh.png (the gmsh mesh, coloured by physical surface, with the refined
box) and levee_layered_uplift.png (the pore pressure along the base of the clay cover at
several times, against the cover's total vertical stress at the probes), and prints, per
probe at the cover base, the total vertical stress sigma_v (from the K0 state: sigma_v =
-(sigma'_yy - S_L p_L), tension positive) and the uplift ratio p_L / sigma_v at 12 and 24 h
(1 means the cover floats: toe uplift).
"""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
NAME = "levee_layered"
PROBES = ["cover_base_crest", "cover_base_toe", "cover_base_42", "cover_base_46",
          "cover_base_55"]
COLOURS = {"sand": "#e8d38a", "cover": "#9c7b5b", "levee": "#c9a27e"}


def read_rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def read_msh(path):
    """Nodes {tag: (x, y)} and triangles by physical surface name of an ASCII MSH 4.1 file."""
    lines = open(path).read().split("\n")
    names, entity_group, nodes, triangles = {}, {}, {}, {}
    i = 0
    while i < len(lines):
        line = lines[i].strip()
        if line == "$PhysicalNames":
            for k in range(int(lines[i + 1])):
                dim, tag, name = lines[i + 2 + k].split(maxsplit=2)
                names[(int(dim), int(tag))] = name.strip('"')
        elif line == "$Entities":
            counts = [int(c) for c in lines[i + 1].split()]
            row = i + 2 + counts[0] + counts[1]
            for k in range(counts[2]):
                words = lines[row + k].split()
                if int(words[7]) > 0:
                    entity_group[int(words[0])] = names[(2, int(words[8]))]
        elif line == "$Nodes":
            blocks = int(lines[i + 1].split()[0])
            row = i + 2
            for _ in range(blocks):
                count = int(lines[row].split()[3])
                tags = [int(t) for t in lines[row + 1: row + 1 + count]]
                for k, tag in enumerate(tags):
                    x, y, _ = (float(v) for v in lines[row + 1 + count + k].split())
                    nodes[tag] = (x, y)
                row += 1 + 2 * count
        elif line == "$Elements":
            blocks = int(lines[i + 1].split()[0])
            row = i + 2
            for _ in range(blocks):
                dim, entity, kind, count = (int(v) for v in lines[row].split())
                if dim == 2 and kind == 2:
                    group = triangles.setdefault(entity_group[entity], [])
                    for k in range(count):
                        group.append([int(v) for v in lines[row + 1 + k].split()[1:]])
                row += 1 + count
        i += 1
    return nodes, triangles


def plot_mesh():
    nodes, triangles = read_msh(os.path.join(HERE, NAME + ".msh"))
    fig, ax = plt.subplots(figsize=(11, 3.4))
    for group, elements in triangles.items():
        polygons = [[nodes[n] for n in element] for element in elements]
        ax.add_collection(PolyCollection(polygons, facecolor=COLOURS.get(group, "grey"),
                                         edgecolor="k", linewidth=0.15, label=group))
    ax.plot([27, 48, 48, 27, 27], [-4, -4, 5.5, 5.5, -4], "r--", linewidth=1,
            label="refined box (0.3 m)")
    ax.set_xlim(-1, 61)
    ax.set_ylim(-9.5, 6)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    count = sum(len(e) for e in triangles.values())
    ax.set_title(f"levee_layered.msh from levee_layered.geo: {len(nodes)} nodes, {count} triangles")
    ax.legend(loc="lower right", fontsize=8, ncol=4)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, NAME + "_mesh.png"), dpi=150)


def plot_uplift(results):
    profile = {}
    for row in read_rows(os.path.join(results, NAME + "_section_cover_base.csv")):
        if row["liquid_pressure"] in ("", "nan"):
            continue
        profile.setdefault(float(row["time"]) / 3600, []).append(
            (float(row["x"]), float(row["liquid_pressure"]) / 1000))
    fig, ax = plt.subplots(figsize=(9, 4.5))
    for hours in (0, 3, 6, 12, 24):
        if hours in profile:
            xs, ps = zip(*profile[hours])
            ax.plot(xs, ps, label=f"p_L at {hours} h")
    print("probe, x (m), sigma_v (kPa), p_L/sigma_v at 12 h, at 24 h")
    xs, sigmas = [], []
    for name in PROBES:
        rows = read_rows(os.path.join(results, f"{NAME}_probe_{name}.csv"))
        first = rows[0]
        sigma_v = -(float(first["stress_yy"]) - float(first["saturation"]) *
                    float(first["liquid_pressure"])) / 1000
        at = {float(r["time"]) / 3600: float(r["liquid_pressure"]) / 1000 for r in rows}
        xs.append(float(first["x"]))
        sigmas.append(sigma_v)
        print(f"{name}, {float(first['x']):.2f}, {sigma_v:.1f}, {at[12.0] / sigma_v:.3f}, "
              f"{at[24.0] / sigma_v:.3f}")
    ax.plot(xs, sigmas, "ks", label="total vertical stress at the probes")
    for x, label in ((15, "river-side toe"), (39, "landside toe")):
        ax.axvline(x, color="grey", linewidth=0.8, linestyle=":")
        ax.text(x + 0.3, ax.get_ylim()[1] * 0.9, label, fontsize=8, color="grey")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("kPa")
    ax.set_title("Pore pressure at the base of the clay cover (y = -2.85 m) during the flood")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, NAME + "_uplift.png"), dpi=150)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--results", default=os.path.join(ROOT, "results", NAME))
    args = parser.parse_args()
    plot_mesh()
    plot_uplift(args.results)


if __name__ == "__main__":
    main()

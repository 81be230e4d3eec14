#!/usr/bin/python3
"""A submerged ground that should stay at rest: how far its top rows of points heave, swell
and fall below the river's hydrostatic pressure (verification/submerged_ground).

  surface_at_rest.py POINTS.e [POINTS.e ...] [--head T H T H ...] [--every K]

For each points file (Exodus II, read with SciPy as scripts/levee_convergence.py reads it)
and every K-th output: the mean volume change V/V0 - 1 of the points of the top two rows
(the points with the two largest initial y), their mean p_L minus the river's hydrostatic
pressure rho_L g (H(t) - y) at their current y (kPa), the top row's mean effective stresses
and its share of points in a plastic state at that output, the whole layer's volume change
(L per m) and the largest displacement (mm). --head gives the river's total head as a
piecewise-linear table of time (s) and head (m); the default is the deck's: 2 m until 1 s,
0.5 m from 2 s. A ground at rest has every column near zero.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from levee_convergence import read_points  # noqa: E402

RHO_G = 1000 * 9.81  # the deck's liquid (N/m^3)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("points", nargs="+")
    parser.add_argument("--head", type=float, nargs="+", default=[0, 2.0, 1, 2.0, 2, 0.5])
    parser.add_argument("--every", type=int, default=2)
    args = parser.parse_args()
    if len(args.head) % 2:
        sys.exit("--head: expected pairs of time (s) and head (m)")
    head_t, head_h = np.array(args.head[0::2]), np.array(args.head[1::2])
    for path in args.points:
        if not os.path.exists(path):
            sys.exit(f"no {path}")
        t, x0, y0, v = read_points(path, want=("displ_x", "displ_y", "volume", "pressure_liquid",
                                               "stress_eff_xx", "stress_eff_yy",
                                               "plastic_state"))
        rows = np.unique(np.round(y0, 9))[::-1]
        top, second = np.isclose(y0, rows[0]), np.isclose(y0, rows[1])
        volume = v["volume"]
        print(f"\n{path}: {len(x0)} points, top rows at y0 = {rows[0]:.4f} / {rows[1]:.4f} m")
        print("| t (s) | top row: V/V0 - 1 | p_L - hydrostatic (kPa) | sigma'_xx, sigma'_yy (kPa) "
              "| plastic | 2nd row: V/V0 - 1 | p_L - hydrostatic (kPa) | layer: volume change "
              "(L/m) | largest |u| (mm) |")
        print("|---:|---:|---:|---|---:|---:|---:|---:|---:|")
        for k in range(0, len(t), args.every):
            y = y0 + v["displ_y"][k]
            excess = v["pressure_liquid"][k] - RHO_G * (np.interp(t[k], head_t, head_h) - y)
            cells = [f"{t[k]:.2f}"]
            for row, stresses in ((top, True), (second, False)):
                cells.append(f"{np.mean(volume[k][row] / volume[0][row] - 1):+.2e}")
                cells.append(f"{np.mean(excess[row]) / 1e3:+.2f}")
                if stresses:
                    cells.append(f"{np.mean(v['stress_eff_xx'][k][row]) / 1e3:.2f}, "
                                 f"{np.mean(v['stress_eff_yy'][k][row]) / 1e3:.2f}")
                    cells.append(f"{np.mean(v['plastic_state'][k][row] > 0):.2f}")
            u = np.hypot(v["displ_x"][k], v["displ_y"][k]).max()
            cells.append(f"{1e3 * (volume[k] - volume[0]).sum():.3f}")
            cells.append(f"{1e3 * u:.2f}")
            print("| " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""The alternating (checkerboard) pattern of a moving mass's cell stresses on a grid of cells
(doc/verification.md, "The cells' checkerboard").

  cell_checkerboard.py POINTS.e H [--origin X Y] [--start T] [--times T ...]

For each output nearest to --times (s; default: every output): the points that moved more
than 5 cm since the output nearest to --start (s, default 1: the levee decks' drawdown start),
their cells (squares of side H from --origin, default (0, -0.5): the grid levee decks), and
per cell holding only such points the mean of their mean effective pressure p' =
-(s'_xx + s'_yy + s'_zz)/3 and of their p_L (kPa). Over every 2 x 2 block of such cells
(values a b / c d): the rms of the checkerboard component (a - b - c + d)/4 and of the
gradient components ((b - a) + (d - c))/4, ((c - a) + (d - b))/4; the correlation of
neighbouring cells' deviations from their 3 x 3 neighbourhood mean along x and y (an
alternating pattern: near -1; a smooth one: positive); and the spread (standard deviation)
of the cells' values. One value a cell (`Volumetric Strain Averaging: element`) leaves the
checkerboard free of nodal forces; `Checkerboard Filter: true` removes it.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from levee_convergence import MOVED, read_points  # noqa: E402

STRESS = ("stress_eff_xx", "stress_eff_yy", "stress_eff_zz")


def cell_means(ix, iy, values, shape, mask, every):
    """Per cell the mean of values[mask]; NaN where a cell holds no point of the mask or any
    point outside it (every: the cell counts of all points)."""
    total = np.zeros(shape)
    count = np.zeros(shape)
    np.add.at(total, (ix[mask], iy[mask]), values[mask])
    np.add.at(count, (ix[mask], iy[mask]), 1)
    full = (count > 0) & (count == every)
    return np.where(full, total / np.maximum(count, 1), np.nan)


def correlation(u, w):
    ok = ~(np.isnan(u) | np.isnan(w))
    return float(np.corrcoef(u[ok], w[ok])[0, 1]) if ok.sum() > 10 else float("nan")


def pattern(m):
    """The checkerboard and gradient rms over full 2 x 2 blocks, the neighbours' correlation
    along x and y and the spread of the cell means m (NaN: no cell)."""
    a, b, c, d = m[:-1, :-1], m[1:, :-1], m[:-1, 1:], m[1:, 1:]
    ok = ~(np.isnan(a) | np.isnan(b) | np.isnan(c) | np.isnan(d))
    checker = ((a - b - c + d) / 4)[ok]
    gx = (((b - a) + (d - c)) / 4)[ok]
    gy = (((c - a) + (d - b)) / 4)[ok]
    nx, ny = m.shape
    padded = np.pad(m, 1, constant_values=np.nan)
    around = np.stack([padded[1 + i:1 + i + nx, 1 + j:1 + j + ny]
                       for i in (-1, 0, 1) for j in (-1, 0, 1)])
    with np.errstate(invalid="ignore"), np.testing.suppress_warnings() as quiet:
        quiet.filter(RuntimeWarning)
        deviation = m - np.nanmean(around, axis=0)
    return {"blocks": int(ok.sum()),
            "checker rms": float(np.sqrt(np.mean(checker ** 2))) if ok.any() else float("nan"),
            "gradient rms": float(np.sqrt(np.mean(gx ** 2 + gy ** 2) / 2)) if ok.any() else float("nan"),
            "corr x": correlation(deviation[:-1], deviation[1:]),
            "corr y": correlation(deviation[:, :-1], deviation[:, 1:]),
            "spread": float(np.nanstd(m)) if (~np.isnan(m)).any() else float("nan")}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("points")
    parser.add_argument("h", type=float)
    parser.add_argument("--origin", type=float, nargs=2, default=(0.0, -0.5))
    parser.add_argument("--start", type=float, default=1.0)
    parser.add_argument("--times", type=float, nargs="*")
    args = parser.parse_args()
    want = ("displ_x", "displ_y", "pressure_liquid") + STRESS
    time, x0, y0, v = read_points(args.points, want)
    k0 = int(np.argmin(np.abs(time - args.start)))
    outputs = (range(len(time)) if not args.times
               else [int(np.argmin(np.abs(time - t))) for t in args.times])
    print("| t (s) | moved points | quantity | blocks | checkerboard rms (kPa) | gradient rms (kPa) "
          "| neighbours' correlation x / y | spread of the cells (kPa) |")
    print("|---:|---:|---|---:|---:|---:|---|---:|")
    for k in outputs:
        ux, uy = v["displ_x"][k], v["displ_y"][k]
        moved = np.hypot(ux - v["displ_x"][k0], uy - v["displ_y"][k0]) > MOVED
        ix = np.floor((x0 + ux - args.origin[0]) / args.h).astype(int)
        iy = np.floor((y0 + uy - args.origin[1]) / args.h).astype(int)
        ix -= ix.min()
        iy -= iy.min()
        shape = (ix.max() + 1, iy.max() + 1)
        every = np.zeros(shape)
        np.add.at(every, (ix, iy), 1)
        quantities = {"p'": -sum(v[s][k] for s in STRESS) / 3e3}
        if "pressure_liquid" in v and np.any(v["pressure_liquid"][k] != 0):
            quantities["p_L"] = v["pressure_liquid"][k] / 1e3
        for name, values in quantities.items():
            r = pattern(cell_means(ix, iy, values, shape, moved, every))
            print(f"| {time[k]:.2f} | {int(moved.sum())} | {name} | {r['blocks']} | "
                  f"{r['checker rms']:.3f} | {r['gradient rms']:.3f} | "
                  f"{r['corr x']:+.2f} / {r['corr y']:+.2f} | {r['spread']:.2f} |")


if __name__ == "__main__":
    main()

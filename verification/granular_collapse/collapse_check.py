#!/usr/bin/python3
"""The V7 bounds, checked on rows written by collapse_run.py (CTest label verification).

  collapse_check.py bounds  ROWS.csv ...   run-out (front, 0.03 L0) and H_inf/L0 within the
                                           bands of collapse_reference (reference/SOURCES.md)
  collapse_check.py volume  ROWS.csv ...   sum of the point volumes at the end within 5 % of
                                           the initial one (psi = 0: no dilation)
  collapse_check.py kinetic ROWS.csv ...   at rest: point kinetic energy <= 1e-4 m g H0 / 2,
                                           and equal to the grid's: |KE_p - KE_grid| <= 1e-6
                                           m g H0 / 2 (no grid-invisible velocity)

Every row is checked and printed; the exit code is 1 if any fails.
"""
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import collapse_reference as ref  # noqa: E402

VOLUME_BOUND = 0.05  # VERIFICATION.md V7: total solid volume of a psi = 0 collapse within 5 %
REST_BOUND = 1e-4    # kinetic energy at rest, fraction of m g H0 / 2 (reference/SOURCES.md 2.3)
INVISIBLE_BOUND = 1e-6  # |KE_points - KE_grid| at rest, fraction of m g H0 / 2


def read_rows(paths):
    rows = []
    for path in paths:
        with open(path, newline="") as handle:
            rows += list(csv.DictReader(handle))
    return rows


def bounds(row):
    a = float(row["a"])
    runout, height = float(row["runout_front_fixed"]), float(row["height"])
    r_low, r_high = (float(v) for v in ref.runout_band(a))
    h_low, h_high = (float(v) for v in ref.height_band(a))
    ok_r = r_low <= runout <= r_high
    ok_h = h_low <= height <= h_high
    lube_low, lube_high = (float(v) for v in ref.lube_runout(a))
    lube = f"{lube_low:.2f}" if lube_low == lube_high else f"{lube_low:.2f}-{lube_high:.2f}"
    print(f"a = {a:g} ({row['shape']} {row['transfer']}, L0/{row['cells']}): run-out "
          f"(L_inf - L0)/L0 = {runout:.3f} (front at 0.03 L0; L99 {float(row['runout_L99']):.3f})"
          f" in [{r_low:.2f}, {r_high:.2f}] (Lube {lube}): {'ok' if ok_r else 'FAIL'}; "
          f"H_inf/L0 = {height:.3f} in [{h_low:.2f}, {h_high:.2f}] (Lube "
          f"{float(ref.lube_height(a)):.2f}): {'ok' if ok_h else 'FAIL'}")
    return ok_r and ok_h


def volume(row):
    ratio = float(row["volume_ratio"])
    ok = abs(ratio - 1) <= VOLUME_BOUND
    print(f"a = {row['a']} ({row['shape']} {row['transfer']}, L0/{row['cells']}): point volume "
          f"end/start {ratio:.4f} (bound 1 +- {VOLUME_BOUND}); porosity "
          f"{float(row['porosity_min']):.3f}-{float(row['porosity_max']):.3f}: "
          f"{'ok' if ok else 'FAIL'}")
    return ok


def kinetic(row):
    scale = float(row["energy_scale"])
    points, grid = float(row["ke_points"]), float(row["ke_grid"])
    rest = points <= REST_BOUND * scale
    equal = abs(points - grid) <= INVISIBLE_BOUND * scale
    print(f"a = {row['a']} ({row['shape']} {row['transfer']}, L0/{row['cells']}) at "
          f"t = {float(row['t_end']):.3g} s: KE points {points:.3g} J/m = {points / scale:.2e} "
          f"m g H0/2 (rest bound {REST_BOUND:g}): {'ok' if rest else 'FAIL'}; KE grid "
          f"{grid:.3g} J/m, |difference| {abs(points - grid) / scale:.2e} m g H0/2 (bound "
          f"{INVISIBLE_BOUND:g}): {'ok' if equal else 'FAIL'}")
    return rest and equal


def main():
    checks = {"bounds": bounds, "volume": volume, "kinetic": kinetic}
    if len(sys.argv) < 3 or sys.argv[1] not in checks:
        sys.exit(__doc__)
    rows = read_rows(sys.argv[2:])
    if not rows:
        sys.exit("collapse_check: no rows")
    results = []
    for row in rows:
        if row.get("status", "ok") != "ok":  # the run itself failed: nothing to measure
            print(f"a = {row['a']} ({row['shape']} {row['transfer']}, L0/{row['cells']}): "
                  f"{row['status']}: FAIL")
            results.append(False)
        else:
            results.append(checks[sys.argv[1]](row))
    print(f"collapse_check {sys.argv[1]}: {sum(results)} of {len(results)} within the bound")
    return 0 if all(results) else 1


if __name__ == "__main__":
    sys.exit(main())

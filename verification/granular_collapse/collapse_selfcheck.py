#!/usr/bin/python3
"""Self-check of the V7 helpers (CTest verification_granular_collapse_selfcheck, < 1 s):
the measures on hand-made point sets and the laws against the tabulated reference values."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import collapse_reference as ref  # noqa: E402
from collapse_results import front_position, mass_quantile, thickness_profile  # noqa: E402

failures = []


def check(name, got, expected, tolerance):
    ok = abs(got - expected) <= tolerance
    print(f"{'ok  ' if ok else 'FAIL'} {name}: {got:.6g} (expected {expected:.6g})")
    if not ok:
        failures.append(name)


# Mass quantiles: ten equal masses at x = 1..10: 95 % behind 10, 90 % behind 9; a heavy
# point moves them.
x = np.arange(1.0, 11.0)
check("L95 of ten equal masses", mass_quantile(x, np.ones(10), 0.95), 10.0, 0)
check("L90 of ten equal masses", mass_quantile(x, np.ones(10), 0.90), 9.0, 0)
check("L99 with 99 % of the mass at x = 1", mass_quantile(x, np.r_[891.0, np.ones(9)], 0.99),
      1.0, 0)

# A wedge h = 1 - x of points on a 0.01 grid: binned thickness and its front.
gx, gy = np.meshgrid(np.arange(0.005, 1.0, 0.01), np.arange(0.005, 1.0, 0.01))
inside = gy < 1 - gx
centres, thickness = thickness_profile(gx[inside], np.full(inside.sum(), 1e-4), 0.05, 1.2, 0.01)
check("wedge thickness at x = 0.275", float(np.interp(0.275, centres, thickness)), 0.725, 0.01)
check("wedge front at h = 0.1", front_position(centres, thickness, 0.1), 0.9, 0.02)
# A detached point ahead of the deposit does not move the front.
centres, thickness = thickness_profile(np.r_[gx[inside], 1.15], np.full(inside.sum() + 1, 1e-4),
                                       0.05, 1.2, 0.01)
check("front with a detached point", front_position(centres, thickness, 0.1), 0.9, 0.02)
# A row of points at spacing 0.01, shifted by any offset, is 0.02 thick in every bin of 0.05.
for offset in (0.0, 0.0025, 0.005):
    centres, thickness = thickness_profile(np.arange(0.005, 1.0, 0.01) + offset,
                                           np.full(100, 2e-4), 0.05, 1.2, 0.01)
    check(f"row of points offset {offset}: thickness range", float(np.ptp(thickness[1:19])), 0,
          1e-12)

# The laws reproduce reference_values_at_target_a.csv (to its printed digits).
for a, row in ref.tabulated_bands().items():
    low, high = ref.runout_band(a)
    check(f"run-out band low, a = {a:g}", float(low), float(row["recommended_quasi2D_runout_min"]),
          0.006)
    check(f"run-out band high, a = {a:g}", float(high),
          float(row["recommended_quasi2D_runout_max"]), 0.006)
    low, high = ref.height_band(a)
    check(f"height band low, a = {a:g}", float(low), float(row["recommended_Hinf_over_L0_min"]),
          0.006)
    check(f"height band high, a = {a:g}", float(high), float(row["recommended_Hinf_over_L0_max"]),
          0.006)
    check(f"Lube height, a = {a:g}", float(ref.lube_height(a)), float(row["Lube2005_Hinf_over_L0"]),
          0.001)
    if row["Nguyen2015_true2D_runout"]:
        check(f"Nguyen run-out, a = {a:g}", float(ref.nguyen_runout(a)),
              float(row["Nguyen2015_true2D_runout"]), 0.001)

# The derived Lube profile file for a = 4 is the shape scaled by the laws.
derived = np.loadtxt(os.path.join(ref.REFERENCE, "profiles", "lube2005_DERIVED_profile_a4.csv"),
                     delimiter=",", skiprows=1)
xs, hs = ref.lube_profile(4.0)
check("derived a = 4 profile, largest x", float(xs[-1]), float(derived[-1, 0]), 0.001)
check("derived a = 4 profile, height at the wall", float(hs[0]), float(derived[0, 1]), 0.001)

print(f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)

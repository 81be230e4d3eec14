#!/usr/bin/python3
"""Self-check of levee_convergence.py's observed order and error bar (CTest
scripts.levee_convergence_selfcheck, < 1 s) on sequences whose order and limit are known by
hand: q(h) = 2 - h^p sampled at one refinement ratio and at two (0.1, 0.05, 1/28 m); its
depth below the surface on five points; its displacement at a probe's position; and its
reading of a strength-reduction search (FS_SRM, bracket, the limit equilibrium's F); and
strength_sensitivity.py's weakened deck (strength and flow rule of its last stage)."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import levee_convergence as lc  # noqa: E402

failures = []


def check(name, got, expected, tolerance):
    ok = abs(got - expected) <= tolerance
    print(f"{'ok  ' if ok else 'FAIL'} {name}: {got:.12g} (expected {expected:.12g})")
    if not ok:
        failures.append(name)


# One ratio, r = 2: 1.0, 1.5, 1.75 on 0.4, 0.2, 0.1 m. e32 = 0.5, e21 = 0.25: p = log 2 / log 2
# = 1; limit 1.75 + 0.25 / (2 - 1) = 2.0; GCI 1.25 * 0.25 / (2 - 1) = 0.3125.
order, limit, bar = lc.error_bar([1.0, 1.5, 1.75], [0.4, 0.2, 0.1])
check("one ratio: order", order, 1.0, 1e-12)
check("one ratio: limit", limit, 2.0, 1e-12)
check("one ratio: error bar", bar, 0.3125, 1e-12)

# Two ratios, q = 2 - h on 0.1, 0.05, 1/28 m: 1.9, 1.95, 1.9642857... The order is 1 and the
# limit 2 exactly; the one-ratio formula with r = 1.4 would give log(3.5) / log(1.4) = 3.72.
sizes = [0.1, 0.05, 1 / 28]
order, limit, bar = lc.error_bar([2 - h for h in sizes], sizes)
check("two ratios, p = 1: order", order, 1.0, 1e-9)
check("two ratios, p = 1: limit", limit, 2.0, 1e-9)
# GCI = 1.25 |e21| / (r21 - 1) = 1.25 * (0.05 - 1/28) / 0.4
check("two ratios, p = 1: error bar", bar, 1.25 * (0.05 - 1 / 28) / 0.4, 1e-12)

# q = 2 - h^2 on the same sizes: order 2 (the limit then uses the capped order 1:
# q1 + e21 / (1.4 - 1), with e21 = 1/400 - 1/784).
order, limit, bar = lc.error_bar([2 - h * h for h in sizes], sizes)
check("two ratios, p = 2: order", order, 2.0, 1e-9)
check("two ratios, p = 2: limit (order capped at 1)", limit,
      2 - 1 / 784 + (1 / 400 - 1 / 784) / 0.4, 1e-12)

# A last change far below the one before (0.5 then 1e-9 on two ratios): a large order (about
# 29: at large p, h3^p and h2^p dominate the changes, so e32 / e21 -> (h3 / h2)^p = 2^p =
# 5e8); the limit and the bar use the capped order 1.
order, limit, bar = lc.error_bar([1.0, 1.5, 1.5 + 1e-9], sizes)
check("vanishing change: order near log(5e8) / log(2)", order, math.log(5e8) / math.log(2),
      0.01)
check("vanishing change: error bar", bar, 1.25e-9 / 0.4, 1e-15)
# Changes that shrink more slowly than any positive order allows on these ratios (0.5 then
# 0.49: e32 / e21 = 1.02 < log 2 / log 1.4): no order, and the bar is 1.25 x the larger.
order, limit, bar = lc.error_bar([1.0, 1.5, 1.99], sizes)
check("slow changes: error bar", bar, 1.25 * 0.5, 1e-12)
if not math.isnan(order):
    failures.append(f"slow changes: order {order} should be nan")

# Changes of opposite sign: no order, no limit, the bar 1.25 x the larger change.
order, limit, bar = lc.error_bar([1.0, 1.5, 1.4], sizes)
check("oscillating: error bar", bar, 1.25 * 0.5, 1e-12)
if not (math.isnan(order) and math.isnan(limit)):
    failures.append("oscillating: order and limit should be nan")

# Depth below the surface: the highest point of each 0.1 m column. Columns [0, 0.1) with
# y = 1.0, 0.7 and [0.1, 0.2) with y = 0.4, 0.45, 0.1 (x = 0.15 lies in the second):
# depths 0, 0.3 | 0.05, 0, 0.35.
import numpy as np  # noqa: E402

depth = lc.depth_below_surface(np.array([0.02, 0.08, 0.12, 0.15, 0.19]),
                               np.array([1.0, 0.7, 0.4, 0.45, 0.1]))
for got, expected, what in zip(depth, [0.0, 0.3, 0.05, 0.0, 0.35], "abcde"):
    check(f"depth below the surface, point {what}", got, expected, 1e-12)

# The material at a probe's position: a displacement linear in the initial position is
# interpolated exactly. Points on the lattice {0, 1, 2}^2 with u_x = 0.1 + 0.2 x + 0.3 y and
# u_y = -0.4 + 0.1 x: at (0.5, 1.5) u = (0.65, -0.35), |u| = sqrt(0.545); at the corner (2, 2)
# u = (1.1, -0.2), |u| = sqrt(1.25); outside the points' hull, at (3, 3), nan.
gx, gy = np.meshgrid([0.0, 1.0, 2.0], [0.0, 1.0, 2.0])
gx, gy = gx.ravel(), gy.ravel()
at = lc.displacement_at(gx, gy, [(0.5, 1.5), (2.0, 2.0), (3.0, 3.0)])
u = at(0.1 + 0.2 * gx + 0.3 * gy, -0.4 + 0.1 * gx)
check("probe at position, inside", u[0], math.sqrt(0.545), 1e-12)
check("probe at position, corner", u[1], math.sqrt(1.25), 1e-12)
if not math.isnan(u[2]):
    failures.append(f"probe at position outside the points: {u[2]} should be nan")
u = at(0.1 + 0.2 * gx + 0.3 * gy, -0.4 + 0.1 * gx, components=True)
check("probe at position, u_x", u[0][0], 0.65, 1e-12)
check("probe at position, u_y (the settlement's sign)", u[0][1], -0.35, 1e-12)

# A strength-reduction search read from its CSVs: from t = 3 s, F = 1 holds, 1.05 fails,
# 1.025 and 1.0375 hold: FS_SRM = (1.0375 + 1.05) / 2 = 1.04375 +- 0.00625, and the limit
# equilibrium's F the row at t = 3 s (1.081, not 1.2 at 2.5 s). A second search from t = 5 s
# whose two trials both hold has no FS_SRM (nan) and no evaluation at its time (nan).
import tempfile  # noqa: E402

with tempfile.TemporaryDirectory() as folder:
    with open(os.path.join(folder, "run_strength_reduction.csv"), "w") as handle:
        handle.write("time,trial,factor,converged,accelerating,failed\n"
                     "3,1,1,1,0,0\n3,2,1.05,0,0,1\n3,3,1.025,1,0,0\n3,4,1.0375,1,0,0\n"
                     "5,1,1,1,0,0\n5,2,1.2,1,0,0\n")
    with open(os.path.join(folder, "run_factor_of_safety.csv"), "w") as handle:
        handle.write("time,factor_of_safety,bishop\n2.5,1.2,1.2\n3,1.081,1.081\n")
    searches = lc.strength_reductions(folder, "run")
    check("strength reduction: FS_SRM", searches[3.0]["FS_SRM"], 1.04375, 1e-12)
    check("strength reduction: bracket", searches[3.0]["bracket"], 0.00625, 1e-12)
    check("strength reduction: F on the same state", searches[3.0]["limit equilibrium F"],
          1.081, 1e-12)
    if not (math.isnan(searches[5.0]["FS_SRM"]) and
            math.isnan(searches[5.0]["limit equilibrium F"])):
        failures.append("strength reduction: a search that never failed has no FS_SRM")
    # FS_SRM that no longer changes between the finest two meshes keeps its bracket as its
    # error bar (the changes alone would give 0); a larger change gives the larger bar.
    order, limit, bar = lc.strength_error_bar([1.09375, 1.04375, 1.01875, 1.01875],
                                              [0.4, 0.2, 0.1, 0.05], [0.00625] * 4)
    check("strength reduction: error bar at least the bracket", bar, 0.00625, 1e-12)
    order, limit, bar = lc.strength_error_bar([1.0, 1.5, 1.75], [0.4, 0.2, 0.1], [0.01] * 3)
    check("strength reduction: error bar from the changes", bar, 0.3125, 1e-12)
    if lc.strength_reductions(folder, "other"):
        failures.append("strength reduction: a run without the CSV has no searches")

# strength_sensitivity.py's weakened deck: the shipped drawdown grid deck at f = 0.75 has
# c' = 0.75 * 2 kPa = 1500 Pa and phi' = atan(0.75 tan 27 deg) = atan(0.382144) = 20.914 deg
# in its last stage; with --flow-rule associated psi = that phi', without it no dilatancy
# change (the deck's psi = 0 stands).
import strength_sensitivity as ss  # noqa: E402
import yaml  # noqa: E402

deck = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "inputs",
                    "levee_drawdown", "levee_drawdown_grid_conjugate.yaml")
for associated in (False, True):
    weakened = yaml.safe_load(ss.deck_text(deck, 0.1, 0.75, 4.0, "copy", associated))["argine"]
    last = list(weakened["Stages"].values())[-1]
    soil = last["Material Changes"]["soil"]
    label = "associated" if associated else "deck's flow rule"
    check(f"weakened deck ({label}): c'", soil["Cohesion (Pa)"], 1500.0, 1e-9)
    check(f"weakened deck ({label}): phi'", soil["Friction Angle (deg)"], 20.914, 5e-4)
    if associated:
        check("weakened deck (associated): psi", soil["Dilatancy Angle (deg)"], 20.914, 5e-4)
    elif "Dilatancy Angle (deg)" in soil:
        failures.append("weakened deck: the deck's flow rule changed without --flow-rule")
    check(f"weakened deck ({label}): element size",
          weakened["Mesh"]["Generate"]["Element Size (m)"], 0.1, 0)
    check(f"weakened deck ({label}): duration", last["Duration (s)"], 4.0, 0)

if failures:
    sys.exit(f"{len(failures)} check(s) failed: " + ", ".join(failures))
print("all checks passed")

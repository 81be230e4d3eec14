"""The experimental laws V7 compares with, and the acceptance bands (reference/SOURCES.md).

a = H0/L0; run-out (L_inf - L0)/L0; final height H_inf/L0. Every coefficient is a row of
reference/scaling_laws.csv; reference/reference_values_at_target_a.csv tabulates these
functions at a = 0.5, 1, 2, 4, 6, 8 (collapse_selfcheck.py checks that they agree).
"""
import csv
import os

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
REFERENCE = os.path.join(HERE, "reference")


def lube_runout_low(a):
    """Lube et al. 2005, quasi-2D channel, sand: 1.2 a (a < 1.8)."""
    return 1.2 * np.asarray(a, float)


def lube_runout_high(a):
    """Lube et al. 2005: 1.9 a^(2/3) (a > 2.8); 1.8 < a < 2.8 is transitional."""
    return 1.9 * np.asarray(a, float) ** (2 / 3)


def lube_runout(a):
    """The Lube branch of a, or both branches' range (low, high) in the transition."""
    a = np.asarray(a, float)
    low, high = lube_runout_low(a), lube_runout_high(a)
    lower = np.where(a < 1.8, low, np.where(a > 2.8, high, np.minimum(low, high)))
    upper = np.where(a < 1.8, low, np.where(a > 2.8, high, np.maximum(low, high)))
    return lower, upper


def lube_height(a):
    """Lube et al. 2005: H_inf/L0 = a (a < 1.15), a^(2/5) above."""
    a = np.asarray(a, float)
    return np.where(a < 1.15, a, a ** 0.4)


def lajeunesse_height(a):
    """Lajeunesse et al. 2005 (secondary, Kumar 2015): a (a < 0.7), a^(1/3) above."""
    a = np.asarray(a, float)
    return np.where(a < 0.7, a, a ** (1 / 3))


def lajeunesse_runout_lower(a):
    """Lajeunesse et al. 2005, lower end of the secondary coefficients (1.2 a, 1.9 a^(2/3)
    above a = 2.3; UNVERIFIED): equal to Lube except 2.3 < a < 2.8."""
    a = np.asarray(a, float)
    return np.where(a < 2.3, 1.2 * a, 1.9 * a ** (2 / 3))


def nguyen_runout(a):
    """Nguyen et al. 2015, true-2D aluminium rods (phi about 20 deg), for context only; no
    law below a = 0.65 (NaN)."""
    a = np.asarray(a, float)
    law = np.where(a < 1.5, 3.25 * a ** 0.96, 3.80 * a ** 0.73)
    return np.where(a < 0.65, np.nan, law)


def nguyen_height(a):
    """Nguyen et al. 2015: H_inf = H0 (a <= 0.65), 0.704 a^(1/3) above."""
    a = np.asarray(a, float)
    return np.where(a <= 0.65, a, 0.704 * a ** (1 / 3))


def runout_band(a):
    """Accepted run-out: 0.75 x the lower Lube branch to 1.30 x max(upper Lube branch, lower
    Lajeunesse value) (reference/SOURCES.md Sec. 3)."""
    lower, upper = lube_runout(a)
    return 0.75 * lower, 1.30 * np.maximum(upper, lajeunesse_runout_lower(a))


def height_band(a):
    """Accepted final height: 0.8 x min(Lube, Lajeunesse) to 1.2 x max(Lube, Lajeunesse)."""
    lube, laj = lube_height(a), lajeunesse_height(a)
    return 0.8 * np.minimum(lube, laj), 1.2 * np.maximum(lube, laj)


def tabulated_bands():
    """{a: row} of reference_values_at_target_a.csv (numbers as floats where they are)."""
    rows = {}
    with open(os.path.join(REFERENCE, "reference_values_at_target_a.csv"), newline="") as f:
        for row in csv.DictReader(f):
            rows[float(row["a"])] = row
    return rows


def lube_shape():
    """Lube's self-similar deposit: x/L_inf, h/H_inf (digitised, a > 1.8), from the wall,
    closed with (0, 1) at the wall and (1, 0) at the front as the DERIVED profile files are."""
    data = np.loadtxt(os.path.join(REFERENCE, "profiles",
                                   "lube2005_selfsimilar_shape_digitised_busch.csv"),
                      delimiter=",", skiprows=1)
    return np.r_[0.0, data[:, 0], 1.0], np.r_[1.0, data[:, 1], 0.0]


def lube_profile(a):
    """The self-similar shape scaled by Lube's laws, x/L0 and h/L0 (derived, a >= 2)."""
    xs, hs = lube_shape()
    _, upper = lube_runout(a)
    return xs * (1 + float(upper)), hs * float(lube_height(a))


def staron_profile(a):
    """Staron's 2-D contact dynamics deposit (NUMERICAL), x/L0 >= 0 half, or None."""
    name = {0.5: "0.50", 1.42: "1.42", 6.26: "6.26"}.get(a)
    if name is None:
        return None
    data = np.loadtxt(os.path.join(REFERENCE, "profiles", f"staronCD_symmetric_a{name}_final.csv"),
                      delimiter=",", skiprows=1)
    right = data[:, 0] >= 0
    return data[right, 0], data[right, 1]

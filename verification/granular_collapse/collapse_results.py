"""Measures of one granular column collapse from the files `argine run` wrote (V7).

  measure(directory, name, column) -> dict of the measures below

Reads NAME_points.e and NAME_grid.e (Exodus II = netCDF-3, SciPy) and NAME_diagnostics.csv.
`column` gives L0, H0 (m), the cell size h (m), the points per cell direction and g.

Definitions (doc/verification.md, "V7 Granular column collapse"):
  mass       m_p = rho_S (1 - n_p) V_p of the first output (constant for a dry point)
  L_q        x behind which the fraction q of the solid mass stays (q = 0.95, 0.99, 1)
  h(x)       deposit thickness at the initial packing: the points' initial volumes
             V_p0 = m_p / (rho_S (1 - n_0)), each spread over one point spacing around its
             final x, summed in columns of width L0 / 20 (the same on every mesh) and
             divided by the width: area per length, so
             voids between points do not count as soil, and an error of the volume update
             (which the volume check reports) does not change where the mass is
  front      the first x from the wall where h(x), smoothed by a running mean over three
             columns (0.15 L0) and linear between their centres, falls below a
             threshold (at least the threshold is deposit): one point spacing s = h / points
             per direction (`front`, the threshold shrinks with the mesh), and the fixed
             0.03 L0 (`front_fixed`, the run-out compared with the experiments; between
             one and two layers of points on the default mesh L0/20, whose one-layer sheet
             is 0.025 L0 thick, so a lone sheet of points does not count as deposit)
  H_inf      the deposit height at the wall: the mean of h(x) over 0 <= x <= L0 / 5 (Lube's
             self-similar deposit averages 1-3 % below its wall height there, a = 2-6)
  volume     sum V_p at the end / at the start; porosity range over the points and outputs
  stop       first output after the peak from which the point kinetic energy stays below
             1e-4 of the column's initial potential energy m g H0 / 2 (the outputs are
             T_c / 2 = sqrt(H0 / g) / 2 apart in the decks)
  KE         point sum 1/2 m_p |v_p|^2 and grid sum 1/2 M_i |v_i|^2 at the last output
"""
import csv
import os

import numpy as np

# Kinetic energy, as a fraction of the column's potential energy m g H0 / 2, below which the
# deposit is taken to be at rest (reference/SOURCES.md Sec. 2 item 3; collapse_check.py
# bounds the final state with the same fraction).
REST_FRACTION = 1e-4
# Width of the columns of the thickness profile: L0 / BINS_PER_L0 on every mesh.
BINS_PER_L0 = 20
# Thickness, as a fraction of L0, at which the deposit ends (front_fixed).
FRONT_THRESHOLD = 0.03


def _names(variable):
    return ["".join(c.decode() for c in row).strip("\x00 ") for row in variable[:]]


def read_exodus(path):
    """Nodal coordinates, times and nodal variables {name: array (time, node)}."""
    from scipy.io import netcdf_file

    with netcdf_file(path, "r", mmap=False) as f:
        names = _names(f.variables["name_nod_var"])
        values = {n: f.variables["vals_nod_var%d" % (k + 1)][:].copy()
                  for k, n in enumerate(names)}
        x, y = f.variables["coordx"][:].copy(), f.variables["coordy"][:].copy()
        time = f.variables["time_whole"][:].copy()
    return x, y, time, values


def read_diagnostics(path):
    with open(path, newline="") as handle:
        rows = [{k: float(v) for k, v in row.items()} for row in csv.DictReader(handle)]
    return {k: np.array([r[k] for r in rows]) for k in rows[0]}


def mass_quantile(x, mass, q):
    """Smallest x behind which the fraction q of the mass lies."""
    order = np.argsort(x)
    cumulative = np.cumsum(mass[order])
    k = int(np.searchsorted(cumulative, q * cumulative[-1] * (1 - 1e-12)))
    return float(x[order][min(k, len(x) - 1)])


def thickness_profile(x, volume, width, extent, spread):
    """Bin centres and thickness (area in the bin / width) from x = 0 to extent. Each point's
    area is spread evenly over [x - spread/2, x + spread/2] (spread: the point spacing,
    at most the width), so that a row of points at that spacing gives the same thickness
    in every bin whatever its offset from the bin edges (no aliasing)."""
    bins = int(np.ceil(extent / width))
    left = np.clip(x - spread / 2, 0, bins * width - spread)
    k = np.clip((left / width).astype(int), 0, bins - 1)
    inside = np.clip(((k + 1) * width - left) / spread, 0, 1)  # share in bin k, rest in k + 1
    area = np.bincount(k, weights=volume * inside, minlength=bins + 1)
    area += np.bincount(k + 1, weights=volume * (1 - inside), minlength=bins + 1)
    return (np.arange(bins) + 0.5) * width, area[:bins] / width


def smoothed(thickness):
    """Running mean over three bins (two at the ends): the profile the fronts are read from,
    which a bin emptied by the bunching of points into lines does not cut short."""
    padded = np.r_[0.0, thickness, 0.0]
    count = np.r_[0.0, np.ones(len(thickness)), 0.0]
    kernel = np.ones(3)
    return np.convolve(padded, kernel, "valid") / np.convolve(count, kernel, "valid")


def front_position(centres, thickness, threshold):
    """First x from the wall where the thickness, linear between bin centres, drops below
    the threshold (the end of the continuous deposit: detached points ahead do not count).
    A thickness equal to the threshold up to round-off counts as deposit."""
    threshold = threshold * (1 - 1e-9)
    below = np.nonzero(thickness < threshold)[0]
    if len(below) == 0:
        return float(centres[-1])
    k = int(below[0])
    if k == 0:
        return 0.0
    t0, t1 = thickness[k - 1], thickness[k]
    return float(centres[k - 1] + (t0 - threshold) / (t0 - t1) * (centres[k] - centres[k - 1]))


def stop_time(diagnostics, energy_scale):
    time, kinetic = diagnostics["time"], diagnostics["kinetic_energy_solid"]
    peak = int(np.argmax(kinetic))
    moving = np.nonzero(kinetic[peak:] >= REST_FRACTION * energy_scale)[0]
    last = peak + (int(moving[-1]) if len(moving) else 0)
    return float(time[last + 1]) if last + 1 < len(time) else float("nan")


def grid_kinetic_energy(path, frame=-1):
    _, _, _, values = read_exodus(path)
    m = values["mass_solid"][frame]
    v2 = values["velocity_solid_x"][frame] ** 2 + values["velocity_solid_y"][frame] ** 2
    return float(0.5 * np.sum(m * v2))


def measure(directory, name, column):
    """All measures of one run (see the module doc); column: dict L0, H0, h, per_direction,
    density (rho_S), g."""
    x0, y0, time, values = read_exodus(os.path.join(directory, name + "_points.e"))
    L0, H0, h = column["L0"], column["H0"], column["h"]
    last = len(time) - 1
    volume = values["volume"]
    porosity = values["porosity"]
    mass = column["density"] * (1 - porosity[0]) * volume[0]
    x = x0 + values["displ_x"][last]
    v2 = values["velocity_solid_x"][last] ** 2 + values["velocity_solid_y"][last] ** 2
    spacing = h / column["per_direction"]
    extent = max(float(np.max(x)), L0) + 2 * h
    width = L0 / BINS_PER_L0
    centres, thickness = thickness_profile(x, volume[0], width, extent + width, spacing)
    smooth = smoothed(thickness)
    energy_scale = float(np.sum(mass)) * column["g"] * H0 / 2
    diagnostics = read_diagnostics(os.path.join(directory, name + "_diagnostics.csv"))
    ke_points = float(0.5 * np.sum(mass * v2))
    grid = os.path.join(directory, name + "_grid.e")
    ke_grid = grid_kinetic_energy(grid) if os.path.exists(grid) else float("nan")
    result = {
        "L95": mass_quantile(x, mass, 0.95), "L99": mass_quantile(x, mass, 0.99),
        "L100": float(np.max(x)),
        "front": front_position(centres, smooth, spacing),
        "front_fixed": front_position(centres, smooth, FRONT_THRESHOLD * L0),
        "H_inf": float(np.mean(thickness[: BINS_PER_L0 // 5])),
        "volume_ratio": float(np.sum(volume[last]) / np.sum(volume[0])),
        "porosity_min": float(np.min(porosity)), "porosity_max": float(np.max(porosity)),
        "t_end": float(time[last]), "t_stop": stop_time(diagnostics, energy_scale),
        "energy_scale": energy_scale, "ke_peak": float(np.max(diagnostics["kinetic_energy_solid"])),
        "ke_points": ke_points, "ke_grid": ke_grid,
        "lost_points": int(diagnostics["lost_points"][-1]), "points": len(x0),
    }
    for key in ("L95", "L99", "L100", "front", "front_fixed"):
        result["runout_" + key] = (result[key] - L0) / L0
    result["height"] = result["H_inf"] / L0
    profile = {"x": centres, "h": thickness}
    return result, profile

#include "argine/slopestability/CircleSearch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace argine {

namespace {

Real gridValue(Real lo, Real hi, int count, int i) {
  return count <= 1 ? lo : lo + (hi - lo) * i / (count - 1);
}

/// Whether the search may take `mass`: inside the abscissa range, deep enough.
bool withinSearchLimits(const SlipMass& mass, const CircleSearchGrid& grid) {
  if (mass.entry_x < grid.mass_x_min || mass.exit_x > grid.mass_x_max) return false;
  Real depth = 0;
  for (const Slice& s : mass.slices) depth = std::max(depth, s.top_y - s.base_y);
  return depth >= grid.min_depth;
}

Real gridStep(Real lo, Real hi, int count) {
  return count <= 1 ? 0 : (hi - lo) / (count - 1);
}

}  // namespace

CriticalCircle searchCriticalCircle(const SlopeSection& section, const CircleSearchGrid& grid,
                                    const BishopOptions& options) {
  CriticalCircle best =
      searchCriticalCircleBy(section, grid, [&options](const SlipMass& mass, const SlipCircle& c) {
        return bishopSimplified(mass.slices, options, endForceDriving(mass, c));
      });
  if (best.found) best.bishop = best.objective;
  return best;
}

namespace {

/// One trial circle of the search: sliced, limited, evaluated; the best so far kept.
/// Returns the objective's F, or NaN when the circle is rejected.
Real tryCircle(const SlopeSection& section, const CircleSearchGrid& grid,
               const CircleObjective& objective, const SlipCircle& circle, CriticalCircle& best) {
  ++best.evaluated;
  SlipMass mass = sliceCircle(section, circle, grid.slice_count, grid.split_at_materials);
  if (!mass.valid || !withinSearchLimits(mass, grid)) {
    ++best.rejected;
    return std::numeric_limits<Real>::quiet_NaN();
  }
  const FactorOfSafety fs = objective(mass, circle);
  if (!fs.admissible) {
    ++best.rejected;
    return std::numeric_limits<Real>::quiet_NaN();
  }
  if (!best.found || fs.value < best.objective.value) {
    best.found = true;
    best.circle = circle;
    best.objective = fs;
    best.mass = std::move(mass);
  }
  return fs.value;
}

/// The grid's points as (centre x, centre y, tangent y) index triples, flattened.
struct GridIndex {
  int nx, ny, nt;
  int flat(int ix, int iy, int it) const { return (ix * ny + iy) * nt + it; }
};

}  // namespace

CriticalCircle searchCriticalCircleBy(const SlopeSection& section, const CircleSearchGrid& grid,
                                      const CircleObjective& objective) {
  CriticalCircle best;
  // First pass: the whole grid, every F kept.
  const GridIndex index{grid.centre_x_count, grid.centre_y_count, grid.tangent_count};
  std::vector<Real> factors(static_cast<std::size_t>(index.nx * index.ny * index.nt));
  for (int ix = 0; ix < index.nx; ++ix)
    for (int iy = 0; iy < index.ny; ++iy)
      for (int it = 0; it < index.nt; ++it) {
        const Real xc = gridValue(grid.centre_x_min, grid.centre_x_max, index.nx, ix);
        const Real yc = gridValue(grid.centre_y_min, grid.centre_y_max, index.ny, iy);
        const Real yt = gridValue(grid.tangent_y_min, grid.tangent_y_max, index.nt, it);
        factors[static_cast<std::size_t>(index.flat(ix, iy, it))] =
            tryCircle(section, grid, objective, SlipCircle{xc, yc, yc - yt}, best);
      }
  if (!best.found) return best;

  // Starts of the refinement: the grid's local minima (F no larger than at any admissible
  // neighbour of the 3 x 3 x 3 block), lowest first, at most grid.starts of them. One start
  // is the global best point; more guard against the refinement settling in the basin of a
  // coarse point while a narrow deeper basin (e.g. shallow circles at a minimum depth) lies
  // between grid points elsewhere.
  std::vector<std::pair<Real, int>> minima;
  for (int ix = 0; ix < index.nx; ++ix)
    for (int iy = 0; iy < index.ny; ++iy)
      for (int it = 0; it < index.nt; ++it) {
        const Real f = factors[static_cast<std::size_t>(index.flat(ix, iy, it))];
        if (!std::isfinite(f)) continue;
        bool lowest = true;
        for (int dx = -1; dx <= 1 && lowest; ++dx)
          for (int dy = -1; dy <= 1 && lowest; ++dy)
            for (int dt = -1; dt <= 1 && lowest; ++dt) {
              const int jx = ix + dx, jy = iy + dy, jt = it + dt;
              if (jx < 0 || jy < 0 || jt < 0 || jx >= index.nx || jy >= index.ny || jt >= index.nt)
                continue;
              const Real g = factors[static_cast<std::size_t>(index.flat(jx, jy, jt))];
              if (std::isfinite(g) && g < f) lowest = false;
            }
        if (lowest) minima.emplace_back(f, index.flat(ix, iy, it));
      }
  std::sort(minima.begin(), minima.end());
  if (static_cast<int>(minima.size()) > std::max(grid.starts, 1))
    minima.resize(static_cast<std::size_t>(std::max(grid.starts, 1)));

  const Real sx0 = gridStep(grid.centre_x_min, grid.centre_x_max, index.nx);
  const Real sy0 = gridStep(grid.centre_y_min, grid.centre_y_max, index.ny);
  const Real st0 = gridStep(grid.tangent_y_min, grid.tangent_y_max, index.nt);
  for (const auto& [factor, flat] : minima) {
    (void)factor;
    const int ix = flat / (index.ny * index.nt), iy = (flat / index.nt) % index.ny,
              it = flat % index.nt;
    // Around this start: passes of the same counts spanning one former spacing on either
    // side of the start's best point, each about (count - 1) / 2 times finer.
    Real cx = gridValue(grid.centre_x_min, grid.centre_x_max, index.nx, ix);
    Real cy = gridValue(grid.centre_y_min, grid.centre_y_max, index.ny, iy);
    Real ct = gridValue(grid.tangent_y_min, grid.tangent_y_max, index.nt, it);
    Real local_f = factors[static_cast<std::size_t>(flat)];
    Real sx = sx0, sy = sy0, st = st0;
    for (int p = 1; p <= grid.refinements; ++p) {
      const Real px = cx, py = cy, pt = ct;
      for (int jx = 0; jx < index.nx; ++jx)
        for (int jy = 0; jy < index.ny; ++jy)
          for (int jt = 0; jt < index.nt; ++jt) {
            const Real xc = gridValue(px - sx, px + sx, index.nx, jx);
            const Real yc = gridValue(py - sy, py + sy, index.ny, jy);
            const Real yt = gridValue(pt - st, pt + st, index.nt, jt);
            const Real f = tryCircle(section, grid, objective, SlipCircle{xc, yc, yc - yt}, best);
            if (std::isfinite(f) && f < local_f) {
              local_f = f;
              cx = xc;
              cy = yc;
              ct = yt;
            }
          }
      sx = gridStep(px - sx, px + sx, index.nx);
      sy = gridStep(py - sy, py + sy, index.ny);
      st = gridStep(pt - st, pt + st, index.nt);
    }
  }
  const Real external = endForceDriving(best.mass, best.circle);
  best.bishop = bishopSimplified(best.mass.slices, {}, external);
  best.ordinary = ordinaryMethodOfSlices(best.mass.slices, external);
  return best;
}

}  // namespace argine

#include "argine/slopestability/CircleSearch.hpp"

#include <algorithm>

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
      searchCriticalCircleBy(section, grid, [&options](const SlipMass& mass, const SlipCircle&) {
        return bishopSimplified(mass.slices, options);
      });
  if (best.found) best.bishop = best.objective;
  return best;
}

CriticalCircle searchCriticalCircleBy(const SlopeSection& section, const CircleSearchGrid& grid,
                                      const CircleObjective& objective) {
  CriticalCircle best;
  CircleSearchGrid pass = grid;
  Real best_tangent = 0;
  for (int p = 0; p <= grid.refinements; ++p) {
    for (int ix = 0; ix < pass.centre_x_count; ++ix) {
      for (int iy = 0; iy < pass.centre_y_count; ++iy) {
        for (int it = 0; it < pass.tangent_count; ++it) {
          const Real xc = gridValue(pass.centre_x_min, pass.centre_x_max, pass.centre_x_count, ix);
          const Real yc = gridValue(pass.centre_y_min, pass.centre_y_max, pass.centre_y_count, iy);
          const Real yt = gridValue(pass.tangent_y_min, pass.tangent_y_max, pass.tangent_count, it);
          ++best.evaluated;
          const SlipCircle circle{xc, yc, yc - yt};
          SlipMass mass = sliceCircle(section, circle, grid.slice_count, grid.split_at_materials);
          if (!mass.valid || !withinSearchLimits(mass, grid)) {
            ++best.rejected;
            continue;
          }
          const FactorOfSafety fs = objective(mass, circle);
          if (!fs.admissible) {
            ++best.rejected;
            continue;
          }
          if (!best.found || fs.value < best.objective.value) {
            best.found = true;
            best.circle = circle;
            best.objective = fs;
            best.mass = std::move(mass);
            best_tangent = yt;
          }
        }
      }
    }
    if (!best.found) break;
    // Next pass: one former spacing on either side of the best point.
    const Real sx = gridStep(pass.centre_x_min, pass.centre_x_max, pass.centre_x_count);
    const Real sy = gridStep(pass.centre_y_min, pass.centre_y_max, pass.centre_y_count);
    const Real st = gridStep(pass.tangent_y_min, pass.tangent_y_max, pass.tangent_count);
    pass.centre_x_min = best.circle.centre_x - sx;
    pass.centre_x_max = best.circle.centre_x + sx;
    pass.centre_y_min = best.circle.centre_y - sy;
    pass.centre_y_max = best.circle.centre_y + sy;
    pass.tangent_y_min = best_tangent - st;
    pass.tangent_y_max = best_tangent + st;
  }
  if (best.found) {
    best.bishop = bishopSimplified(best.mass.slices);
    best.ordinary = ordinaryMethodOfSlices(best.mass.slices);
  }
  return best;
}

}  // namespace argine

#include "argine/slopestability/BlockSearch.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "argine/slopestability/PolylineSlip.hpp"

namespace argine {

namespace {

constexpr int kParameters = 5;  // left end, left vertex, right vertex, right end, offset
using Parameters = std::array<Real, kParameters>;

struct Window {
  Parameters lo, hi;
};

Window windowsOf(const BlockSearchWindows& w) {
  return {{w.left_end_min, w.left_vertex_min, w.right_vertex_min, w.right_end_min, w.offset_min},
          {w.left_end_max, w.left_vertex_max, w.right_vertex_max, w.right_end_max, w.offset_max}};
}

/// The four-point surface of parameters p; false when the abscissae do not increase.
bool surfaceOf(const SlopeSection& section, const BlockSearchWindows& w, const Parameters& p,
               Polyline& surface) {
  if (!(p[0] < p[1] && p[1] < p[2] && p[2] < p[3])) return false;
  surface.x = {p[0], p[1], p[2], p[3]};
  surface.y = {section.ground.at(p[0]), w.plane.at(p[1]) + p[4], w.plane.at(p[2]) + p[4],
               section.ground.at(p[3])};
  const Real left = std::atan(std::abs(surface.y[1] - surface.y[0]) / (p[1] - p[0]));
  const Real right = std::atan(std::abs(surface.y[3] - surface.y[2]) / (p[3] - p[2]));
  return left <= w.max_left_end_inclination && right <= w.max_right_end_inclination;
}

}  // namespace

CriticalBlock searchCriticalBlock(const SlopeSection& section, const BlockSearchWindows& windows,
                                  const SpencerOptions& options) {
  CriticalBlock best;
  const Window box = windowsOf(windows);
  const auto evaluate = [&](const Parameters& p) {
    ++best.evaluated;
    Polyline surface;
    if (!surfaceOf(section, windows, p, surface)) {
      ++best.rejected;
      return false;
    }
    SlipMass mass =
        slicePolyline(section, surface, windows.slice_count, windows.split_at_materials);
    if (!mass.valid) {
      ++best.rejected;
      return false;
    }
    const SpencerFactor f = spencer(mass.slices, options);
    if (!f.factor.admissible) {
      ++best.rejected;
      return false;
    }
    if (best.found && !(f.factor.value < best.spencer.factor.value)) return false;
    best.found = true;
    best.surface = surface;
    best.spencer = f;
    best.mass = std::move(mass);
    return true;
  };

  // Grid over the windows.
  const int n = std::max(windows.grid_count, 1);
  Parameters step{};
  for (int d = 0; d < kParameters; ++d) {
    step[d] = n > 1 ? (box.hi[d] - box.lo[d]) / (n - 1) : 0;
  }
  Parameters best_p{};
  std::array<int, kParameters> index{};
  for (;;) {
    Parameters p;
    for (int d = 0; d < kParameters; ++d) p[d] = box.lo[d] + step[d] * index[d];
    if (evaluate(p)) best_p = p;
    int d = 0;
    while (d < kParameters && ++index[d] == n) index[d++] = 0;
    if (d == kParameters) break;
  }
  if (!best.found) return best;

  // Compass search from the best grid point, inside the windows.
  for (int d = 0; d < kParameters; ++d) {
    if (!(step[d] > 0)) step[d] = 0.5 * (box.hi[d] - box.lo[d]);
  }
  while (best.evaluated < windows.max_evaluations) {
    bool improved = false;
    for (int d = 0; d < kParameters; ++d) {
      for (const Real sign : {Real(1), Real(-1)}) {
        Parameters p = best_p;
        p[d] = std::clamp(p[d] + sign * step[d], box.lo[d], box.hi[d]);
        if (p[d] != best_p[d] && evaluate(p)) {
          best_p = p;
          improved = true;
        }
      }
    }
    if (improved) continue;
    Real largest = 0;
    for (int d = 0; d < kParameters; ++d) {
      step[d] *= 0.5;
      largest = std::max(largest, step[d]);
    }
    if (largest < windows.step_tolerance) break;
  }
  return best;
}

}  // namespace argine

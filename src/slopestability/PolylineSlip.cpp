#include "argine/slopestability/PolylineSlip.hpp"

#include <algorithm>
#include <cmath>

#include "argine/slopestability/Slicing.hpp"

namespace argine {

namespace {

/// Inclination of the segment of `p` that contains xq (the right one at a vertex).
Real segmentAngle(const Polyline& p, Real xq) {
  std::size_t i =
      static_cast<std::size_t>(std::upper_bound(p.x.begin(), p.x.end(), xq) - p.x.begin());
  i = std::clamp<std::size_t>(i, 1, p.x.size() - 1);
  return std::atan2(p.y[i] - p.y[i - 1], p.x[i] - p.x[i - 1]);
}

}  // namespace

SlipMass slicePolyline(const SlopeSection& section, const Polyline& surface, int slice_count,
                       bool split_at_materials) {
  SlipMass mass;
  if (surface.x.size() < 2 || slice_count < 1) {
    mass.reason = "fewer than two points or no slices";
    return mass;
  }
  // ground - surface is linear between the merged vertices of both lines.
  std::vector<Real> xs = surface.x;
  for (const Real xg : section.ground.x) {
    if (xg > surface.xFirst() && xg < surface.xLast()) xs.push_back(xg);
  }
  std::sort(xs.begin(), xs.end());
  const Real span = surface.xLast() - surface.xFirst();
  const Real tol = 1e-9 * span;
  std::vector<Real> depth;  // ground - surface at xs
  for (const Real x : xs) depth.push_back(section.ground.at(x) - surface.at(x));
  if (depth.front() > tol || depth.back() > tol) {
    mass.reason = "the polyline starts or ends below the ground";
    return mass;
  }
  bool entered = false;
  for (std::size_t i = 1; i < xs.size(); ++i) {
    const Real d0 = depth[i - 1], d1 = depth[i];
    if (d0 <= tol && d1 > tol) {  // goes below the ground
      const Real x = d0 >= 0 ? xs[i - 1] : xs[i - 1] + (xs[i] - xs[i - 1]) * d0 / (d0 - d1);
      if (!entered) mass.entry_x = x;
      entered = true;
    }
    if (d0 > tol && d1 <= tol) {  // comes back up
      mass.exit_x = d1 >= 0 ? xs[i] : xs[i - 1] + (xs[i] - xs[i - 1]) * d0 / (d0 - d1);
    }
  }
  if (!entered || !(mass.exit_x > mass.entry_x)) {
    mass.reason = "the polyline does not go below the ground";
    return mass;
  }
  if (mass.entry_x < section.ground.xFirst() || mass.exit_x > section.ground.xLast()) {
    mass.reason = "the sliding mass runs out of the ground line";
    return mass;
  }
  Real lowest = std::min(surface.at(mass.entry_x), surface.at(mass.exit_x));
  for (std::size_t i = 0; i < surface.x.size(); ++i) {
    if (surface.x[i] > mass.entry_x && surface.x[i] < mass.exit_x) {
      lowest = std::min(lowest, surface.y[i]);
    }
  }
  if (lowest < section.floor) {
    mass.reason = "the slip surface goes below the floor of the section";
    return mass;
  }

  const SlipBase base{[&surface](Real x) { return surface.at(x); },
                      [&surface](Real x) { return segmentAngle(surface, x); }};
  sliceMass(section, base, slice_count, split_at_materials, surface.x, mass);
  return mass;
}

}  // namespace argine

#include "argine/slopestability/CircularSlip.hpp"

#include <algorithm>
#include <cmath>

#include "argine/slopestability/Slicing.hpp"

namespace argine {

namespace {

/// Elevation of the lower arc at x (|x - centre_x| <= R).
Real lowerArcY(const SlipCircle& c, Real x) {
  const Real dx = x - c.centre_x;
  return c.centre_y - std::sqrt(std::max(c.radius * c.radius - dx * dx, Real(0)));
}

}  // namespace

std::vector<Real> lowerArcGroundCrossings(const SlopeSection& section, const SlipCircle& c) {
  std::vector<Real> crossings;
  const Polyline& g = section.ground;
  for (std::size_t i = 1; i < g.x.size(); ++i) {
    // Segment P0 + t (P1 - P0), t in [0, 1], against |P - C| = R: a quadratic in t.
    const Real px = g.x[i - 1] - c.centre_x, py = g.y[i - 1] - c.centre_y;
    const Real dx = g.x[i] - g.x[i - 1], dy = g.y[i] - g.y[i - 1];
    const Real a = dx * dx + dy * dy;
    const Real b = 2 * (px * dx + py * dy);
    const Real cc = px * px + py * py - c.radius * c.radius;
    const Real disc = b * b - 4 * a * cc;
    if (disc < 0) continue;
    const Real root = std::sqrt(disc);
    for (const Real t : {(-b - root) / (2 * a), (-b + root) / (2 * a)}) {
      if (t < 0 || t > 1) continue;
      if (py + t * dy > 0) continue;  // upper half of the circle
      crossings.push_back(g.x[i - 1] + t * dx);
    }
  }
  std::sort(crossings.begin(), crossings.end());
  crossings.erase(std::unique(crossings.begin(), crossings.end(),
                              [](Real p, Real q) { return std::abs(p - q) <= 1e-12; }),
                  crossings.end());
  return crossings;
}

Real endForceDriving(const SlipMass& mass, const SlipCircle& circle) {
  Real driving = 0;
  for (const HorizontalForce& h : mass.end_forces)
    driving -= h.force * (circle.centre_y - h.y) / circle.radius;
  return driving;
}

SlipMass sliceCircle(const SlopeSection& section, const SlipCircle& c, int slice_count,
                     bool split_at_materials) {
  SlipMass mass;
  if (c.radius <= 0 || slice_count < 1) {
    mass.reason = "radius or slice count not positive";
    return mass;
  }
  const std::vector<Real> crossings = lowerArcGroundCrossings(section, c);
  if (crossings.size() < 2) {
    mass.reason = "the lower arc does not cut the ground twice";
    return mass;
  }
  mass.entry_x = crossings.front();
  mass.exit_x = crossings.back();
  const Polyline& g = section.ground;
  // The arc must come back to the ground inside the ground line: beyond the outermost
  // crossings it must lie above the ground (or end), otherwise the mass runs out of the
  // section.
  for (const Real end : {g.xFirst(), g.xLast()}) {
    if (std::abs(end - c.centre_x) < c.radius && (end < mass.entry_x || end > mass.exit_x) &&
        lowerArcY(c, end) < g.at(end)) {
      mass.reason = "the sliding mass runs out of the ground line";
      return mass;
    }
  }
  const Real lowest = (c.centre_x > mass.entry_x && c.centre_x < mass.exit_x)
                          ? c.centre_y - c.radius
                          : std::min(lowerArcY(c, mass.entry_x), lowerArcY(c, mass.exit_x));
  if (lowest < section.floor) {
    mass.reason = "the slip surface goes below the floor of the section";
    return mass;
  }

  const SlipBase base{
      [&c](Real x) { return lowerArcY(c, x); },
      [&c](Real x) {
        return std::asin(std::clamp((x - c.centre_x) / c.radius, Real(-1), Real(1)));
      }};
  sliceMass(section, base, slice_count, split_at_materials, {}, mass);
  return mass;
}

}  // namespace argine

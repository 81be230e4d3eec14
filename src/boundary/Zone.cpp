#include "argine/boundary/Zone.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "argine/input/Deck.hpp"

namespace argine {

Zone makeZone(const ZoneSpec& spec) {
  Zone zone;
  switch (spec.kind) {
    case ZoneSpec::Kind::Everywhere:
      zone.kind = Zone::Kind::Everywhere;
      break;
    case ZoneSpec::Kind::HalfPlane: {
      zone.kind = Zone::Kind::HalfPlane;
      zone.point = spec.point;
      const Real length = std::hypot(spec.direction[0], spec.direction[1]);
      zone.direction = {spec.direction[0] / length, spec.direction[1] / length};
      break;
    }
    case ZoneSpec::Kind::Box:
      zone.kind = Zone::Kind::Box;
      zone.lower_left = spec.lower_left;
      zone.upper_right = spec.upper_right;
      break;
    case ZoneSpec::Kind::PolylineBand:
      zone.kind = Zone::Kind::PolylineBand;
      zone.vertices = spec.vertices;
      zone.width = spec.width;
      break;
  }
  return zone;
}

Real distanceToSegment(const std::array<Real, 2>& a, const std::array<Real, 2>& b, Real x, Real y) {
  const Real ex = b[0] - a[0], ey = b[1] - a[1];
  const Real length2 = ex * ex + ey * ey;
  // parameter of the closest point, clamped to the segment
  const Real t =
      length2 > 0 ? std::clamp(((x - a[0]) * ex + (y - a[1]) * ey) / length2, 0.0, 1.0) : 0.0;
  return std::hypot(x - (a[0] + t * ex), y - (a[1] + t * ey));
}

Real distanceToPolyline(const std::vector<std::array<Real, 2>>& vertices, Real x, Real y) {
  if (vertices.size() == 1) return std::hypot(x - vertices[0][0], y - vertices[0][1]);
  Real nearest = std::numeric_limits<Real>::infinity();
  for (std::size_t k = 0; k + 1 < vertices.size(); ++k)
    nearest = std::min(nearest, distanceToSegment(vertices[k], vertices[k + 1], x, y));
  return nearest;
}

bool zoneContains(const Zone& zone, Real x, Real y) {
  switch (zone.kind) {
    case Zone::Kind::Everywhere:
      return true;
    case Zone::Kind::HalfPlane:
      return (x - zone.point[0]) * zone.direction[0] + (y - zone.point[1]) * zone.direction[1] >= 0;
    case Zone::Kind::Box:
      return x >= zone.lower_left[0] && x <= zone.upper_right[0] && y >= zone.lower_left[1] &&
             y <= zone.upper_right[1];
    case Zone::Kind::PolylineBand:
      return !zone.vertices.empty() && distanceToPolyline(zone.vertices, x, y) <= zone.width;
  }
  return false;
}

}  // namespace argine

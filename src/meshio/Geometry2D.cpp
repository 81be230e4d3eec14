#include "argine/meshio/Geometry2D.hpp"

#include <algorithm>
#include <cmath>

namespace argine {

Real signedArea(const std::vector<Point2>& polygon) {
  const std::size_t n = polygon.size();
  Real twice_area = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Point2& p = polygon[i];
    const Point2& q = polygon[(i + 1) % n];
    twice_area += p[0] * q[1] - q[0] * p[1];
  }
  return 0.5 * twice_area;
}

bool isInsidePolygon(const Point2& p, const std::vector<Point2>& polygon) {
  // Crossing number of a ray towards +x; edges are half-open in y so vertices count once.
  bool inside = false;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point2& a = polygon[i];
    const Point2& b = polygon[j];
    if ((a[1] > p[1]) != (b[1] > p[1])) {
      const Real x_cross = a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
      if (p[0] < x_cross) inside = !inside;
    }
  }
  return inside;
}

Real distanceToSegment(const Point2& p, const Point2& a, const Point2& b) {
  const Real dx = b[0] - a[0], dy = b[1] - a[1];
  const Real length2 = dx * dx + dy * dy;
  Real t = length2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length2 : 0;
  t = std::clamp(t, Real(0), Real(1));
  return std::hypot(p[0] - (a[0] + t * dx), p[1] - (a[1] + t * dy));
}

bool segmentsCross(const Point2& a, const Point2& b, const Point2& c, const Point2& d,
                   Real tolerance, Point2* where) {
  // Orientation values are twice triangle areas: scale the tolerance by the lengths.
  const Real scale = std::hypot(b[0] - a[0], b[1] - a[1]) * std::hypot(d[0] - c[0], d[1] - c[1]);
  const Real eps = tolerance * scale;
  const Real o1 = orientation(a, b, c), o2 = orientation(a, b, d);
  const Real o3 = orientation(c, d, a), o4 = orientation(c, d, b);
  const bool crosses = ((o1 > eps && o2 < -eps) || (o1 < -eps && o2 > eps)) &&
                       ((o3 > eps && o4 < -eps) || (o3 < -eps && o4 > eps));
  if (crosses && where) {
    const Real t = o3 / (o3 - o4);
    *where = {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};
  }
  return crosses;
}

Real angleDegrees(const Point2& a, const Point2& b, const Point2& c) {
  const Real ux = a[0] - b[0], uy = a[1] - b[1];
  const Real vx = c[0] - b[0], vy = c[1] - b[1];
  // atan2(|cross|, dot) is accurate for small and large angles alike.
  const Real angle = std::atan2(std::abs(ux * vy - uy * vx), ux * vx + uy * vy);
  return angle * 180.0 / M_PI;
}

Real minimumAngleDegrees(const Point2& a, const Point2& b, const Point2& c) {
  if (orientation(a, b, c) == 0) return 0;
  return std::min({angleDegrees(c, a, b), angleDegrees(a, b, c), angleDegrees(b, c, a)});
}

}  // namespace argine

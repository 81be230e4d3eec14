#pragma once
/// @file Geometry2D.hpp
/// Small plane-geometry helpers of the mesh readers and generators (polygons, segments,
/// triangle angles). Plain double arithmetic: callers keep tolerances in mind.

#include <array>
#include <vector>

#include "argine/core/Types.hpp"

namespace argine {

/// A point or vector of the plane (m).
using Point2 = std::array<Real, 2>;

/// Twice the signed area of triangle abc: > 0 when a, b, c turn counter-clockwise.
inline Real orientation(const Point2& a, const Point2& b, const Point2& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/// Signed area of a polygon (shoelace formula): > 0 for counter-clockwise vertices.
Real signedArea(const std::vector<Point2>& polygon);

/// True when p lies inside the polygon (even-odd rule). Points on the boundary may go
/// either way: callers test points well inside or well outside (e.g. element centroids
/// of a mesh that conforms to the polygon).
bool isInsidePolygon(const Point2& p, const std::vector<Point2>& polygon);

/// Distance from p to the segment ab.
Real distanceToSegment(const Point2& p, const Point2& a, const Point2& b);

/// True when the segments ab and cd cross at a point interior to both (a proper crossing,
/// with a relative tolerance `tolerance` on the orientation tests); `where` gets the point.
bool segmentsCross(const Point2& a, const Point2& b, const Point2& c, const Point2& d,
                   Real tolerance, Point2* where);

/// Smallest interior angle of triangle abc (degrees); 0 for a degenerate triangle.
Real minimumAngleDegrees(const Point2& a, const Point2& b, const Point2& c);

/// Interior angle at vertex b of the corner a-b-c (degrees, in [0, 180]).
Real angleDegrees(const Point2& a, const Point2& b, const Point2& c);

}  // namespace argine

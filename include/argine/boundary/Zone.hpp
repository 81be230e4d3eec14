#pragma once
/// @file Zone.hpp
/// Where on the CURRENT free boundary a hydraulic condition applies (thesis Sec. 4: "if the
/// boundary node lies inside the area where a specified condition has to be applied, e.g.
/// in the infiltration zone or on the potential seepage face, the corresponding boundary
/// condition is applied"). A zone is a region of the plane, tested at the midpoints of the
/// free sides each step, so the condition follows the soil surface as it moves.
///
/// Kinds: everywhere; half-plane {x : (x - point) . direction >= 0} (e.g. "x < 8 m" is
/// point (8, 0), direction (-1, 0)); box [lower_left, upper_right]; polyline band
/// {x : distance(x, polyline) <= width}. Plain data and free functions (the implicit
/// seepage solver can use them too).

#include <array>
#include <vector>

#include "argine/core/Types.hpp"

namespace argine {

struct ZoneSpec;

struct Zone {
  enum class Kind { Everywhere, HalfPlane, Box, PolylineBand } kind = Kind::Everywhere;
  std::array<Real, 2> point{0.0, 0.0};        ///< half-plane: a point on its edge (m)
  std::array<Real, 2> direction{0.0, 1.0};    ///< half-plane: unit vector pointing inside
  std::array<Real, 2> lower_left{0.0, 0.0};   ///< box (m)
  std::array<Real, 2> upper_right{0.0, 0.0};  ///< box (m)
  std::vector<std::array<Real, 2>> vertices;  ///< polyline band: polyline vertices (m)
  Real width = 0;                             ///< polyline band: half-width (m)
};

/// The zone of a deck spec (the half-plane direction normalised; a zero direction or a
/// polyline of fewer than 2 vertices is rejected by the deck reader).
Zone makeZone(const ZoneSpec& spec);

/// Distance (m) from (x, y) to the segment a-b.
Real distanceToSegment(const std::array<Real, 2>& a, const std::array<Real, 2>& b, Real x, Real y);

/// Distance (m) from (x, y) to a polyline (its vertices joined in order).
Real distanceToPolyline(const std::vector<std::array<Real, 2>>& vertices, Real x, Real y);

/// Whether (x, y) lies in the zone (edges included).
bool zoneContains(const Zone& zone, Real x, Real y);

}  // namespace argine

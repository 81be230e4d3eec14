#pragma once
/// @file MeshRegions.hpp
/// Which soil region of a `rectangle` mesh with Regions (Mesh::regions) holds a position.
/// One rule serves the generator (an element's block is the region holding its centroid)
/// and the seeding (a pattern position is seeded with the material of the region holding
/// it), so the two never disagree:
///
///   the FIRST region, in deck order, whose CLOSED polygon holds the position; -1 if none.
///
/// "Closed": a position within `tolerance()` (1e-9 of the regions' extent) of a region's
/// edge counts as on it, hence inside. So a position on an edge shared by two regions goes
/// to exactly one of them (the earlier), whatever the rounding of the two copies of that
/// edge, and a pattern position on a 45-degree slope through cell corners is soil.
/// Regions never overlap (the generator refuses that), so only their shared edges decide
/// anything by order.

#include <array>
#include <vector>

#include "argine/mesh/Mesh.hpp"

namespace argine {

class RegionLocator {
 public:
  explicit RegionLocator(const std::vector<BlockRegion>& regions);

  /// Index into the regions of the one holding p (the rule above), or -1.
  int regionAt(const std::array<Real, kDim>& p) const;
  /// True when region r's bounding box meets the box [low, high] (closed, with the
  /// tolerance): a cheap test before looking at an element's positions one by one.
  bool mayTouch(int r, const std::array<Real, kDim>& low, const std::array<Real, kDim>& high) const;
  /// Distance (m) within which a position counts as on a region edge.
  Real tolerance() const { return tolerance_; }

 private:
  bool holds(int r, const std::array<Real, kDim>& p) const;

  const std::vector<BlockRegion>* regions_;
  std::vector<std::array<Real, 2 * kDim>> bounds_;  ///< x_min, y_min, x_max, y_max per region
  Real tolerance_ = 0;
};

}  // namespace argine

#include "argine/mesh/MeshRegions.hpp"

#include <algorithm>
#include <cmath>

namespace argine {

namespace {

using Point = std::array<Real, kDim>;

/// Relative size of the band around a region edge that counts as on the edge: far above the
/// rounding of positions mapped from local coordinates (1e-16 of the coordinates), far below
/// any pattern spacing a mesh of at most 1e8 cells can have.
constexpr Real kOnEdge = 1e-9;

Real distanceToSegment(const Point& p, const Point& a, const Point& b) {
  const Real dx = b[0] - a[0], dy = b[1] - a[1];
  const Real length2 = dx * dx + dy * dy;
  Real t = length2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length2 : 0;
  t = std::clamp(t, Real(0), Real(1));
  return std::hypot(p[0] - (a[0] + t * dx), p[1] - (a[1] + t * dy));
}

/// Even-odd rule with a ray towards +x; positions on the boundary may go either way, which
/// is why holds() tests the distance to the edges first.
bool insideOpen(const Point& p, const std::vector<Point>& polygon) {
  bool inside = false;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point& a = polygon[i];
    const Point& b = polygon[j];
    if ((a[1] > p[1]) != (b[1] > p[1])) {
      const Real x_cross = a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
      if (p[0] < x_cross) inside = !inside;
    }
  }
  return inside;
}

}  // namespace

RegionLocator::RegionLocator(const std::vector<BlockRegion>& regions) : regions_(&regions) {
  Real extent = 0;
  for (const BlockRegion& region : regions) {
    std::array<Real, 2 * kDim> box{INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (const Point& v : region.vertices)
      for (int d = 0; d < kDim; ++d) {
        box[d] = std::min(box[d], v[d]);
        box[kDim + d] = std::max(box[kDim + d], v[d]);
      }
    for (int d = 0; d < kDim; ++d) extent = std::max(extent, box[kDim + d] - box[d]);
    bounds_.push_back(box);
  }
  tolerance_ = kOnEdge * extent;
}

bool RegionLocator::mayTouch(int r, const Point& low, const Point& high) const {
  const auto& box = bounds_[r];
  for (int d = 0; d < kDim; ++d)
    if (high[d] < box[d] - tolerance_ || low[d] > box[kDim + d] + tolerance_) return false;
  return true;
}

bool RegionLocator::holds(int r, const Point& p) const {
  if (!mayTouch(r, p, p)) return false;
  const auto& polygon = (*regions_)[r].vertices;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i)
    if (distanceToSegment(p, polygon[i], polygon[(i + 1) % n]) <= tolerance_) return true;
  return insideOpen(p, polygon);
}

int RegionLocator::regionAt(const Point& p) const {
  for (std::size_t r = 0; r < regions_->size(); ++r)
    if (holds(static_cast<int>(r), p)) return static_cast<int>(r);
  return -1;
}

}  // namespace argine

#include "argine/init/VerticalColumns.hpp"

#include <algorithm>
#include <cmath>

#include "argine/input/Deck.hpp"
#include "argine/mesh/Mesh.hpp"

namespace argine {

namespace {

bool hasRegions(const Mesh& mesh, const ElementBlock& block) {
  const int index = static_cast<int>(&block - mesh.blocks.data());
  return std::any_of(mesh.regions.begin(), mesh.regions.end(),
                     [&](const BlockRegion& region) { return region.block == index; });
}

/// Heights where the vertical line at x crosses the polygon's edges, pairwise the inside.
/// Edges are half-open in x, so a vertex on the line counts once and a vertical edge never.
std::vector<Real> crossings(const std::vector<std::array<Real, 2>>& polygon, Real x) {
  std::vector<Real> heights;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const auto& a = polygon[i];
    const auto& b = polygon[j];
    if ((a[0] > x) != (b[0] > x))
      heights.push_back(a[1] + (x - a[0]) * (b[1] - a[1]) / (b[0] - a[0]));
  }
  std::sort(heights.begin(), heights.end());
  return heights;
}

}  // namespace

std::vector<int> elementMaterials(const Mesh& mesh, const std::vector<MaterialSpec>& materials) {
  std::vector<int> material_of(mesh.numElements(), -1);
  for (std::size_t m = 0; m < materials.size(); ++m) {
    const ElementBlock* block = mesh.findBlock(materials[m].block);
    if (!block || hasRegions(mesh, *block)) continue;
    for (int e : block->elements) material_of[e] = static_cast<int>(m);
  }
  return material_of;
}

std::vector<MaterialPolygon> regionMaterials(const Mesh& mesh,
                                             const std::vector<MaterialSpec>& materials) {
  std::vector<MaterialPolygon> polygons;
  for (const BlockRegion& region : mesh.regions)
    for (std::size_t m = 0; m < materials.size(); ++m)
      if (materials[m].block == mesh.blocks[region.block].name)
        polygons.push_back({region.vertices, static_cast<int>(m)});
  return polygons;
}

VerticalColumns::VerticalColumns(const Mesh& mesh, std::vector<int> element_material,
                                 std::vector<MaterialPolygon> polygons)
    : element_material_(std::move(element_material)), polygons_(std::move(polygons)) {
  const auto coordinates =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  const auto connectivity =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.connectivity);
  const int elements = mesh.numElements(), corners = mesh.nodesPerElement();
  corners_.resize(elements);
  Real x_min = INFINITY, x_max = -INFINITY, width_sum = 0;
  for (int e = 0; e < elements; ++e) {
    Real lo = INFINITY, hi = -INFINITY;
    for (int c = 0; c < corners; ++c) {
      const int node = connectivity(e, c);
      corners_[e].push_back(coordinates(node, 0));
      corners_[e].push_back(coordinates(node, 1));
      lo = std::min(lo, coordinates(node, 0));
      hi = std::max(hi, coordinates(node, 0));
    }
    x_min = std::min(x_min, lo);
    x_max = std::max(x_max, hi);
    width_sum += hi - lo;
  }
  if (elements == 0) return;
  x_min_ = x_min;
  const Real span = std::max<Real>(x_max - x_min, 1e-12);
  const int count = std::max(
      1, std::min(4 * elements, static_cast<int>(std::ceil(span / (width_sum / elements)))));
  bin_width_ = span / count;
  bins_.assign(count, {});
  for (int e = 0; e < elements; ++e) {
    if (element_material_[e] < 0) continue;
    Real lo = INFINITY, hi = -INFINITY;
    for (int c = 0; c < corners; ++c) {
      lo = std::min(lo, corners_[e][2 * c]);
      hi = std::max(hi, corners_[e][2 * c]);
    }
    for (int b = binOf(lo); b <= binOf(hi); ++b) bins_[b].push_back(e);
  }
}

int VerticalColumns::binOf(Real x) const {
  const int b = static_cast<int>(std::floor((x - x_min_) / bin_width_));
  return std::clamp(b, 0, static_cast<int>(bins_.size()) - 1);
}

std::vector<ColumnInterval> VerticalColumns::intervals(Real x, Real y_low, Real y_high) const {
  std::vector<ColumnInterval> found;
  if (!(y_high > y_low)) return found;
  for (const MaterialPolygon& polygon : polygons_) {
    const std::vector<Real> heights = crossings(polygon.vertices, x);
    for (std::size_t i = 0; i + 1 < heights.size(); i += 2) {
      const Real lo = std::max(heights[i], y_low), hi = std::min(heights[i + 1], y_high);
      if (hi > lo) found.push_back({lo, hi, polygon.material});
    }
  }
  static const std::vector<int> kNoElements;
  for (int e : bins_.empty() ? kNoElements : bins_[binOf(x)]) {
    // The vertical line meets a convex element in one segment: the heights where it crosses
    // the element's edges (a vertical edge on the line gives both its ends).
    const auto& c = corners_[e];
    const int n = static_cast<int>(c.size() / 2);
    Real lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < n; ++i) {
      const Real xa = c[2 * i], ya = c[2 * i + 1];
      const Real xb = c[2 * ((i + 1) % n)], yb = c[2 * ((i + 1) % n) + 1];
      if (x < std::min(xa, xb) || x > std::max(xa, xb)) continue;
      if (xa == xb) {
        lo = std::min({lo, ya, yb});
        hi = std::max({hi, ya, yb});
        continue;
      }
      const Real y = ya + (x - xa) / (xb - xa) * (yb - ya);
      lo = std::min(lo, y);
      hi = std::max(hi, y);
    }
    lo = std::max(lo, y_low);
    hi = std::min(hi, y_high);
    if (hi > lo) found.push_back({lo, hi, element_material_[e]});
  }
  std::sort(found.begin(), found.end(),
            [](const ColumnInterval& a, const ColumnInterval& b) { return a.y_low < b.y_low; });
  // Remove overlaps (elements on both sides of an edge the line runs along).
  std::vector<ColumnInterval> merged;
  Real reach = -INFINITY;
  for (ColumnInterval interval : found) {
    interval.y_low = std::max(interval.y_low, reach);
    if (!(interval.y_high > interval.y_low)) continue;
    reach = interval.y_high;
    merged.push_back(interval);
  }
  return merged;
}

}  // namespace argine

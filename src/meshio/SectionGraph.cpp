#include "argine/meshio/SectionGraph.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <utility>

#include "argine/core/Error.hpp"

namespace argine {

namespace {

const std::string kWhere = "Mesh/Generate";

std::string str(const Point2& p) {
  std::ostringstream out;
  out << "(" << p[0] << ", " << p[1] << ")";
  return out.str();
}

/// Index of a vertex within `tolerance` of p, adding p when there is none.
int mergeVertex(std::vector<Point2>& vertices, const Point2& p, Real tolerance) {
  for (std::size_t i = 0; i < vertices.size(); ++i)
    if (std::hypot(vertices[i][0] - p[0], vertices[i][1] - p[1]) <= tolerance)
      return static_cast<int>(i);
  vertices.push_back(p);
  return static_cast<int>(vertices.size()) - 1;
}

struct RawSegment {
  int a, b;
  std::string owner;  // "the box" or "region <block>", for messages
};

}  // namespace

SectionGraph buildSectionGraph(const GeneratorSpec& spec) {
  SectionGraph graph;
  graph.lower_left = spec.lower_left;
  graph.upper_right = spec.upper_right;
  const Point2& lo = spec.lower_left;
  const Point2& hi = spec.upper_right;
  if (!(hi[0] > lo[0] && hi[1] > lo[1]))
    throw InputError(
        kWhere + "/Upper Right (m)",
        "the box needs upper right " + str(hi) + " above and right of " + "lower left " + str(lo));
  if (!(spec.element_size > 0))
    throw InputError(kWhere + "/Element Size (m)",
                     "the element size must be positive, got " + std::to_string(spec.element_size));
  const Real size = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  graph.tolerance = 1e-7 * size;
  const Real tol = graph.tolerance;

  graph.vertices = {{lo[0], lo[1]}, {hi[0], lo[1]}, {hi[0], hi[1]}, {lo[0], hi[1]}};
  std::vector<RawSegment> raw;
  for (int i = 0; i < 4; ++i) raw.push_back({i, (i + 1) % 4, "the box"});

  for (std::size_t r = 0; r < spec.regions.size(); ++r) {
    const PolygonRegion& region = spec.regions[r];
    const std::string where = kWhere + "/Regions/" + region.block + "/Vertices (m)";
    if (region.block.empty())
      throw InputError(kWhere + "/Regions",
                       "region " + std::to_string(r + 1) + " has no block name");
    std::vector<int> ids;
    for (Point2 p : region.vertices) {
      for (int d = 0; d < 2; ++d) {
        if (p[d] < lo[d] - tol || p[d] > hi[d] + tol)
          throw InputError(where,
                           "vertex " + str(p) + " is outside the box " + str(lo) + " - " + str(hi));
        p[d] = std::clamp(p[d], lo[d], hi[d]);
      }
      const int id = mergeVertex(graph.vertices, p, tol);
      if (ids.empty() || ids.back() != id) ids.push_back(id);
    }
    while (ids.size() > 1 && ids.front() == ids.back()) ids.pop_back();
    if (ids.size() < 3)
      throw InputError(
          where, "a region needs at least 3 distinct vertices, got " + std::to_string(ids.size()));
    std::vector<Point2> polygon;
    for (int id : ids) polygon.push_back(graph.vertices[id]);
    const Real area = signedArea(polygon);
    if (!(std::abs(area) > tol * size)) throw InputError(where, "the region has zero area");
    if (area < 0) {  // clockwise: accept, store counter-clockwise
      std::reverse(polygon.begin(), polygon.end());
      std::reverse(ids.begin(), ids.end());
    }
    for (std::size_t i = 0; i < ids.size(); ++i)
      raw.push_back({ids[i], ids[(i + 1) % ids.size()], "region " + region.block});
    graph.regions.push_back(std::move(polygon));
    graph.region_blocks.push_back(region.block);
  }

  // Split every edge at the vertices lying on it; store shared pieces once.
  std::map<std::pair<int, int>, std::string> pieces;
  for (const RawSegment& segment : raw) {
    const Point2& a = graph.vertices[segment.a];
    const Point2& b = graph.vertices[segment.b];
    const Real dx = b[0] - a[0], dy = b[1] - a[1];
    const Real length2 = dx * dx + dy * dy;
    std::vector<std::pair<Real, int>> on_segment{{0.0, segment.a}, {1.0, segment.b}};
    for (std::size_t v = 0; v < graph.vertices.size(); ++v) {
      if (static_cast<int>(v) == segment.a || static_cast<int>(v) == segment.b) continue;
      const Point2& p = graph.vertices[v];
      const Real t = ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length2;
      if (t > 0 && t < 1 && distanceToSegment(p, a, b) <= tol)
        on_segment.push_back({t, static_cast<int>(v)});
    }
    std::sort(on_segment.begin(), on_segment.end());
    for (std::size_t i = 0; i + 1 < on_segment.size(); ++i) {
      const int p = on_segment[i].second, q = on_segment[i + 1].second;
      pieces.emplace(std::make_pair(std::min(p, q), std::max(p, q)), segment.owner);
    }
  }

  std::vector<std::string> owners;
  for (const auto& [key, owner] : pieces) {
    graph.segments.push_back({key.first, key.second});
    owners.push_back(owner);
  }
  for (std::size_t i = 0; i < graph.segments.size(); ++i)
    for (std::size_t j = i + 1; j < graph.segments.size(); ++j) {
      const auto& s = graph.segments[i];
      const auto& t = graph.segments[j];
      Point2 where;
      if (segmentsCross(graph.vertices[s[0]], graph.vertices[s[1]], graph.vertices[t[0]],
                        graph.vertices[t[1]], 1e-9, &where)) {
        const std::string what = owners[i] == owners[j]
                                     ? owners[i] + " intersects itself"
                                     : owners[i] + " and " + owners[j] + " overlap";
        throw InputError(kWhere + "/Regions",
                         what + ": edges cross at " + str(where) + " (regions must not overlap)");
      }
    }
  return graph;
}

}  // namespace argine

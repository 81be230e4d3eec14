#include "argine/meshio/Delaunay.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace argine {

namespace {
__extension__ typedef __int128 Int128;

constexpr int64_t kGridCells = int64_t(1) << 26;  // snap cells across the box
constexpr int64_t kSuperSize = int64_t(1) << 27;  // super-triangle legs: 6 * 2^27 < 2^30
}  // namespace

DelaunayTriangulation::DelaunayTriangulation(const Point2& lower_left, const Point2& upper_right)
    : origin_(lower_left) {
  const Real size = std::max(upper_right[0] - lower_left[0], upper_right[1] - lower_left[1]);
  if (!(size > 0)) throw std::invalid_argument("DelaunayTriangulation: empty box");
  scale_ = static_cast<Real>(kGridCells) / size;
  // Integer coordinates stay below 2^30 in magnitude, so orientation fits in 64 bits and
  // the in-circle determinant (three terms of at most 2^61 * 2^61) in 128 bits.
  const int64_t m = kSuperSize;
  snapped_ = {{-m, -m}, {5 * m, -m}, {-m, 5 * m}};
  vertex_triangle_ = {0, 0, 0};
  triangles_.push_back({{-3, -2, -1}, {-1, -1, -1}, true});
  in_cavity_.push_back(0);
}

int64_t DelaunayTriangulation::orient(int a, int b, const Snapped& p) const {
  const Snapped& pa = snapped(a);
  const Snapped& pb = snapped(b);
  return (pb[0] - pa[0]) * (p[1] - pa[1]) - (pb[1] - pa[1]) * (p[0] - pa[0]);
}

bool DelaunayTriangulation::inCircle(const Triangle& t, const Snapped& p) const {
  const Snapped& a = snapped(t.vertex[0]);
  const Snapped& b = snapped(t.vertex[1]);
  const Snapped& c = snapped(t.vertex[2]);
  const Int128 adx = a[0] - p[0], ady = a[1] - p[1];
  const Int128 bdx = b[0] - p[0], bdy = b[1] - p[1];
  const Int128 cdx = c[0] - p[0], cdy = c[1] - p[1];
  const Int128 det = (adx * adx + ady * ady) * (bdx * cdy - bdy * cdx) +
                     (bdx * bdx + bdy * bdy) * (cdx * ady - cdy * adx) +
                     (cdx * cdx + cdy * cdy) * (adx * bdy - ady * bdx);
  return det > 0;  // strictly inside the circumcircle of the counter-clockwise triangle
}

int DelaunayTriangulation::locate(const Snapped& p, int start) const {
  // Visibility walk; a random first edge avoids cycling in degenerate configurations.
  int t = start;
  const std::size_t max_steps = 4 * triangles_.size() + 16;
  for (std::size_t step = 0; step < max_steps; ++step) {
    const Triangle& tri = triangles_[t];
    random_ ^= random_ << 13;
    random_ ^= random_ >> 7;
    random_ ^= random_ << 17;
    const int first = static_cast<int>(random_ % 3);
    int next = -1;
    for (int k = 0; k < 3 && next < 0; ++k) {
      const int i = (first + k) % 3;
      if (orient(tri.vertex[(i + 1) % 3], tri.vertex[(i + 2) % 3], p) < 0) next = tri.neighbour[i];
    }
    if (next < 0) return t;
    t = next;
  }
  // Fallback (never expected): scan every live triangle.
  for (std::size_t s = 0; s < triangles_.size(); ++s) {
    const Triangle& tri = triangles_[s];
    if (!tri.alive) continue;
    bool inside = true;
    for (int i = 0; i < 3 && inside; ++i)
      inside = orient(tri.vertex[(i + 1) % 3], tri.vertex[(i + 2) % 3], p) >= 0;
    if (inside) return static_cast<int>(s);
  }
  throw std::logic_error("DelaunayTriangulation: point outside the super-triangle");
}

int DelaunayTriangulation::newTriangle(const Triangle& t) {
  if (!free_.empty()) {
    const int slot = free_.back();
    free_.pop_back();
    triangles_[slot] = t;
    return slot;
  }
  triangles_.push_back(t);
  in_cavity_.push_back(0);
  return static_cast<int>(triangles_.size()) - 1;
}

int DelaunayTriangulation::insert(const Point2& p, int hint) {
  const Snapped s{std::llround((p[0] - origin_[0]) * scale_),
                  std::llround((p[1] - origin_[1]) * scale_)};
  const int start =
      (hint >= 0 && hint < static_cast<int>(triangles_.size()) && triangles_[hint].alive) ? hint
                                                                                          : last_;
  const int t = locate(s, start);
  for (int v : triangles_[t].vertex)
    if (v >= 0 && snapped(v) == s) return v;

  const int v = static_cast<int>(points_.size());
  points_.push_back(p);
  snapped_.push_back(s);
  vertex_triangle_.push_back(-1);

  // Cavity: the connected set of triangles whose circumcircle strictly contains p.
  cavity_.assign(1, t);
  in_cavity_[t] = 1;
  for (std::size_t i = 0; i < cavity_.size(); ++i)
    for (int n : triangles_[cavity_[i]].neighbour)
      if (n >= 0 && !in_cavity_[n] && inCircle(triangles_[n], s)) {
        in_cavity_[n] = 1;
        cavity_.push_back(n);
      }

  // Boundary edges (a, b) of the cavity, counter-clockwise seen from p.
  struct Edge {
    int a, b, outside;
  };
  std::vector<Edge> edges;
  for (int c : cavity_) {
    const Triangle& tri = triangles_[c];
    for (int i = 0; i < 3; ++i) {
      const int n = tri.neighbour[i];
      if (n >= 0 && in_cavity_[n]) continue;
      const int a = tri.vertex[(i + 1) % 3], b = tri.vertex[(i + 2) % 3];
      if (orient(a, b, s) <= 0)
        throw std::logic_error("DelaunayTriangulation: cavity not star-shaped");
      edges.push_back({a, b, n});
    }
  }
  for (int c : cavity_) {
    in_cavity_[c] = 0;
    triangles_[c].alive = false;
    free_.push_back(c);
  }

  // Fan of new triangles (a, b, p); link them to the outside and to each other.
  created_.clear();
  for (const Edge& e : edges) {
    const int slot = newTriangle({{e.a, e.b, v}, {-1, -1, e.outside}, true});
    created_.push_back(slot);
    if (e.outside >= 0) {  // the outside triangle's edge (b, a) is opposite its third vertex
      Triangle& outside = triangles_[e.outside];
      for (int j = 0; j < 3; ++j)
        if (outside.vertex[j] != e.a && outside.vertex[j] != e.b) outside.neighbour[j] = slot;
    }
    vertex_triangle_[e.a + kSuper] = slot;
  }
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = 0; j < edges.size(); ++j) {
      if (edges[j].a == edges[i].b) triangles_[created_[i]].neighbour[0] = created_[j];
      if (edges[j].b == edges[i].a) triangles_[created_[i]].neighbour[1] = created_[j];
    }
  vertex_triangle_[v + kSuper] = created_.front();
  last_ = created_.front();
  return v;
}

bool DelaunayTriangulation::hasEdge(int a, int b) const {
  const int start = vertex_triangle_[a + kSuper];
  int t = start;
  do {
    const Triangle& tri = triangles_[t];
    const int i = tri.vertex[0] == a ? 0 : tri.vertex[1] == a ? 1 : 2;
    if (tri.vertex[(i + 1) % 3] == b || tri.vertex[(i + 2) % 3] == b) return true;
    t = tri.neighbour[(i + 2) % 3];  // across edge (a, vertex i+1): next triangle around a
  } while (t >= 0 && t != start);
  return false;
}

std::vector<std::array<int, 3>> DelaunayTriangulation::innerTriangles() const {
  std::vector<std::array<int, 3>> result;
  for (const Triangle& tri : triangles_)
    if (tri.alive && tri.vertex[0] >= 0 && tri.vertex[1] >= 0 && tri.vertex[2] >= 0)
      result.push_back(tri.vertex);
  return result;
}

}  // namespace argine

/// @file SectionTriangulator.cpp
/// Lattice + Delaunay triangulation conforming to a section graph (see the header for why).
#include "argine/meshio/SectionTriangulator.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

#include "argine/meshio/Delaunay.hpp"

namespace argine {

namespace {

/// Spatial hash of edge pieces: each piece is listed in every cell within `reach` of it.
class PieceIndex {
 public:
  PieceIndex(const Point2& origin, Real cell) : origin_(origin), cell_(cell) {}

  void add(int id, const Point2& a, const Point2& b, Real reach) {
    const int64_t i0 = cellOf(std::min(a[0], b[0]) - reach, 0);
    const int64_t i1 = cellOf(std::max(a[0], b[0]) + reach, 0);
    const int64_t j0 = cellOf(std::min(a[1], b[1]) - reach, 1);
    const int64_t j1 = cellOf(std::max(a[1], b[1]) + reach, 1);
    for (int64_t i = i0; i <= i1; ++i)
      for (int64_t j = j0; j <= j1; ++j) cells_[key(i, j)].push_back(id);
  }

  /// Pieces that may be within their reach of p (a superset).
  const std::vector<int>& near(const Point2& p) const {
    static const std::vector<int> none;
    const auto it = cells_.find(key(cellOf(p[0], 0), cellOf(p[1], 1)));
    return it == cells_.end() ? none : it->second;
  }

 private:
  int64_t cellOf(Real x, int d) const {
    return static_cast<int64_t>(std::floor((x - origin_[d]) / cell_));
  }
  // Cell indices stay far below 2^30 in magnitude (element count limit), so keys are unique.
  static int64_t key(int64_t i, int64_t j) {
    const int64_t offset = int64_t(1) << 30;
    return (i + offset) * (int64_t(1) << 31) + (j + offset);
  }

  Point2 origin_;
  Real cell_;
  std::unordered_map<int64_t, std::vector<int>> cells_;
};

Real distance(const Point2& a, const Point2& b) {
  return std::hypot(b[0] - a[0], b[1] - a[1]);
}

Point2 circumcentre(const Point2& a, const Point2& b, const Point2& c) {
  const Real bx = b[0] - a[0], by = b[1] - a[1];
  const Real cx = c[0] - a[0], cy = c[1] - a[1];
  const Real d = 2 * (bx * cy - by * cx);
  const Real b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  return {a[0] + (cy * b2 - by * c2) / d, a[1] + (bx * c2 - cx * b2) / d};
}

class Triangulator {
 public:
  Triangulator(const SectionGraph& graph, Real h, const TriangulatorOptions& options)
      : graph_(graph),
        h_(h),
        options_(options),
        dt_(graph.lower_left, graph.upper_right),
        index_(graph.lower_left, h) {
    findSmallAngles();
  }

  SectionTriangulation run() {
    insertGraph();
    insertLattice();
    recoverAllPieces();
    for (int round = 0; round < 4; ++round) {
      const bool refined = refine();
      recoverAllPieces();
      if (!refined) break;
    }
    SectionTriangulation result;
    for (int v = 0; v < dt_.numVertices(); ++v) result.points.push_back(dt_.point(v));
    result.triangles = dt_.innerTriangles();
    result.on_edge = on_edge_;
    smooth(result);
    return result;
  }

 private:
  struct Piece {
    int a, b;
    bool alive;
  };

  int insert(const Point2& p, int hint) {
    const int v = dt_.insert(p, hint);
    if (v == static_cast<int>(on_edge_.size())) on_edge_.push_back(0);
    return v;
  }

  void addPiece(int a, int b) {
    const int id = static_cast<int>(pieces_.size());
    pieces_.push_back({a, b, true});
    const Point2& pa = dt_.point(a);
    const Point2& pb = dt_.point(b);
    index_.add(id, pa, pb, std::max(options_.lattice_clearance * h_, 0.5 * distance(pa, pb)));
  }

  /// Splits a piece at its midpoint (a point of the graph edge, so it stays on the edge).
  void splitPiece(int id) {
    const Piece piece = pieces_[id];
    const Point2& pa = dt_.point(piece.a);
    const Point2& pb = dt_.point(piece.b);
    const int before = dt_.numVertices();
    const int m = insert({0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1])}, dt_.triangleAt(piece.a));
    if (m < before)
      throw std::logic_error("section triangulator: an edge piece became too short to split");
    on_edge_[m] = 1;
    pieces_[id].alive = false;
    addPiece(piece.a, m);
    addPiece(m, piece.b);
  }

  /// Graph vertices where two edges meet at less than 60 degrees. Refining next to them
  /// cascades (each split encroaches the other edge), so triangles there are refined only
  /// down to a fraction of h; elsewhere refinement follows the local feature size.
  void findSmallAngles() {
    std::vector<std::vector<Real>> directions(graph_.vertices.size());
    for (const auto& segment : graph_.segments)
      for (int end = 0; end < 2; ++end) {
        const Point2& from = graph_.vertices[segment[end]];
        const Point2& to = graph_.vertices[segment[1 - end]];
        directions[segment[end]].push_back(std::atan2(to[1] - from[1], to[0] - from[0]));
      }
    for (std::size_t v = 0; v < directions.size(); ++v) {
      auto& d = directions[v];
      if (d.size() < 2) continue;
      std::sort(d.begin(), d.end());
      Real smallest = d.front() + 2 * M_PI - d.back();
      for (std::size_t k = 0; k + 1 < d.size(); ++k) smallest = std::min(smallest, d[k + 1] - d[k]);
      if (smallest < M_PI / 3) small_angles_.push_back(graph_.vertices[v]);
    }
  }

  /// Smallest circumradius worth refining for a triangle with circumcircle (centre, radius):
  /// 0.3 h when the circle is within a few radii of a small input angle (the cascade zone),
  /// else 0.05 h, so that features drawn smaller than h get well-shaped elements but no
  /// element becomes so small that it dictates the explicit time step.
  Real refinementFloor(const Point2& centre, Real radius) const {
    for (const Point2& apex : small_angles_)
      if (distance(centre, apex) < 6 * radius) return 0.3 * h_;
    return 0.05 * h_;
  }

  /// Graph vertices and points spaced <= h along every graph edge.
  void insertGraph() {
    std::vector<int> ids;
    for (const Point2& p : graph_.vertices) {
      ids.push_back(insert(p, -1));
      on_edge_[ids.back()] = 1;
    }
    for (const auto& segment : graph_.segments) {
      const Point2& a = graph_.vertices[segment[0]];
      const Point2& b = graph_.vertices[segment[1]];
      const int n = std::max(1, static_cast<int>(std::ceil(distance(a, b) / h_ - 1e-9)));
      int previous = ids[segment[0]];
      for (int k = 1; k <= n; ++k) {
        int v = ids[segment[1]];
        if (k < n) {
          const Real t = static_cast<Real>(k) / n;
          v = insert({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])}, -1);
          on_edge_[v] = 1;
        }
        addPiece(previous, v);
        previous = v;
      }
    }
  }

  /// Equilateral lattice of spacing h, rows snaking left-right so each point is inserted
  /// next to the previous one; points near an edge piece are left out.
  void insertLattice() {
    const Point2& lo = graph_.lower_left;
    const Point2& hi = graph_.upper_right;
    const Real row_height = h_ * std::sqrt(3.0) / 2;
    const int rows = static_cast<int>(std::floor((hi[1] - lo[1]) / row_height));
    const int columns = static_cast<int>(std::floor((hi[0] - lo[0]) / h_)) + 1;
    const Real x_start = lo[0] + 0.5 * ((hi[0] - lo[0]) - (columns - 1) * h_);
    const Real clearance = options_.lattice_clearance * h_;
    for (int j = 1; j <= rows; ++j) {
      const Real y = lo[1] + j * row_height;
      for (int k = 0; k <= columns; ++k) {
        const int i = (j % 2 == 0) ? k : columns - k;
        const Real x = x_start + (i - 0.5 * (j % 2)) * h_;
        const Point2 p{x, y};
        if (x <= lo[0] || x >= hi[0] || y >= hi[1]) continue;
        bool clear = true;
        for (int id : index_.near(p)) {
          const Piece& piece = pieces_[id];
          if (distanceToSegment(p, dt_.point(piece.a), dt_.point(piece.b)) < clearance) {
            clear = false;
            break;
          }
        }
        if (clear) insert(p, -1);
      }
    }
  }

  /// Splits edge pieces that are not Delaunay edges until all are.
  void recoverAllPieces() {
    for (int pass = 0;; ++pass) {
      if (pass > 64) throw std::logic_error("section triangulator: edges could not be recovered");
      bool all_present = true;
      for (std::size_t id = 0; id < pieces_.size(); ++id)
        if (pieces_[id].alive && !dt_.hasEdge(pieces_[id].a, pieces_[id].b)) {
          splitPiece(static_cast<int>(id));
          all_present = false;
        }
      if (all_present) return;
    }
  }

  /// Live pieces whose diametral circle contains p.
  std::vector<int> encroachedBy(const Point2& p) const {
    std::vector<int> result;
    for (int id : index_.near(p)) {
      const Piece& piece = pieces_[id];
      if (!piece.alive) continue;
      const Point2& a = dt_.point(piece.a);
      const Point2& b = dt_.point(piece.b);
      const Point2 mid{0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])};
      if (distance(p, mid) < 0.5 * distance(a, b)) result.push_back(id);
    }
    return result;
  }

  bool isBad(const DelaunayTriangulation::Triangle& t) const {
    for (int v : t.vertex)
      if (v < 0) return false;
    return minimumAngleDegrees(dt_.point(t.vertex[0]), dt_.point(t.vertex[1]),
                               dt_.point(t.vertex[2])) < options_.refine_below_degrees;
  }

  /// Ruppert steps on triangles with a small angle; returns true when points were added.
  bool refine() {
    struct Entry {
      int slot;
      std::array<int, 3> vertex;
    };
    std::vector<Entry> queue;
    auto consider = [&](int slot) {
      const auto& t = dt_.triangles()[slot];
      if (t.alive && isBad(t)) queue.push_back({slot, t.vertex});
    };
    for (std::size_t s = 0; s < dt_.triangles().size(); ++s) consider(static_cast<int>(s));
    auto considerCreated = [&] {
      const std::vector<int> created = dt_.lastCreated();
      for (int s : created) consider(s);
    };
    const Point2& lo = graph_.lower_left;
    const Point2& hi = graph_.upper_right;
    const int budget = dt_.numVertices() / 2 + 100;
    int added = 0;
    while (!queue.empty() && added < budget) {
      const Entry entry = queue.back();
      queue.pop_back();
      const auto& t = dt_.triangles()[entry.slot];
      if (!t.alive || t.vertex != entry.vertex) continue;
      const Point2& a = dt_.point(t.vertex[0]);
      const Point2& b = dt_.point(t.vertex[1]);
      const Point2& c = dt_.point(t.vertex[2]);
      const Point2 centre = circumcentre(a, b, c);
      const Real radius = distance(centre, a);
      const Real floor = refinementFloor(centre, radius);
      if (!(radius > floor)) continue;
      const std::vector<int> encroached = encroachedBy(centre);
      if (!encroached.empty()) {
        bool split = false;
        for (int id : encroached)
          if (distance(dt_.point(pieces_[id].a), dt_.point(pieces_[id].b)) > floor) {
            splitPiece(id);
            considerCreated();
            split = true;
            ++added;
          }
        if (split) queue.push_back(entry);  // try again if it survived
        continue;
      }
      if (centre[0] <= lo[0] || centre[0] >= hi[0] || centre[1] <= lo[1] || centre[1] >= hi[1])
        continue;
      const int before = dt_.numVertices();
      if (insert(centre, entry.slot) < before) continue;
      considerCreated();
      ++added;
    }
    return added > 0;
  }

  /// Smart Laplacian smoothing: a free node moves to the mean of its neighbours when that
  /// raises the smallest angle of the triangles around it (so nothing inverts).
  void smooth(SectionTriangulation& mesh) const {
    const std::size_t n = mesh.points.size();
    std::vector<std::vector<int>> around(n);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      for (int v : mesh.triangles[t]) around[v].push_back(static_cast<int>(t));
    auto worstAngle = [&](int v) {
      Real worst = 180;
      for (int t : around[v]) {
        const auto& tri = mesh.triangles[t];
        const Point2& a = mesh.points[tri[0]];
        const Point2& b = mesh.points[tri[1]];
        const Point2& c = mesh.points[tri[2]];
        worst = orientation(a, b, c) > 0 ? std::min(worst, minimumAngleDegrees(a, b, c)) : -1;
        if (worst < 0) break;
      }
      return worst;
    };
    for (int sweep = 0; sweep < options_.smoothing_sweeps; ++sweep)
      for (std::size_t v = 0; v < n; ++v) {
        if (mesh.on_edge[v] || around[v].empty()) continue;
        Point2 mean{0, 0};
        int count = 0;
        for (int t : around[v])
          for (int w : mesh.triangles[t])
            if (w != static_cast<int>(v)) {
              mean[0] += mesh.points[w][0];
              mean[1] += mesh.points[w][1];
              ++count;
            }
        mean = {mean[0] / count, mean[1] / count};
        const Point2 old = mesh.points[v];
        const Real before = worstAngle(static_cast<int>(v));
        mesh.points[v] = mean;
        if (!(worstAngle(static_cast<int>(v)) > before)) mesh.points[v] = old;
      }
  }

  const SectionGraph& graph_;
  Real h_;
  TriangulatorOptions options_;
  DelaunayTriangulation dt_;
  PieceIndex index_;
  std::vector<Piece> pieces_;
  std::vector<char> on_edge_;
  std::vector<Point2> small_angles_;
};

}  // namespace

SectionTriangulation triangulateSection(const SectionGraph& graph, Real element_size,
                                        const TriangulatorOptions& options) {
  return Triangulator(graph, element_size, options).run();
}

}  // namespace argine

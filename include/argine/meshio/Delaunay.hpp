#pragma once
/// @file Delaunay.hpp
/// Incremental Delaunay triangulation (Bowyer–Watson) of points inside a box, the core of
/// the polygon-section generator.
///
/// Robustness: the predicates (orientation, in-circle) are evaluated EXACTLY on integer
/// coordinates: each point is snapped to a grid of 2^26 cells across the box and the
/// predicates use 64/128-bit integers, so collinear boundary points and cocircular lattice
/// points (normal in generated meshes) never corrupt the triangulation. The original
/// double coordinates are kept for everything else (they are what the mesh gets); the
/// snap moves a point by at most 1.5e-8 box sizes, far below any element size we make.

#include <array>
#include <cstdint>
#include <vector>

#include "argine/meshio/Geometry2D.hpp"

namespace argine {

class DelaunayTriangulation {
 public:
  /// One triangle: vertices counter-clockwise; neighbour[i] is across the edge opposite
  /// vertex[i] (-1 on the outer boundary of the super-triangle).
  struct Triangle {
    std::array<int, 3> vertex;     ///< vertex indices (super-triangle vertices are < 0)
    std::array<int, 3> neighbour;  ///< neighbouring triangle across the edge opposite vertex i
    bool alive = true;             ///< false once removed (its slot is reused)
  };

  /// Starts with a super-triangle enclosing the box [lower_left, upper_right].
  DelaunayTriangulation(const Point2& lower_left, const Point2& upper_right);

  /// Inserts p (inside the box) and returns its vertex index, or the index of an existing
  /// vertex that snaps to the same grid point. `hint` is a triangle near p (-1: the last
  /// one created), which makes spatially ordered insertion O(1) per point.
  int insert(const Point2& p, int hint = -1);

  /// True when the segment between vertices a and b is an edge of the triangulation.
  bool hasEdge(int a, int b) const;

  /// Number of inserted vertices (indices 0 .. numVertices()-1).
  int numVertices() const { return static_cast<int>(points_.size()); }
  /// Original coordinates of vertex v.
  const Point2& point(int v) const { return points_[v]; }

  /// All triangle slots (check `alive`); vertex indices < 0 are super-triangle vertices.
  const std::vector<Triangle>& triangles() const { return triangles_; }
  /// Triangles created by the last insert (for quality checks of the new ones).
  const std::vector<int>& lastCreated() const { return created_; }
  /// A live triangle that has vertex v as a corner (a good walk start near v).
  int triangleAt(int v) const { return vertex_triangle_[v + kSuper]; }

  /// Live triangles whose three vertices are inserted points (not the super-triangle).
  std::vector<std::array<int, 3>> innerTriangles() const;

 private:
  using Snapped = std::array<int64_t, 2>;
  static constexpr int kSuper = 3;  // vertex v is stored at v + kSuper; super vertices 0..2

  const Snapped& snapped(int v) const { return snapped_[v + kSuper]; }
  int64_t orient(int a, int b, const Snapped& p) const;
  bool inCircle(const Triangle& t, const Snapped& p) const;
  int locate(const Snapped& p, int start) const;
  int newTriangle(const Triangle& t);

  Point2 origin_;
  Real scale_;
  std::vector<Point2> points_;
  std::vector<Snapped> snapped_;      // super vertices first
  std::vector<int> vertex_triangle_;  // a live triangle touching each vertex (+kSuper)
  std::vector<Triangle> triangles_;
  std::vector<int> free_;  // dead triangle slots
  std::vector<int> created_;
  std::vector<int> cavity_;      // scratch
  std::vector<char> in_cavity_;  // scratch, per triangle slot
  int last_ = 0;
  mutable uint64_t random_ = 0x9E3779B97F4A7C15ull;
};

}  // namespace argine

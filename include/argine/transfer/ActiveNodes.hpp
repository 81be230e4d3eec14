#pragma once
/// @file ActiveNodes.hpp
/// The nodes of the background elements that hold material points: the only nodes a step
/// computes on. Rebuilt once per step after the points are located; the cost is one pass
/// over the points plus a byte scan of the node flags (no per-node arithmetic).

#include "argine/core/Types.hpp"

namespace argine {

struct MaterialPoints;
struct Mesh;
struct PointShapes;

class ActiveNodes {
 public:
  /// Prepare for a mesh with `num_nodes` nodes; the list starts empty.
  explicit ActiveNodes(int num_nodes = 0);

  /// Lists every node of every element that holds a located point (element >= 0).
  void rebuild(const Mesh& mesh, const MaterialPoints& points);

  /// The same, plus the listed nodes (e.g. the nodes shared with other MPI ranks, which must
  /// be cleared and solved on every rank holding them).
  void rebuild(const Mesh& mesh, const MaterialPoints& points,
               Kokkos::View<const int*, MemSpace> also);
  /// The same with the points' shapes: on the grid families (GIMP, B-spline) the nodes of
  /// every located point's 3 x 3 stencil instead of its element's.
  void rebuild(const Mesh& mesh, const MaterialPoints& points, const PointShapes* shapes,
               Kokkos::View<const int*, MemSpace> also);
  /// The nodes of `from` whose `mask` entry is non-zero (e.g. the nodes this rank owns).
  void assignMasked(const ActiveNodes& from, Kokkos::View<const unsigned char*, MemSpace> mask);

  /// Node indices, ascending; entries [0, count()) are valid.
  Kokkos::View<const int*, MemSpace> nodes() const { return nodes_; }
  /// Number of active nodes.
  int count() const { return count_; }

 private:
  Kokkos::View<int*, MemSpace> flag_;   ///< 1 while a node is being marked, else 0
  Kokkos::View<int*, MemSpace> nodes_;  ///< compacted list (capacity = number of mesh nodes)
  int count_ = 0;
};

}  // namespace argine

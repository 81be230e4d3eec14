#pragma once
/// @file FreeBoundary.hpp
/// The current boundary of the soil on the fixed background mesh (thesis Sec. 4, Fig. 4.4):
///  - active elements: elements holding at least one located material point;
///  - free sides: sides of active elements whose neighbour is empty (no points) or absent
///    (the mesh edge); a free side's outward normal is its geometric normal (counter-
///    clockwise elements: the edge vector turned clockwise);
///  - boundary elements: active elements with a free side; boundary nodes: end nodes of free
///    sides; boundary material points: the points of boundary elements.
/// On a background mesh that does not follow the soil surface the free sides form a
/// staircase; a pressure integrated along them gives the same resultant as along the
/// surface (each side carries its projection).
///
/// Cost of detect(): one pass over the points (their element) and loops over the active
/// elements only; the per-element flags are cleared through the previous active list, so
/// empty background elements cost nothing. Call it when a point changed element (the free
/// boundary cannot change otherwise). Host loops: the lists are small (boundary-sized).

#include <vector>

#include "argine/core/Types.hpp"

namespace argine {

struct MaterialPoints;
struct Mesh;

/// One free side of an active element.
struct FreeSide {
  int element = -1;            ///< active element
  int side = -1;               ///< local side (joins local nodes side and side+1)
  int a = -1, b = -1;          ///< end nodes, counter-clockwise within the element
  Real length = 0;             ///< (m)
  Real normal[kDim] = {0, 0};  ///< outward unit normal
  Real xa[kDim] = {0, 0};      ///< coordinates of node a (m)
  Real xb[kDim] = {0, 0};      ///< coordinates of node b (m)
  bool mesh_edge = false;      ///< no neighbour (the mesh edge) rather than an empty one
  /// Midpoint coordinate d.
  Real midpoint(int d) const { return 0.5 * (xa[d] + xb[d]); }
};

class FreeBoundary {
 public:
  FreeBoundary() = default;
  /// Copies the mesh geometry and its edge adjacency to the host (once).
  explicit FreeBoundary(const Mesh& mesh);

  /// Finds the active elements, free sides and boundary nodes of the points' current
  /// elements (element >= 0).
  void detect(const MaterialPoints& points);

  /// The same from the list of active elements (ascending), e.g. the union over MPI ranks
  /// of the elements holding points (physics/DistributedStep.hpp).
  void detectFromActiveElements(const std::vector<int>& active_elements);

  bool isActive(int element) const { return active_[element] != 0; }
  const std::vector<int>& activeElements() const { return active_list_; }
  const std::vector<FreeSide>& sides() const { return sides_; }
  /// Boundary nodes, ascending.
  const std::vector<int>& nodes() const { return nodes_; }
  /// Active elements with at least one free side, ascending.
  const std::vector<int>& boundaryElements() const { return boundary_elements_; }
  /// Indices of the boundary material points (in boundary elements), for the points as
  /// they are now (indices change when the points are sorted).
  std::vector<int> boundaryPoints(const MaterialPoints& points) const;
  /// The free side of `element` with local index `side` as a FreeSide (geometry only).
  FreeSide sideOf(int element, int side) const;
  /// Sides (= nodes) per element of the mesh.
  int sidesPerElement() const { return per_; }
  /// The element across local side `side` of `element`, -1 at the mesh edge.
  int neighbour(int element, int side) const { return neighbours_[element * per_ + side]; }
  /// How many times detect() ran (for tests of when it runs).
  long detections() const { return detections_; }

 private:
  void findFreeSides();  ///< sides_, boundary_elements_, nodes_ from active_ / active_list_

  int per_ = 0;
  std::vector<Real> x_;                   ///< node coordinates, x0 y0 x1 y1 ...
  std::vector<int> connectivity_;         ///< per_ entries per element
  std::vector<int> neighbours_;           ///< per_ entries per element, -1 on the mesh edge
  std::vector<unsigned char> active_;     ///< per element
  std::vector<unsigned char> node_flag_;  ///< per node, scratch (cleared after use)
  std::vector<int> active_list_, boundary_elements_, nodes_;
  std::vector<FreeSide> sides_;
  long detections_ = 0;
};

}  // namespace argine

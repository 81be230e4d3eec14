#include "argine/boundary/FreeBoundary.hpp"

#include <algorithm>
#include <cmath>

#include "argine/mesh/Mesh.hpp"
#include "argine/mesh/MeshGeometry.hpp"
#include "argine/points/MaterialPoints.hpp"

namespace argine {

FreeBoundary::FreeBoundary(const Mesh& mesh) : per_(mesh.nodesPerElement()) {
  const auto X = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  const auto C = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.connectivity);
  const auto N =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), computeElementNeighbours(mesh));
  const int nodes = mesh.numNodes(), elements = mesh.numElements();
  x_.resize(2 * static_cast<std::size_t>(nodes));
  for (int i = 0; i < nodes; ++i) x_[2 * i] = X(i, 0), x_[2 * i + 1] = X(i, 1);
  connectivity_.resize(static_cast<std::size_t>(elements) * per_);
  neighbours_.resize(connectivity_.size());
  for (int e = 0; e < elements; ++e)
    for (int s = 0; s < per_; ++s) {
      connectivity_[e * per_ + s] = C(e, s);
      neighbours_[e * per_ + s] = N(e, s);
    }
  active_.assign(elements, 0);
  node_flag_.assign(nodes, 0);
}

FreeSide FreeBoundary::sideOf(int element, int side) const {
  FreeSide f;
  f.element = element;
  f.side = side;
  f.a = connectivity_[element * per_ + side];
  f.b = connectivity_[element * per_ + (side + 1) % per_];
  for (int d = 0; d < kDim; ++d) f.xa[d] = x_[2 * f.a + d], f.xb[d] = x_[2 * f.b + d];
  const Real tx = f.xb[0] - f.xa[0], ty = f.xb[1] - f.xa[1];
  f.length = std::hypot(tx, ty);
  // counter-clockwise element: the outward normal is the edge vector turned clockwise
  f.normal[0] = ty / f.length;
  f.normal[1] = -tx / f.length;
  f.mesh_edge = neighbours_[element * per_ + side] < 0;
  return f;
}

void FreeBoundary::detect(const MaterialPoints& points) {
  ++detections_;
  for (const int e : active_list_) active_[e] = 0;  // clear through the old list
  active_list_.clear();
  const auto element = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.element);
  for (int p = 0; p < points.count; ++p) {
    const int e = element(p);
    if (e < 0 || active_[e]) continue;
    active_[e] = 1;
    active_list_.push_back(e);
  }
  std::sort(active_list_.begin(), active_list_.end());
  findFreeSides();
}

void FreeBoundary::detectFromActiveElements(const std::vector<int>& active_elements) {
  ++detections_;
  for (const int e : active_list_) active_[e] = 0;  // clear through the old list
  active_list_ = active_elements;
  for (const int e : active_list_) active_[e] = 1;
  findFreeSides();
}

void FreeBoundary::findFreeSides() {
  sides_.clear();
  boundary_elements_.clear();
  nodes_.clear();
  for (const int e : active_list_) {
    bool boundary = false;
    for (int s = 0; s < per_; ++s) {
      const int neighbour = neighbours_[e * per_ + s];
      if (neighbour >= 0 && active_[neighbour]) continue;
      boundary = true;
      sides_.push_back(sideOf(e, s));
      for (const int node : {sides_.back().a, sides_.back().b})
        if (!node_flag_[node]) {
          node_flag_[node] = 1;
          nodes_.push_back(node);
        }
    }
    if (boundary) boundary_elements_.push_back(e);
  }
  for (const int node : nodes_) node_flag_[node] = 0;
  std::sort(nodes_.begin(), nodes_.end());
}

std::vector<int> FreeBoundary::boundaryPoints(const MaterialPoints& points) const {
  const auto element = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.element);
  std::vector<int> list;
  for (int p = 0; p < points.count; ++p) {
    const int e = element(p);
    if (e >= 0 && std::binary_search(boundary_elements_.begin(), boundary_elements_.end(), e))
      list.push_back(p);
  }
  return list;
}

}  // namespace argine

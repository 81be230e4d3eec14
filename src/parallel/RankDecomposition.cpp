#include "argine/parallel/RankDecomposition.hpp"

#include <algorithm>
#include <numeric>

#include "argine/mesh/ElementFootprint.hpp"
#include "argine/mesh/Mesh.hpp"
#include "argine/points/MaterialPoints.hpp"

namespace argine {

namespace {

// Splits `elements` (indices) into `parts` parts numbered from `first_part`.
void bisect(const std::vector<Real>& x, const std::vector<Real>& y, const std::vector<Real>& w,
            std::vector<int> elements, int parts, int first_part, std::vector<int>& part) {
  if (parts <= 1 || elements.size() <= 1) {
    for (const int e : elements) part[e] = first_part;
    return;
  }
  Real low[2] = {x[elements[0]], y[elements[0]]}, high[2] = {low[0], low[1]};
  for (const int e : elements) {
    low[0] = std::min(low[0], x[e]), high[0] = std::max(high[0], x[e]);
    low[1] = std::min(low[1], y[e]), high[1] = std::max(high[1], y[e]);
  }
  const std::vector<Real>& c = high[0] - low[0] >= high[1] - low[1] ? x : y;
  std::sort(elements.begin(), elements.end(),
            [&](int a, int b) { return c[a] < c[b] || (c[a] == c[b] && a < b); });
  const int left_parts = parts / 2;
  Real total = 0;
  for (const int e : elements) total += w[e];
  const Real target = total * left_parts / parts;
  std::size_t cut = 0;
  Real sum = 0;
  while (cut < elements.size() - 1 && sum + 0.5 * w[elements[cut]] < target)
    sum += w[elements[cut++]];
  cut = std::max<std::size_t>(cut, 1);
  bisect(x, y, w, std::vector<int>(elements.begin(), elements.begin() + cut), left_parts,
         first_part, part);
  bisect(x, y, w, std::vector<int>(elements.begin() + cut, elements.end()), parts - left_parts,
         first_part + left_parts, part);
}

}  // namespace

std::vector<int> bisectElements(const std::vector<Real>& centroid_x,
                                const std::vector<Real>& centroid_y,
                                const std::vector<Real>& weights, int parts) {
  std::vector<int> part(centroid_x.size(), 0);
  std::vector<int> all(centroid_x.size());
  std::iota(all.begin(), all.end(), 0);
  bisect(centroid_x, centroid_y, weights, all, std::max(parts, 1), 0, part);
  return part;
}

std::vector<Real> pointsPerElementWeights(const Mesh& mesh, const MaterialPoints& points) {
  std::vector<Real> weights(mesh.numElements(), 1e-3);
  const auto element = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.element);
  for (int p = 0; p < points.count; ++p)
    if (element(p) >= 0) weights[element(p)] += 1;
  return weights;
}

RankDecomposition::RankDecomposition(MPI_Comm comm, const Mesh& mesh,
                                     const std::vector<Real>& element_weights)
    : comm_(comm) {
  MPI_Comm_rank(comm, &rank_);
  MPI_Comm_size(comm, &size_);
  const int elements = mesh.numElements(), nodes = mesh.numNodes(), per = mesh.nodesPerElement();
  const auto X = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  const auto C = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.connectivity);
  std::vector<Real> cx(elements, 0), cy(elements, 0);
  for (int e = 0; e < elements; ++e) {
    for (int a = 0; a < per; ++a) cx[e] += X(C(e, a), 0) / per, cy[e] += X(C(e, a), 1) / per;
  }
  element_owner_ = bisectElements(cx, cy, element_weights, size_);
  owned_elements_ =
      static_cast<int>(std::count(element_owner_.begin(), element_owner_.end(), rank_));

  // The ranks whose elements' points can reach each node (the elements whose footprint
  // holds it: their nodes on linear shapes, the 4 x 4 block on the grid families), as a
  // sorted small list.
  const ElementFootprint footprint(mesh);
  std::vector<std::vector<int>> node_ranks(nodes);
  int reach[ElementFootprint::kMaxNodes];
  for (int e = 0; e < elements; ++e) {
    const int count = footprint.nodes(e, reach);
    for (int a = 0; a < count; ++a) {
      auto& ranks = node_ranks[reach[a]];
      const int r = element_owner_[e];
      if (std::find(ranks.begin(), ranks.end(), r) == ranks.end()) ranks.push_back(r);
    }
  }
  std::vector<int> slot_of(nodes, -1);
  node_owned_i_ = Kokkos::View<unsigned char*, MemSpace>("node_owned_i", nodes);
  const auto owned = Kokkos::create_mirror_view(node_owned_i_);
  for (int i = 0; i < nodes; ++i) {
    auto& ranks = node_ranks[i];
    std::sort(ranks.begin(), ranks.end());
    owned(i) = (ranks.empty() ? 0 : ranks[0]) == rank_ ? 1 : 0;
    if (ranks.size() < 2 || !std::binary_search(ranks.begin(), ranks.end(), rank_)) continue;
    slot_of[i] = static_cast<int>(shared_nodes_.size());
    shared_nodes_.push_back(i);
  }
  Kokkos::deep_copy(node_owned_i_, owned);
  for (int r = 0; r < size_; ++r) {
    if (r == rank_) continue;
    RankNeighbour neighbour;
    neighbour.rank = r;
    for (const int i : shared_nodes_)
      if (std::binary_search(node_ranks[i].begin(), node_ranks[i].end(), r)) {
        neighbour.nodes.push_back(i);
        neighbour.slots.push_back(slot_of[i]);
      }
    if (!neighbour.nodes.empty()) neighbours_.push_back(std::move(neighbour));
  }
  element_owner_e_ = Kokkos::View<int*, MemSpace>("element_owner_e", elements);
  Kokkos::deep_copy(element_owner_e_,
                    Kokkos::View<const int*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(
                        element_owner_.data(), elements));
  shared_nodes_i_ = Kokkos::View<int*, MemSpace>("shared_nodes_i", shared_nodes_.size());
  Kokkos::deep_copy(shared_nodes_i_,
                    Kokkos::View<const int*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(
                        shared_nodes_.data(), shared_nodes_.size()));
}

}  // namespace argine

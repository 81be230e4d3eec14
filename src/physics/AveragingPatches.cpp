#include "argine/physics/AveragingPatches.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include "argine/mesh/Mesh.hpp"

namespace argine {

AveragingPatches buildAveragingPatches(const Mesh& mesh, Real length) {
  if (!(length > 0)) throw std::invalid_argument("buildAveragingPatches: length must be > 0");
  const auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  const auto nodes_e = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.connectivity);
  Real lower[kDim] = {std::numeric_limits<Real>::max(), std::numeric_limits<Real>::max()};
  for (int i = 0; i < mesh.numNodes(); ++i)
    for (int d = 0; d < kDim; ++d) lower[d] = std::min(lower[d], x(i, d));
  const int elements = mesh.numElements(), corners = mesh.nodesPerElement();
  // (row, column) of each element's patch; the rows and columns in use numbered in order
  std::vector<std::pair<long, long>> cell(elements);
  std::map<std::pair<long, long>, int> number;
  for (int e = 0; e < elements; ++e) {
    Real centre[kDim] = {0, 0};
    for (int a = 0; a < corners; ++a)
      for (int d = 0; d < kDim; ++d) centre[d] += x(nodes_e(e, a), d) / corners;
    const auto index = [&](int d) {
      return static_cast<long>(std::floor((centre[d] - lower[d]) / length));
    };
    cell[e] = {index(1), index(0)};
    number.emplace(cell[e], 0);
  }
  AveragingPatches patches;
  for (auto& entry : number) entry.second = patches.count++;
  patches.patch_e = Kokkos::View<int*, MemSpace>("averaging_patch_e", elements);
  const auto patch_e = Kokkos::create_mirror_view(patches.patch_e);
  for (int e = 0; e < elements; ++e) patch_e(e) = number.at(cell[e]);
  Kokkos::deep_copy(patches.patch_e, patch_e);
  return patches;
}

RowNeighbours buildRowNeighbours(const Mesh& mesh, Kokkos::View<const int*, MemSpace> row_e,
                                 int row_count) {
  const auto nodes_e = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.connectivity);
  const auto row_of = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), row_e);
  const int elements = mesh.numElements(), corners = mesh.nodesPerElement();
  const auto row = [&](int e) { return row_of.extent(0) > 0 ? row_of(e) : e; };
  std::map<std::pair<int, int>, int> first_of_edge;  // edge (low, high node) -> an element
  std::vector<std::set<int>> neighbours(row_count);
  for (int e = 0; e < elements; ++e)
    for (int a = 0; a < corners; ++a) {
      const int i = nodes_e(e, a), j = nodes_e(e, (a + 1) % corners);
      const auto [it, fresh] = first_of_edge.emplace(std::minmax(i, j), e);
      if (fresh) continue;
      const int r = row(e), s = row(it->second);
      if (r == s) continue;
      neighbours[r].insert(s);
      neighbours[s].insert(r);
    }
  RowNeighbours out;
  out.start = Kokkos::View<int*, MemSpace>("averaging_neighbour_start", row_count + 1);
  auto start = Kokkos::create_mirror_view(out.start);
  start(0) = 0;
  for (int r = 0; r < row_count; ++r) {
    start(r + 1) = start(r) + static_cast<int>(neighbours[r].size());
    out.most = std::max(out.most, static_cast<int>(neighbours[r].size()));
  }
  out.rows = Kokkos::View<int*, MemSpace>("averaging_neighbour_rows", start(row_count));
  auto rows = Kokkos::create_mirror_view(out.rows);
  for (int r = 0; r < row_count; ++r) {
    int k = start(r);
    for (int s : neighbours[r]) rows(k++) = s;
  }
  Kokkos::deep_copy(out.start, start);
  Kokkos::deep_copy(out.rows, rows);
  return out;
}

}  // namespace argine

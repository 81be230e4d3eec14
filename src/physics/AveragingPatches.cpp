#include "argine/physics/AveragingPatches.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
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

}  // namespace argine

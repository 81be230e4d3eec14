#include "argine/mesh/PointLocator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "argine/mesh/MeshGeometry.hpp"

namespace argine {

PointLocator::PointLocator(const Mesh& mesh)
    : type_(mesh.type),
      num_elements_(mesh.numElements()),
      coordinates_(mesh.coordinates),
      connectivity_(mesh.connectivity),
      neighbours_(computeElementNeighbours(mesh)) {
  const int elements = num_elements_, per = mesh.nodesPerElement();
  const auto coordinates =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  const auto connectivity =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.connectivity);
  constexpr Real kEpsilon = std::numeric_limits<Real>::epsilon();

  // Raw element boxes, the largest coordinate magnitude and the smallest element extent.
  std::vector<Real> raw(static_cast<size_t>(elements) * 4);
  Real magnitude = 0.0, smallest_extent = std::numeric_limits<Real>::max(), extent_sum = 0.0;
  for (int e = 0; e < elements; ++e) {
    Real lo[kDim] = {std::numeric_limits<Real>::max(), std::numeric_limits<Real>::max()};
    Real hi[kDim] = {-lo[0], -lo[1]};
    for (int a = 0; a < per; ++a)
      for (int i = 0; i < kDim; ++i) {
        const Real c = coordinates(connectivity(e, a), i);
        lo[i] = std::min(lo[i], c);
        hi[i] = std::max(hi[i], c);
        magnitude = std::max(magnitude, std::fabs(c));
      }
    const Real extent = std::max(hi[0] - lo[0], hi[1] - lo[1]);
    smallest_extent = std::min(smallest_extent, extent);
    extent_sum += extent;
    for (int i = 0; i < kDim; ++i) {
      raw[4 * e + i] = lo[i];
      raw[4 * e + 2 + i] = hi[i];
    }
  }
  if (elements == 0) return;  // nothing to find; locate() then always returns -1 (no bins)

  // Local coordinates are computed from x - X_0 (absolute round-off eps * |x|), so their
  // error is about eps * |x| / h; keep the tolerance an order above that.
  if (smallest_extent > 0.0)
    tolerance_ = std::max(1e-12, 16.0 * kEpsilon * magnitude / smallest_extent);

  // Enlarge each box so that every point within the tolerance of the element is inside it
  // (local coordinates span at most 2 units over the element extent).
  Kokkos::View<Real* [4], MemSpace> boxes("locator_element_boxes", elements);
  auto boxes_host = Kokkos::create_mirror_view(boxes);
  for (int i = 0; i < kDim; ++i) {
    box_min_[i] = std::numeric_limits<Real>::max();
    box_max_[i] = -std::numeric_limits<Real>::max();
  }
  for (int e = 0; e < elements; ++e) {
    const Real extent = std::max(raw[4 * e + 2] - raw[4 * e], raw[4 * e + 3] - raw[4 * e + 1]);
    const Real pad = 4.0 * tolerance_ * extent + 4.0 * kEpsilon * magnitude;
    for (int i = 0; i < kDim; ++i) {
      boxes_host(e, i) = raw[4 * e + i] - pad;
      boxes_host(e, 2 + i) = raw[4 * e + 2 + i] + pad;
      box_min_[i] = std::min(box_min_[i], boxes_host(e, i));
      box_max_[i] = std::max(box_max_[i], boxes_host(e, 2 + i));
    }
  }
  Kokkos::deep_copy(boxes, boxes_host);
  boxes_ = boxes;

  // Bins about the mean element extent: each element overlaps a few bins, each bin holds a
  // few elements. Capped at 4 bins per element for meshes with a few large elements.
  Real bin_size = extent_sum / elements;
  const Real width = box_max_[0] - box_min_[0], height = box_max_[1] - box_min_[1];
  const Real max_bins = 4.0 * elements + 16.0;
  if (width * height / (bin_size * bin_size) > max_bins)
    bin_size = std::sqrt(width * height / max_bins);
  for (int i = 0; i < kDim; ++i) {
    const Real length = box_max_[i] - box_min_[i];
    bins_[i] = std::max(1, static_cast<int>(std::ceil(length / bin_size)));
    inverse_bin_size_[i] = length > 0.0 ? bins_[i] / length : 0.0;
  }

  // CSR: count, prefix sum, fill in increasing element order (locate relies on that order).
  const int bins = bins_[0] * bins_[1];
  std::vector<int> offsets(static_cast<size_t>(bins) + 1, 0);
  auto range = [&](int e, int r[4]) {
    for (int i = 0; i < kDim; ++i) {
      r[i] = binOf(boxes_host(e, i), i);
      r[2 + i] = binOf(boxes_host(e, 2 + i), i);
    }
  };
  for (int e = 0; e < elements; ++e) {
    int r[4];
    range(e, r);
    for (int by = r[1]; by <= r[3]; ++by)
      for (int bx = r[0]; bx <= r[2]; ++bx) ++offsets[by * bins_[0] + bx + 1];
  }
  for (int b = 0; b < bins; ++b) offsets[b + 1] += offsets[b];
  std::vector<int> fill(offsets.begin(), offsets.end() - 1);
  Kokkos::View<int*, MemSpace> bin_elements("locator_bin_elements", offsets[bins]);
  auto bin_elements_host = Kokkos::create_mirror_view(bin_elements);
  for (int e = 0; e < elements; ++e) {
    int r[4];
    range(e, r);
    for (int by = r[1]; by <= r[3]; ++by)
      for (int bx = r[0]; bx <= r[2]; ++bx) bin_elements_host(fill[by * bins_[0] + bx]++) = e;
  }
  Kokkos::View<int*, MemSpace> bin_offsets("locator_bin_offsets", bins + 1);
  auto bin_offsets_host = Kokkos::create_mirror_view(bin_offsets);
  for (int b = 0; b <= bins; ++b) bin_offsets_host(b) = offsets[b];
  Kokkos::deep_copy(bin_offsets, bin_offsets_host);
  Kokkos::deep_copy(bin_elements, bin_elements_host);
  bin_offsets_ = bin_offsets;
  bin_elements_ = bin_elements;
}

int PointLocator::locateAll(const Kokkos::View<const Real* [kDim], MemSpace>& positions,
                            const Kokkos::View<int*, MemSpace>& elements,
                            const Kokkos::View<Real* [kDim], MemSpace>& local) const {
  const PointLocator locator = *this;
  int outside = 0;
  Kokkos::parallel_reduce(
      "locateAll", Kokkos::RangePolicy<ExecSpace>(0, positions.extent(0)),
      KOKKOS_LAMBDA(const int p, int& lost) {
        const Real x[kDim] = {positions(p, 0), positions(p, 1)};
        Real xi[kDim] = {local(p, 0), local(p, 1)};
        const int element = locator.locate(x, xi, elements(p));
        elements(p) = element;
        if (element < 0) {
          ++lost;
          return;
        }
        local(p, 0) = xi[0];
        local(p, 1) = xi[1];
      },
      outside);
  return outside;
}

}  // namespace argine

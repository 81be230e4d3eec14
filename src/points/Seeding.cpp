#include "argine/points/Seeding.hpp"

#include <Kokkos_Sort.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "argine/core/Error.hpp"
#include "argine/mesh/MeshRegions.hpp"
#include "argine/mesh/ShapeFunctions.hpp"
#include "argine/points/PointFields.hpp"

namespace argine {

namespace {

/// Appends the 3-point pattern (barycentric (2/3, 1/6, 1/6) and its permutations) of the
/// triangle with local vertices P[0..2].
void appendGaussThree(const Real P[3][kDim], std::vector<Real>& out) {
  for (int i = 0; i < 3; ++i)
    for (int d = 0; d < kDim; ++d)
      out.push_back((2.0 / 3.0) * P[i][d] + (1.0 / 6.0) * P[(i + 1) % 3][d] +
                    (1.0 / 6.0) * P[(i + 2) % 3][d]);
}

std::vector<Real> triPattern(int n) {
  std::vector<Real> xi;
  // The four sub-triangles cut by the edge midpoints (corner 0, 1, 2, then the middle one).
  const Real sub[4][3][kDim] = {{{0.0, 0.0}, {0.5, 0.0}, {0.0, 0.5}},
                                {{0.5, 0.0}, {1.0, 0.0}, {0.5, 0.5}},
                                {{0.0, 0.5}, {0.5, 0.5}, {0.0, 1.0}},
                                {{0.5, 0.0}, {0.5, 0.5}, {0.0, 0.5}}};
  const Real whole[3][kDim] = {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}};
  switch (n) {
    case 1:
      return {1.0 / 3.0, 1.0 / 3.0};
    case 3:
      appendGaussThree(whole, xi);
      return xi;
    case 4:
      for (const auto& t : sub)
        for (int d = 0; d < kDim; ++d) xi.push_back((t[0][d] + t[1][d] + t[2][d]) / 3.0);
      return xi;
    case 6: {
      // Barycentric (L0, L1, L2) = permutations of (11, 5, 2)/18; local (xi, eta) = (L1, L2).
      const int permutations[6][3] = {{11, 5, 2}, {11, 2, 5}, {5, 11, 2},
                                      {2, 11, 5}, {5, 2, 11}, {2, 5, 11}};
      for (const auto& l : permutations) {
        xi.push_back(l[1] / 18.0);
        xi.push_back(l[2] / 18.0);
      }
      return xi;
    }
    case 12:
      for (const auto& t : sub) appendGaussThree(t, xi);
      return xi;
    default:
      return xi;
  }
}

std::vector<Real> quadPattern(int n) {
  const int m = static_cast<int>(std::lround(std::sqrt(static_cast<double>(n))));
  std::vector<Real> xi;
  if (m < 1 || m > 4 || m * m != n) return xi;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      xi.push_back(-1.0 + (2.0 * i + 1.0) / m);
      xi.push_back(-1.0 + (2.0 * j + 1.0) / m);
    }
  return xi;
}

std::string whereOf(const SeedRequest& request, const Mesh& mesh) {
  if (!request.where.empty()) return request.where;
  std::ostringstream out;
  out << "Points Per Element (block ";
  if (request.block >= 0 && request.block < static_cast<int>(mesh.blocks.size()))
    out << "'" << mesh.blocks[request.block].name << "')";
  else
    out << "index " << request.block << ")";
  return out.str();
}

/// Fills point `next` from position k of an element's pattern (host views).
template <class Shape, class HostPoints, class Coordinates, class Connectivity>
void seedPoint(int element, int k, const SeedRequest& request, const std::vector<Real>& pattern,
               const Coordinates& coordinates, const Connectivity& connectivity, HostPoints& host,
               int& next) {
  Real X[Shape::kNodes][kDim];
  gatherElementCoordinates<Shape>(coordinates, connectivity, element, X);
  const Real xi[kDim] = {pattern[2 * k], pattern[2 * k + 1]};
  Real x[kDim], J[kDim][kDim];
  mapToPhysical<Shape>(X, xi, x);
  // Sub-region volume: det J at its centre x reference sub-area (exact, see Seeding.hpp).
  const Real volume =
      jacobian<Shape>(X, xi, J) * Shape::kReferenceArea / request.points_per_element;
  const int p = next++;
  host.id(p) = p;
  host.element(p) = element;
  host.material(p) = request.material;
  host.volume(p) = volume;
  host.initial_volume(p) = volume;
  for (int d = 0; d < kDim; ++d) {
    host.local(p, d) = xi[d];
    host.position(p, d) = x[d];
    host.initial_position(p, d) = x[d];
  }
}

/// One point of a region-seeded request: position k of element's pattern.
struct RegionSeed {
  int element = 0;
  int request = 0;
  int k = 0;
};

/// The pattern positions of the region-seeded requests that lie inside their regions
/// (MeshRegions.hpp decides which region holds a position), by element, then request, then
/// position. `regions_of[r]` lists the regions of request r's block (empty: not region-seeded).
template <class Shape, class Coordinates, class Connectivity>
std::vector<RegionSeed> regionSeeds(const Mesh& mesh,
                                    const std::vector<std::vector<int>>& regions_of,
                                    const std::vector<std::vector<Real>>& patterns,
                                    const Coordinates& coordinates,
                                    const Connectivity& connectivity) {
  std::vector<RegionSeed> seeds;
  const RegionLocator locator(mesh.regions);
  for (int e = 0; e < mesh.numElements(); ++e) {
    Real X[Shape::kNodes][kDim];
    gatherElementCoordinates<Shape>(coordinates, connectivity, e, X);
    std::array<Real, kDim> low{X[0][0], X[0][1]}, high = low;
    for (int a = 1; a < Shape::kNodes; ++a)
      for (int d = 0; d < kDim; ++d) {
        low[d] = std::min(low[d], X[a][d]);
        high[d] = std::max(high[d], X[a][d]);
      }
    for (std::size_t r = 0; r < regions_of.size(); ++r) {
      const bool near = std::any_of(regions_of[r].begin(), regions_of[r].end(), [&](int region) {
        return locator.mayTouch(region, low, high);
      });
      if (!near) continue;
      const int block = mesh.regions[regions_of[r].front()].block;
      const int n = static_cast<int>(patterns[r].size()) / 2;
      for (int k = 0; k < n; ++k) {
        const Real xi[kDim] = {patterns[r][2 * k], patterns[r][2 * k + 1]};
        Real x[kDim];
        mapToPhysical<Shape>(X, xi, x);
        const int region = locator.regionAt({x[0], x[1]});
        if (region >= 0 && mesh.regions[region].block == block)
          seeds.push_back({e, static_cast<int>(r), k});
      }
    }
  }
  return seeds;
}

/// Host mirrors of the fields seeding fills.
struct HostSeedFields {
  explicit HostSeedFields(const MaterialPoints& points)
      : id(Kokkos::create_mirror_view(points.id)),
        element(Kokkos::create_mirror_view(points.element)),
        material(Kokkos::create_mirror_view(points.material)),
        local(Kokkos::create_mirror_view(points.local)),
        position(Kokkos::create_mirror_view(points.position)),
        initial_position(Kokkos::create_mirror_view(points.initial_position)),
        volume(Kokkos::create_mirror_view(points.volume)),
        initial_volume(Kokkos::create_mirror_view(points.initial_volume)) {}
  void copyTo(MaterialPoints& points) const {
    Kokkos::deep_copy(points.id, id);
    Kokkos::deep_copy(points.element, element);
    Kokkos::deep_copy(points.material, material);
    Kokkos::deep_copy(points.local, local);
    Kokkos::deep_copy(points.position, position);
    Kokkos::deep_copy(points.initial_position, initial_position);
    Kokkos::deep_copy(points.volume, volume);
    Kokkos::deep_copy(points.initial_volume, initial_volume);
  }
  decltype(Kokkos::create_mirror_view(MaterialPoints::View<int*>())) id, element, material;
  decltype(Kokkos::create_mirror_view(MaterialPoints::View<Real*[kDim]>())) local, position,
      initial_position;
  decltype(Kokkos::create_mirror_view(MaterialPoints::View<Real*>())) volume, initial_volume;
};

/// BinSort operator: one bin per element (plus a last bin for element -1), ordered by
/// permanent id within a bin so the result does not depend on the backend.
struct ElementBins {
  int bins = 1;                           ///< elements + 1
  Kokkos::View<const int*, MemSpace> id;  ///< point ids (tie-break within a bin)
  template <class Keys>
  KOKKOS_INLINE_FUNCTION int bin(Keys& element, const int& p) const {
    return element(p) < 0 ? bins - 1 : element(p);
  }
  KOKKOS_INLINE_FUNCTION int max_bins() const { return bins; }
  /// True if point a goes before point b (same bin).
  template <class Keys, class A, class B>
  KOKKOS_INLINE_FUNCTION bool operator()(Keys&, A& a, B& b) const {
    return id(a) < id(b);
  }
};

}  // namespace

std::string supportedPointsPerElement(ElementType type) {
  return type == ElementType::Tri3 ? "1, 3, 4, 6, 12" : "1, 4, 9, 16";
}

std::vector<Real> seedingPattern(ElementType type, int points_per_element,
                                 const std::string& where) {
  std::vector<Real> pattern =
      type == ElementType::Tri3 ? triPattern(points_per_element) : quadPattern(points_per_element);
  if (pattern.empty()) {
    std::ostringstream out;
    out << "expected one of " << supportedPointsPerElement(type) << " points per "
        << exodusName(type) << " element, found " << points_per_element;
    if (type == ElementType::Quad4)
      out << " (quadrilaterals take square numbers: an m x m grid of equal sub-squares)";
    throw InputError(where, out.str());
  }
  return pattern;
}

MaterialPoints seedMaterialPoints(const Mesh& mesh, const std::vector<SeedRequest>& requests) {
  const int elements = mesh.numElements();
  std::vector<std::vector<Real>> patterns;
  std::vector<std::vector<int>> regions_of(requests.size());  // regions of each request's block
  std::vector<int> owner(elements, -1);  // whole-element request seeding each element
  std::vector<int> requested(mesh.blocks.size(), -1);
  long total = 0;
  for (size_t r = 0; r < requests.size(); ++r) {
    const SeedRequest& request = requests[r];
    const std::string where = whereOf(request, mesh);
    if (request.block < 0 || request.block >= static_cast<int>(mesh.blocks.size())) {
      std::ostringstream out;
      out << "block index " << request.block << " does not exist; the mesh has "
          << mesh.blocks.size() << " blocks";
      throw InputError(where, out.str());
    }
    patterns.push_back(seedingPattern(mesh.type, request.points_per_element, where));
    for (std::size_t region = 0; region < mesh.regions.size(); ++region)
      if (mesh.regions[region].block == request.block)
        regions_of[r].push_back(static_cast<int>(region));
    if (!regions_of[r].empty()) {
      if (requested[request.block] >= 0)
        throw InputError(where, "block '" + mesh.blocks[request.block].name +
                                    "' is already seeded by another material (a block takes "
                                    "one material)");
      requested[request.block] = static_cast<int>(r);
      continue;
    }
    for (const int e : mesh.blocks[request.block].elements) {
      if (owner[e] >= 0) {
        std::ostringstream out;
        out << "element " << e + 1 << " of block '" << mesh.blocks[request.block].name
            << "' is already seeded by another material (a block takes one material)";
        throw InputError(where, out.str());
      }
      owner[e] = static_cast<int>(r);
      total += request.points_per_element;
    }
  }

  const auto coordinates =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  const auto connectivity =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.connectivity);
  const bool triangles = mesh.type == ElementType::Tri3;
  std::vector<RegionSeed> seeds;
  if (!mesh.regions.empty())
    seeds = triangles ? regionSeeds<Tri3>(mesh, regions_of, patterns, coordinates, connectivity)
                      : regionSeeds<Quad4>(mesh, regions_of, patterns, coordinates, connectivity);
  total += static_cast<long>(seeds.size());

  MaterialPoints points;
  points.allocate(static_cast<int>(total));
  HostSeedFields host(points);
  int next = 0;
  auto seed = [&](int e, int k, int r) {
    if (triangles)
      seedPoint<Tri3>(e, k, requests[r], patterns[r], coordinates, connectivity, host, next);
    else
      seedPoint<Quad4>(e, k, requests[r], patterns[r], coordinates, connectivity, host, next);
  };
  std::size_t s = 0;
  for (int e = 0; e < elements; ++e) {  // increasing element: points come out sorted
    const int r = owner[e];
    if (r >= 0) {
      if (s < seeds.size() && seeds[s].element == e) {
        std::ostringstream out;
        out << "element " << e + 1 << " of block '" << mesh.blocks[requests[r].block].name
            << "' also holds points of region '"
            << mesh.blocks[requests[seeds[s].request].block].name
            << "': in a mesh with regions a material fills a region, not the rest of the box";
        throw InputError(whereOf(requests[r], mesh), out.str());
      }
      for (int k = 0; k < requests[r].points_per_element; ++k) seed(e, k, r);
    }
    for (; s < seeds.size() && seeds[s].element == e; ++s) seed(e, seeds[s].k, seeds[s].request);
  }
  host.copyTo(points);
  return points;
}

void sortPointsByElement(MaterialPoints& points) {
  if (points.count <= 1) return;
  int highest = -1;
  const auto element = points.element;
  Kokkos::parallel_reduce(
      "highestElement", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p, int& h) {
        if (element(p) > h) h = element(p);
      },
      Kokkos::Max<int>(highest));

  ElementBins bins;
  bins.bins = highest + 2;
  bins.id = points.id;
  using Keys = Kokkos::View<int*, MemSpace>;
  Kokkos::BinSort<Keys, ElementBins> sorter(points.element, bins, /*sort_within_bins=*/true);
  sorter.create_permute_vector();
  // The permutation is fixed now, so permuting the key (element) and id Views is safe.
  forEachPointField(points, [&](const char*, auto& field) { sorter.sort(field); });
}

}  // namespace argine

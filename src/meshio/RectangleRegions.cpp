/// @file RectangleRegions.cpp
/// Regions of a `rectangle` mesh: geometry checks, the overlap test and the element blocks.
#include "argine/meshio/RectangleRegions.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "argine/core/Error.hpp"
#include "argine/mesh/MeshRegions.hpp"
#include "argine/meshio/SectionGraph.hpp"

namespace argine {

namespace {

const std::string kWhere = "Mesh/Generate/Regions";
const std::string kEmptyBlock = "empty";

/// Refuses regions that overlap without crossing edges (crossings buildSectionGraph already
/// refused): one inside another, two equal ones, or two sharing an edge and more. The graph
/// holds every region edge split at every vertex on it, so each face of the plane the edges
/// cut out borders some edge piece; a probe just off the middle of each piece, on either
/// side, lies in the face there. A face inside two regions is an overlap.
void checkRegionsDisjoint(const SectionGraph& graph) {
  for (const auto& segment : graph.segments) {
    const Point2& a = graph.vertices[segment[0]];
    const Point2& b = graph.vertices[segment[1]];
    const Real length = std::hypot(b[0] - a[0], b[1] - a[1]);
    if (!(length > 0)) continue;
    // Off the edge by far more than rounding, yet well inside any face it borders (pieces
    // are at least the merge tolerance long, faces at least that wide near their edges).
    const Real offset = std::min(1e-3 * length, 10 * graph.tolerance);
    const Point2 normal{-(b[1] - a[1]) / length, (b[0] - a[0]) / length};
    for (const Real side : {1.0, -1.0}) {
      const Point2 probe{0.5 * (a[0] + b[0]) + side * offset * normal[0],
                         0.5 * (a[1] + b[1]) + side * offset * normal[1]};
      int first = -1;
      for (std::size_t r = 0; r < graph.regions.size(); ++r) {
        if (!isInsidePolygon(probe, graph.regions[r])) continue;
        if (first < 0) {
          first = static_cast<int>(r);
          continue;
        }
        std::ostringstream what;
        what << "regions " << graph.region_blocks[first] << " and " << graph.region_blocks[r]
             << " overlap near (" << probe[0] << ", " << probe[1]
             << "); regions may share edges but not area";
        throw InputError(kWhere, what.str());
      }
    }
  }
}

}  // namespace

void applyRectangleRegions(const GeneratorSpec& spec, Mesh& mesh) {
  const SectionGraph graph = buildSectionGraph(spec);
  checkRegionsDisjoint(graph);

  std::vector<std::string> block_names;
  std::vector<BlockRegion> regions;
  for (std::size_t r = 0; r < graph.regions.size(); ++r) {
    const std::string& name = graph.region_blocks[r];
    auto it = std::find(block_names.begin(), block_names.end(), name);
    if (it == block_names.end()) it = block_names.insert(block_names.end(), name);
    regions.push_back({static_cast<int>(it - block_names.begin()), graph.regions[r]});
  }

  const auto coordinates =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  const auto connectivity =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.connectivity);
  const int corners = mesh.nodesPerElement();
  const RegionLocator locator(regions);
  std::vector<int> block_of(mesh.numElements(), -1);
  bool outside = false;
  for (int e = 0; e < mesh.numElements(); ++e) {
    std::array<Real, kDim> centroid{0, 0};
    for (int c = 0; c < corners; ++c)
      for (int d = 0; d < kDim; ++d) centroid[d] += coordinates(connectivity(e, c), d) / corners;
    const int region = locator.regionAt(centroid);
    if (region >= 0) {
      block_of[e] = regions[region].block;
    } else {
      outside = true;
    }
  }
  auto empty = std::find(block_names.begin(), block_names.end(), kEmptyBlock);
  if (empty == block_names.end() && outside)
    empty = block_names.insert(block_names.end(), kEmptyBlock);
  const int empty_block = static_cast<int>(empty - block_names.begin());

  mesh.blocks.clear();
  for (std::size_t b = 0; b < block_names.size(); ++b)
    mesh.blocks.push_back({block_names[b], static_cast<int>(b) + 1, {}});
  auto element_block = Kokkos::create_mirror_view(mesh.element_block);
  for (int e = 0; e < mesh.numElements(); ++e) {
    const int b = block_of[e] >= 0 ? block_of[e] : empty_block;
    element_block(e) = b;
    mesh.blocks[b].elements.push_back(e);
  }
  Kokkos::deep_copy(mesh.element_block, element_block);
  mesh.regions = std::move(regions);
}

}  // namespace argine

/// @file MeshAssembly.cpp
/// The checks and orientation rule shared by the mesh readers (MeshAssembly.hpp).
#include "argine/meshio/MeshAssembly.hpp"

#include <algorithm>
#include <cmath>

#include "argine/core/Error.hpp"
#include "argine/meshio/Geometry2D.hpp"

namespace argine {

AssembledMesh assembleMesh(const std::string& path, ElementType type, const std::vector<Real>& x,
                           const std::vector<Real>& y, const std::vector<RawElementBlock>& blocks) {
  const int nv = nodesPerElement(type);
  const int num_nodes = static_cast<int>(x.size());
  std::size_t total = 0;
  for (const auto& block : blocks) total += block.connectivity.size() / nv;
  const int num_elements = static_cast<int>(total);

  AssembledMesh result;
  Mesh& mesh = result.mesh;
  mesh.type = type;
  mesh.coordinates = Kokkos::View<Real* [kDim], MemSpace>("mesh coordinates", num_nodes);
  mesh.connectivity = Kokkos::View<int**, MemSpace>("mesh connectivity", num_elements, nv);
  mesh.element_block = Kokkos::View<int*, MemSpace>("mesh element block", num_elements);
  auto coordinates = Kokkos::create_mirror_view(mesh.coordinates);
  auto connectivity = Kokkos::create_mirror_view(mesh.connectivity);
  auto element_block = Kokkos::create_mirror_view(mesh.element_block);
  for (int n = 0; n < num_nodes; ++n) {
    coordinates(n, 0) = x[n];
    coordinates(n, 1) = y[n];
  }

  // Connectivity, made counter-clockwise; flipped[e] remembers reordered elements.
  result.flipped.assign(num_elements, 0);
  int e = 0;
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    ElementBlock block;
    block.name = blocks[b].name;
    block.id = blocks[b].id;
    const int count = static_cast<int>(blocks[b].connectivity.size() / nv);
    for (int i = 0; i < count; ++i, ++e) {
      const std::string which = "element " + std::to_string(e + 1) + " (block " + block.name + ")";
      std::vector<Point2> corners(nv);
      for (int k = 0; k < nv; ++k) {
        const int node = blocks[b].connectivity[static_cast<std::size_t>(i) * nv + k];
        if (node < 0 || node >= num_nodes)
          throw InputError(path, which + " refers to node " + std::to_string(node + 1) +
                                     " but the mesh has " + std::to_string(num_nodes) + " nodes");
        connectivity(e, k) = node;
        corners[k] = {x[node], y[node]};
      }
      Real longest = 0;
      for (int k = 0; k < nv; ++k) {
        const Point2& p = corners[k];
        const Point2& q = corners[(k + 1) % nv];
        longest = std::max(longest, std::hypot(q[0] - p[0], q[1] - p[1]));
      }
      const Real area = signedArea(corners);
      const Real tolerance = 1e-12 * longest * longest;
      if (!(std::abs(area) > tolerance))
        throw InputError(path, which + " has zero area (degenerate element)");
      if (area < 0) {
        // Reverse the node order: new local node k = old local node (nv - k) % nv.
        result.flipped[e] = 1;
        std::vector<int> old(nv);
        for (int k = 0; k < nv; ++k) old[k] = connectivity(e, k);
        for (int k = 0; k < nv; ++k) connectivity(e, k) = old[(nv - k) % nv];
        std::reverse(corners.begin() + 1, corners.end());
      }
      // A reflex corner makes the bilinear map of a quad fold over (negative Jacobian).
      for (int k = 0; nv == 4 && k < nv; ++k)
        if (orientation(corners[(k + nv - 1) % nv], corners[k], corners[(k + 1) % nv]) < -tolerance)
          throw InputError(path, which + " is not convex (reflex corner at node " +
                                     std::to_string(connectivity(e, k) + 1) + ")");
      element_block(e) = static_cast<int>(b);
      block.elements.push_back(e);
    }
    mesh.blocks.push_back(std::move(block));
  }
  Kokkos::deep_copy(mesh.coordinates, coordinates);
  Kokkos::deep_copy(mesh.connectivity, connectivity);
  Kokkos::deep_copy(mesh.element_block, element_block);
  return result;
}

}  // namespace argine

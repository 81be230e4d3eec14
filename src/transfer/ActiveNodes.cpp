#include "argine/transfer/ActiveNodes.hpp"

#include "argine/mesh/Mesh.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine {

ActiveNodes::ActiveNodes(int num_nodes)
    : flag_("active_flag_i", num_nodes), nodes_("active_nodes", num_nodes) {}

void ActiveNodes::rebuild(const Mesh& mesh, const MaterialPoints& points) {
  rebuild(mesh, points, Kokkos::View<const int*, MemSpace>());
}

void ActiveNodes::rebuild(const Mesh& mesh, const MaterialPoints& points,
                          Kokkos::View<const int*, MemSpace> also) {
  rebuild(mesh, points, nullptr, also);
}

void ActiveNodes::rebuild(const Mesh& mesh, const MaterialPoints& points, const PointShapes* shapes,
                          Kokkos::View<const int*, MemSpace> also) {
  if (static_cast<int>(flag_.extent(0)) != mesh.numNodes()) *this = ActiveNodes(mesh.numNodes());
  auto flag = flag_;
  auto nodes = nodes_;
  const auto connectivity = mesh.connectivity;
  const auto element_p = points.element;
  const int nodes_per_element = mesh.nodesPerElement();

  // Mark: every point writes 1 to its element's nodes or, on the grid families, to its
  // stencil's (equal values, so no race matters).
  if (shapes && shapes->onGrid()) {
    const auto grid_p = shapes->grid_p;
    const int row = shapes->grid_row;
    Kokkos::parallel_for(
        "active_nodes_mark_stencils", Kokkos::RangePolicy<ExecSpace>(0, points.count),
        KOKKOS_LAMBDA(const int p) {
          if (element_p(p) < 0) return;
          for (int a = 0; a < kGridStencilNodes; ++a) flag(gridNode(grid_p(p), row, a)) = 1;
        });
  } else {
    Kokkos::parallel_for(
        "active_nodes_mark", Kokkos::RangePolicy<ExecSpace>(0, points.count),
        KOKKOS_LAMBDA(const int p) {
          const int e = element_p(p);
          if (e < 0) return;
          for (int a = 0; a < nodes_per_element; ++a) flag(connectivity(e, a)) = 1;
        });
  }
  Kokkos::parallel_for(
      "active_nodes_mark_also", Kokkos::RangePolicy<ExecSpace>(0, also.extent(0)),
      KOKKOS_LAMBDA(const int j) { flag(also(j)) = 1; });

  // Compact the flags into an ascending list (a byte-cheap scan of all nodes).
  int count = 0;
  Kokkos::parallel_scan(
      "active_nodes_compact", Kokkos::RangePolicy<ExecSpace>(0, mesh.numNodes()),
      KOKKOS_LAMBDA(const int i, int& offset, const bool final) {
        if (flag(i)) {
          if (final) nodes(offset) = i;
          ++offset;
        }
      },
      count);

  // Clear the flags again, touching only the listed nodes.
  Kokkos::parallel_for(
      "active_nodes_clear", Kokkos::RangePolicy<ExecSpace>(0, count),
      KOKKOS_LAMBDA(const int j) { flag(nodes(j)) = 0; });
  count_ = count;
}

void ActiveNodes::assignMasked(const ActiveNodes& from,
                               Kokkos::View<const unsigned char*, MemSpace> mask) {
  if (nodes_.extent(0) != from.nodes_.extent(0))
    *this = ActiveNodes(static_cast<int>(from.nodes_.extent(0)));
  auto nodes = nodes_;
  const auto source = from.nodes_;
  int count = 0;
  Kokkos::parallel_scan(
      "active_nodes_masked", Kokkos::RangePolicy<ExecSpace>(0, from.count_),
      KOKKOS_LAMBDA(const int j, int& offset, const bool final) {
        if (mask(source(j))) {
          if (final) nodes(offset) = source(j);
          ++offset;
        }
      },
      count);
  count_ = count;
}

}  // namespace argine

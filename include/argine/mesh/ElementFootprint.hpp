#pragma once
/// @file ElementFootprint.hpp
/// The footprint of an element: every node whose shape function a material point inside it
/// can reach. With the element's own (linear) shapes these are its nodes; on the grid
/// families (GIMP, B-spline: GridShapes.hpp) a point in cell (i, j) reaches beyond its cell,
/// and the footprint is the 4 x 4 block of grid lines i-1 .. i+2 by j-1 .. j+2, clipped to the
/// grid. The one definition of which nodes an element's points can touch, for whatever
/// decides per element rather than per point: the rank decomposition's shared nodes, node
/// owners and always-active nodes (parallel/RankDecomposition.hpp).

#include "argine/mesh/GridShapes.hpp"
#include "argine/mesh/Mesh.hpp"

namespace argine {

class ElementFootprint {
 public:
  /// Most nodes of one footprint: the grid families' 4 x 4 block (kGridStencil + 1 lines per
  /// axis, see nodes()).
  static constexpr int kMaxNodes = (kGridStencil + 1) * (kGridStencil + 1);

  /// The footprints of `mesh`'s elements on its shape functions (Mesh::shape_functions; the
  /// grid families need Mesh::structured). Keeps a host copy of the connectivity.
  explicit ElementFootprint(const Mesh& mesh);

  /// Writes the footprint of `element` into `nodes` and returns how many there are: linear
  /// shapes, the element's nodes in connectivity order; grid families, the block's nodes
  /// ascending (row by row).
  int nodes(int element, int nodes[kMaxNodes]) const;

 private:
  Kokkos::View<int**, Kokkos::HostSpace> connectivity_;
  int nodes_per_element_ = 0;
  bool grid_ = false;
  StructuredGrid structured_;
};

}  // namespace argine

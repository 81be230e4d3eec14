#include "argine/mesh/ElementFootprint.hpp"

#include <algorithm>
#include <stdexcept>

namespace argine {

ElementFootprint::ElementFootprint(const Mesh& mesh)
    : connectivity_(Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.connectivity)),
      nodes_per_element_(mesh.nodesPerElement()),
      grid_(mesh.shape_functions != ShapeFamily::Linear),
      structured_(mesh.structured) {
  if (grid_ && !structured_.valid())
    throw std::logic_error("GIMP and B-spline shape functions need a structured grid");
}

int ElementFootprint::nodes(int element, int nodes[kMaxNodes]) const {
  if (!grid_) {
    for (int a = 0; a < nodes_per_element_; ++a) nodes[a] = connectivity_(element, a);
    return nodes_per_element_;
  }
  // A point in cell i (i <= xi <= i + 1, also on the cell's edges) has its stencil's first
  // line at floor(xi - 1/2), i - 1 or i (gridStencil1D), so its kGridStencil lines lie in
  // i - 1 .. i + kGridStencil - 1; a ghost line outside the grid folds into the edge lines,
  // which the clipped range holds.
  const int row = structured_.cells[0] + 1;
  const int cell[kDim] = {element % structured_.cells[0], element / structured_.cells[0]};
  int first[kDim], last[kDim];
  for (int d = 0; d < kDim; ++d) {
    first[d] = std::max(cell[d] - 1, 0);
    last[d] = std::min(cell[d] + kGridStencil - 1, structured_.cells[d]);
  }
  int count = 0;
  for (int j = first[1]; j <= last[1]; ++j)
    for (int i = first[0]; i <= last[0]; ++i) nodes[count++] = i + j * row;
  return count;
}

}  // namespace argine

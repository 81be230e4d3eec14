#pragma once
/// @file AffineElementMaps.hpp
/// The inverse element maps of the affine elements of a fixed background mesh (every Tri3,
/// and the parallelogram Quad4s of structured meshes), computed once per mesh. With them,
/// re-locating a point that stays in its element and evaluating its shape gradients take a
/// few multiplications and no division or node gather: xi = J^-1 (x - x_0) and
/// dN/dx = dN/dxi J^-1 (J constant on an affine element). Other elements are marked
/// non-affine and take the general path (Newton inverse, Jacobian at the point).

#include "argine/core/Types.hpp"

namespace argine {

struct Mesh;

struct AffineElementMaps {
  template <class T>
  using View = Kokkos::View<T, MemSpace>;

  View<Real* [4]> inverse_jacobian_e;  ///< J^-1 row-major: (0,0), (0,1), (1,0), (1,1) (1/m)
  View<Real* [kDim]> origin_e;         ///< x at the origin of xi (Tri3: node 0; Quad4: centre)
  View<int*> affine_e;                 ///< 1 for an affine element, else 0
  /// On a structured Quad4 mesh whose elements are the grid's cells in grid order (node
  /// (i, j) = i + (cells[0] + 1) j, counter-clockwise from the lower left: the rectangle
  /// generator's): the element of cell i + cells[0] j, -1 for a cell without one; else empty.
  /// The grid families locate points with it by index arithmetic (GridRelocation.hpp).
  View<int*> cell_element;

  AffineElementMaps() = default;
  /// Maps of every element of `mesh` (host work once, O(elements)).
  explicit AffineElementMaps(const Mesh& mesh);
  /// Number of elements the maps were made for (0: none, every element takes the general
  /// path).
  int count() const { return static_cast<int>(affine_e.extent(0)); }
};

}  // namespace argine

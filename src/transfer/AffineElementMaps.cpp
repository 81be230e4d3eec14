#include "argine/transfer/AffineElementMaps.hpp"

#include <cmath>

#include "argine/mesh/Mesh.hpp"
#include "argine/mesh/ShapeFunctions.hpp"

namespace argine {

namespace {

/// J^-1 exactly as physicalGradients forms it (ShapeFunctions.hpp), at xi = 0; returns
/// det J.
template <class Shape>
Real inverseJacobian(const Real X[][kDim], Real inverse[4]) {
  const Real origin[kDim] = {0, 0};
  Real J[kDim][kDim];
  const Real det = jacobian<Shape>(X, origin, J);
  const Real inv = 1.0 / det;
  inverse[0] = J[1][1] * inv;
  inverse[1] = -J[0][1] * inv;
  inverse[2] = -J[1][0] * inv;
  inverse[3] = J[0][0] * inv;
  return det;
}

/// AffineElementMaps::cell_element of `mesh` (host copies of its coordinates and
/// connectivity): empty unless every element is a cell of mesh.structured, once, with its
/// nodes in grid order and at the cell's corners.
template <class Coordinates, class Connectivity>
Kokkos::View<int*, MemSpace> cellElements(const Mesh& mesh, const Coordinates& coordinates,
                                          const Connectivity& connectivity) {
  const StructuredGrid& grid = mesh.structured;
  if (mesh.type != ElementType::Quad4 || !grid.valid()) return {};
  const int nx = grid.cells[0], ny = grid.cells[1], row = nx + 1;
  Kokkos::View<int*, MemSpace> cells("cell_element", static_cast<std::size_t>(nx) * ny);
  auto cell_h = Kokkos::create_mirror_view(cells);
  Kokkos::deep_copy(cell_h, -1);
  constexpr int kCornerX[4] = {0, 1, 1, 0}, kCornerY[4] = {0, 0, 1, 1};
  for (int e = 0; e < mesh.numElements(); ++e) {
    const int i = connectivity(e, 0) % row, j = connectivity(e, 0) / row;
    if (i >= nx || j >= ny || cell_h(i + nx * j) >= 0) return {};
    for (int k = 0; k < 4; ++k) {
      const int corner[kDim] = {i + kCornerX[k], j + kCornerY[k]};
      const int node = corner[0] + row * corner[1];
      if (connectivity(e, k) != node) return {};
      for (int d = 0; d < kDim; ++d)  // the generator's coordinates, up to rounding
        if (std::fabs(coordinates(node, d) - (grid.origin[d] + corner[d] * grid.spacing[d])) >
            1e-9 * grid.spacing[d])
          return {};
    }
    cell_h(i + nx * j) = e;
  }
  Kokkos::deep_copy(cells, cell_h);
  return cells;
}

}  // namespace

AffineElementMaps::AffineElementMaps(const Mesh& mesh)
    : inverse_jacobian_e("affine_inverse_jacobian_e", mesh.numElements()),
      origin_e("affine_origin_e", mesh.numElements()),
      affine_e("affine_e", mesh.numElements()) {
  const auto coordinates =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  const auto connectivity =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.connectivity);
  auto inverse = Kokkos::create_mirror_view(inverse_jacobian_e);
  auto origin = Kokkos::create_mirror_view(origin_e);
  auto affine = Kokkos::create_mirror_view(affine_e);
  withShape(mesh.type, [&](auto shape) {
    using Shape = decltype(shape);
    for (int e = 0; e < mesh.numElements(); ++e) {
      Real X[Shape::kNodes][kDim];
      gatherElementCoordinates<Shape>(coordinates, connectivity, e, X);
      Real inv[4];
      const Real det = inverseJacobian<Shape>(X, inv);
      bool is_affine = det > 0 && Kokkos::Experimental::isfinite(1 / det);
      if constexpr (Shape::kNodes == 4) {
        // x = c + J xi + d xi eta: affine when the bilinear term d vanishes (the test of the
        // relocation's closed form, PointShapes.cpp).
        Real d[kDim], J[kDim][kDim];
        for (int i = 0; i < kDim; ++i) {
          d[i] = 0.25 * (X[0][i] - X[1][i] + X[2][i] - X[3][i]);
          J[i][0] = 0.25 * (-X[0][i] + X[1][i] + X[2][i] - X[3][i]);
          J[i][1] = 0.25 * (-X[0][i] - X[1][i] + X[2][i] + X[3][i]);
          origin(e, i) = 0.25 * (X[0][i] + X[1][i] + X[2][i] + X[3][i]);
        }
        const Real size2 =
            J[0][0] * J[0][0] + J[1][0] * J[1][0] + J[0][1] * J[0][1] + J[1][1] * J[1][1];
        is_affine = is_affine && d[0] * d[0] + d[1] * d[1] <= 1e-28 * size2;
      } else {
        for (int i = 0; i < kDim; ++i) origin(e, i) = X[0][i];
      }
      for (int k = 0; k < 4; ++k) inverse(e, k) = inv[k];
      affine(e) = is_affine ? 1 : 0;
    }
  });
  Kokkos::deep_copy(inverse_jacobian_e, inverse);
  Kokkos::deep_copy(origin_e, origin);
  Kokkos::deep_copy(affine_e, affine);
  cell_element = cellElements(mesh, coordinates, connectivity);
}

}  // namespace argine

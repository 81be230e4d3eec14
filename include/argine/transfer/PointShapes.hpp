#pragma once
/// @file PointShapes.hpp
/// Shape functions of the background mesh evaluated at every material point, once per step
/// after the points are located: the node indices, values N and physical gradients dN/dx
/// that every particle-grid kernel of the step reads. Caching them means the Jacobian of a
/// point's element is inverted once per step instead of once per transfer.

#include "argine/core/Types.hpp"
#include "argine/mesh/Mesh.hpp"
#include "argine/mesh/ShapeFunctions.hpp"

namespace argine {

class PointLocator;
struct AffineElementMaps;
struct MaterialPoints;

/// Most nodes an element of a 2D background mesh has (Quad4).
inline constexpr int kMaxElementNodes = 4;

/// The shape functions of one point: what every particle-grid kernel reads for it, together.
struct PointShape {
  int node[kMaxElementNodes];             ///< mesh node of each element node; -1 for a lost point
  Real value[kMaxElementNodes];           ///< N_a(x_p)
  Real gradient[kMaxElementNodes][kDim];  ///< dN_a/dx_i (x_p) (1/m)
};

/// N and dN/dx at xi in an affine element with inverse Jacobian J^-1 (row-major: (0,0),
/// (0,1), (1,0), (1,1)): dN_a/dx_i = dN_a/dxi_0 J^-1_0i + dN_a/dxi_1 J^-1_1i, J constant. For
/// one point (T = Real) or kLanes (T = Lanes) in one element: the one formula of the
/// relocation and the transfers' AffineShapesAt, so both give the same bits.
template <class Shape, class T>
KOKKOS_INLINE_FUNCTION void affineShapes(const T xi[kDim], const Real inverse[4],
                                         T N[Shape::kNodes], T dNdx[Shape::kNodes][kDim]) {
  Shape::values(xi, N);
  T dN[Shape::kNodes][kDim];
  Shape::localGradients(xi, dN);
  for (int a = 0; a < Shape::kNodes; ++a)
    for (int i = 0; i < kDim; ++i) dNdx[a][i] = dN[a][0] * inverse[i] + dN[a][1] * inverse[2 + i];
}

struct PointShapes {
  template <class T>
  using View = Kokkos::View<T, MemSpace>;

  /// One record per point (112 bytes): a kernel reads a point's nodes, values and gradients
  /// from one place at fixed offsets. Three Views (nodes, values, gradients) cost three
  /// memory streams and runtime row strides: ~10 % more instructions and time in P2G and
  /// G2P on Serial (verification/benchmark). A GPU port may want them split again.
  View<PointShape*> shape_p;
  ElementType type = ElementType::Quad4;  ///< element shape the kernels dispatch on

  /// Set by relocateAndEvaluateShapes with AffineElementMaps, empty after the other
  /// evaluations: the record of a located point p whose element e = points.element(p) has
  /// affine_e(e) = 1 is then exactly nodes connectivity(e, a) and affineShapes(xi_p,
  /// inverse_jacobian_e(e)) with xi_p = points.local(p), so a kernel may compute it from 16
  /// bytes of the point instead of reading 112 (transfer/PointShapesAt.hpp, AffineShapesAt),
  /// and get the same bits.
  Kokkos::View<const Real* [4], MemSpace> inverse_jacobian_e;
  Kokkos::View<const int*, MemSpace> affine_e;
  Kokkos::View<const int**, MemSpace> connectivity;
  /// Whether the views above are set.
  KOKKOS_INLINE_FUNCTION bool fromAffineMaps() const { return affine_e.extent(0) > 0; }
  /// Whether the records of the points in `element` (>= 0) may be computed (see above).
  KOKKOS_INLINE_FUNCTION bool computableIn(int element) const {
    return fromAffineMaps() && affine_e(element) != 0;
  }

  /// Allocate for n points.
  void allocate(int n);
  /// Number of points allocated for.
  int count() const { return static_cast<int>(shape_p.extent(0)); }
};

/// Evaluate N and dN/dx at every point from its element and local coordinates (points with
/// element < 0, lost from the mesh, get node -1 and zero weights). Reallocates `shapes` when
/// the number of points changed. Dispatches once on mesh.type.
void evaluatePointShapes(const Mesh& mesh, const MaterialPoints& points, PointShapes& shapes);

/// Re-locates every point from its position (element and local coordinates, as
/// PointLocator::locateAll) and evaluates its shape functions, in one pass: a point still
/// strictly inside its element (the common case) is found with one inverse map whose
/// element coordinates are reused for N and dN/dx; the others go through `locator`.
/// Returns the number of points outside the mesh (element -1, zero weights).
int relocateAndEvaluateShapes(const Mesh& mesh, const PointLocator& locator, MaterialPoints& points,
                              PointShapes& shapes);

/// What a relocation found.
struct RelocationCounts {
  int lost = 0;             ///< points outside the mesh (element -1)
  int changed_element = 0;  ///< points whose element changed (0: the active nodes did not)
};

/// The same with the inverse maps of the mesh's affine elements (AffineElementMaps, built
/// once per mesh): a point staying in an affine element costs no division and no node
/// gather. In an affine element xi = J^-1 (x - x_0) whichever way the element was found,
/// so relocating points again from unchanged positions (e.g. after sorting them) gives the
/// same shapes bit for bit. Results differ from the overload above only by round-off
/// (J^-1 instead of Cramer's rule; J of a parallelogram Quad4 taken at its centre).
RelocationCounts relocateAndEvaluateShapes(const Mesh& mesh, const PointLocator& locator,
                                           const AffineElementMaps& maps, MaterialPoints& points,
                                           PointShapes& shapes);

}  // namespace argine

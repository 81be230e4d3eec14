#pragma once
/// @file PointShapes.hpp
/// Shape functions of the background mesh evaluated at every material point, once per step
/// after the points are located: the node indices, values N and physical gradients dN/dx
/// that every particle-grid kernel of the step reads. Caching them means the Jacobian of a
/// point's element is inverted once per step instead of once per transfer.

#include "argine/core/Types.hpp"
#include "argine/mesh/Mesh.hpp"

namespace argine {

class PointLocator;
struct MaterialPoints;

/// Most nodes an element of a 2D background mesh has (Quad4).
inline constexpr int kMaxElementNodes = 4;

struct PointShapes {
  template <class T>
  using View = Kokkos::View<T, MemSpace>;

  View<int* [kMaxElementNodes]> node_p;    ///< mesh node of each element node; -1 for a lost point
  View<Real* [kMaxElementNodes]> value_p;  ///< N_a(x_p)
  View<Real* [kMaxElementNodes][kDim]> gradient_p;  ///< dN_a/dx_i (x_p) (1/m)
  ElementType type = ElementType::Quad4;            ///< element shape the kernels dispatch on

  /// Allocate for n points.
  void allocate(int n);
  /// Number of points allocated for.
  int count() const { return static_cast<int>(node_p.extent(0)); }
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

}  // namespace argine

#pragma once
/// @file PointShapesAt.hpp
/// What a transfer kernel reads of a point's shape functions, for one point (T = Real) or
/// for kLanes consecutive points at once (T = Lanes, core/Lanes.hpp): N_a, dN_a/dx_d and a
/// nodal value at the point's node a. A kernel body written once against this serves both,
/// so the per-point formulas have one source and every lane gets the one-point bits. The
/// lanes read their shapes and nodal values lane by lane (a gather); when all of them lie in
/// one element, a nodal value is read once and copied to every lane.

#include "argine/core/Lanes.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine {

template <class T>
struct PointShapesAt;

template <>
struct PointShapesAt<Real> {
  using Value = Real;
  static constexpr int kCount = 1;  ///< points
  PointShape computed;              ///< the shapes, where they are not stored
  const PointShape& shape;          ///< the record or `computed` (PointShapes::of)

  /// Point p, located.
  template <class ElementView, class LocalView>
  KOKKOS_INLINE_FUNCTION PointShapesAt(const PointShapes& shapes, const ElementView& element_p,
                                       const LocalView& local_p, int p)
      : shape(shapes.of(p, element_p, local_p, computed)) {}
  PointShapesAt(const PointShapesAt&) = delete;  // `shape` may refer to `computed`
  KOKKOS_INLINE_FUNCTION int node(int a, int /*lane*/ = 0) const { return shape.node[a]; }
  KOKKOS_INLINE_FUNCTION Real value(int a) const { return shape.value[a]; }
  KOKKOS_INLINE_FUNCTION Real gradient(int a, int d) const { return shape.gradient[a][d]; }
  /// values_i(node a, slot).
  template <class Values>
  KOKKOS_INLINE_FUNCTION Real nodal(const Values& values_i, int a, int slot) const {
    return values_i(shape.node[a], slot);
  }
};

template <>
struct PointShapesAt<Lanes> {
  using Value = Lanes;
  static constexpr int kCount = kLanes;
  const PointShape* shape[kLanes];
  bool one_element;  ///< all lanes have the same nodes

  /// The points p .. p + kLanes - 1 (a chunk), all located, with records (not
  /// PointShapes::computed_c); `one_element`: all in one element.
  KOKKOS_INLINE_FUNCTION PointShapesAt(const PointShapes& shapes, int p, bool same_element)
      : one_element(same_element) {
    for (int l = 0; l < kLanes; ++l) shape[l] = &shapes.stored_p(p + l);
  }
  KOKKOS_INLINE_FUNCTION int node(int a, int lane) const { return shape[lane]->node[a]; }
  KOKKOS_INLINE_FUNCTION Lanes value(int a) const {
    Lanes out;
    for (int l = 0; l < kLanes; ++l) out[l] = shape[l]->value[a];
    return out;
  }
  KOKKOS_INLINE_FUNCTION Lanes gradient(int a, int d) const {
    Lanes out;
    for (int l = 0; l < kLanes; ++l) out[l] = shape[l]->gradient[a][d];
    return out;
  }
  // forced: not inlined, the call re-reads the lanes' node indices for every slot
  template <class Values>
  KOKKOS_FORCEINLINE_FUNCTION Lanes nodal(const Values& values_i, int a, int slot) const {
    if (one_element) return splat<Lanes>(values_i(shape[0]->node[a], slot));
    Lanes out;
    for (int l = 0; l < kLanes; ++l) out[l] = values_i(shape[l]->node[a], slot);
    return out;
  }
};

/// The same as PointShapesAt<Lanes> for a chunk of kLanes points whose shapes are computed
/// (PointShapes::computed_c: one affine element), from their local coordinates and the
/// element's J^-1, all lanes at once: 16 bytes a point instead of a 112-byte record, the bits
/// PointShapes::of gives each point (affineShapes, the one formula).
template <class Shape>
struct AffineShapesAt {
  using Value = Lanes;
  static constexpr int kCount = kLanes;
  int nodes[Shape::kNodes];
  Lanes N[Shape::kNodes];
  Lanes dNdx[Shape::kNodes][kDim];

  /// The points p .. p + kLanes - 1, all in element e, which is affine.
  template <class LocalView>
  KOKKOS_INLINE_FUNCTION AffineShapesAt(const PointShapes& shapes, const LocalView& local_p, int p,
                                        int e) {
    const Lanes xi[kDim] = {load<Lanes>(local_p, p, 0), load<Lanes>(local_p, p, 1)};
    const Real inverse[4] = {shapes.inverse_jacobian_e(e, 0), shapes.inverse_jacobian_e(e, 1),
                             shapes.inverse_jacobian_e(e, 2), shapes.inverse_jacobian_e(e, 3)};
    affineShapes<Shape>(xi, inverse, N, dNdx);
    for (int a = 0; a < Shape::kNodes; ++a) nodes[a] = shapes.connectivity(e, a);
  }
  KOKKOS_INLINE_FUNCTION int node(int a, int /*lane*/) const { return nodes[a]; }
  KOKKOS_INLINE_FUNCTION Lanes value(int a) const { return N[a]; }
  KOKKOS_INLINE_FUNCTION Lanes gradient(int a, int d) const { return dNdx[a][d]; }
  template <class Values>
  KOKKOS_INLINE_FUNCTION Lanes nodal(const Values& values_i, int a, int slot) const {
    return splat<Lanes>(values_i(nodes[a], slot));
  }
};

/// Point l's part of v: v itself for one point (a value or a bool), lane l for Lanes.
template <class V>
KOKKOS_INLINE_FUNCTION auto lane(const V& v, int /*l*/)
    -> std::enable_if_t<std::is_scalar_v<V>, V> {
  return v;
}
KOKKOS_INLINE_FUNCTION Real lane(Lanes v, int l) {
  return v[l];
}
KOKKOS_INLINE_FUNCTION bool lane(LaneMask m, int l) {
  return m[l] != 0;
}

/// The points' values of v in point order: out[0] = v for one point, the lanes for Lanes (one
/// vector store, where extracting lanes one by one costs a shuffle each).
KOKKOS_INLINE_FUNCTION void spill(Real v, Real out[1]) {
  out[0] = v;
}
KOKKOS_INLINE_FUNCTION void spill(Lanes v, Real out[kLanes]) {
  std::memcpy(out, &v, sizeof v);
}

}  // namespace argine

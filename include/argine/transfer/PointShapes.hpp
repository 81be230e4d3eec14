#pragma once
/// @file PointShapes.hpp
/// Shape functions of the background mesh evaluated at every material point, once per step
/// after the points are located: the node indices, values N and physical gradients dN/dx
/// that every particle-grid kernel of the step reads. Caching them means the Jacobian of a
/// point's element is inverted once per step instead of once per transfer.

#include "argine/core/Lanes.hpp"
#include "argine/core/Types.hpp"
#include "argine/mesh/GridShapes.hpp"
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

/// A point's record from its element's nodes, N and dN/dx; the slots past Shape::kNodes get
/// node -1 and zero weights, so that a record's bits depend on nothing else.
template <class Shape, class Connectivity>
KOKKOS_INLINE_FUNCTION void setPointShape(const Connectivity& connectivity, int e,
                                          const Real N[Shape::kNodes],
                                          const Real dNdx[Shape::kNodes][kDim], PointShape& shape) {
  for (int a = 0; a < Shape::kNodes; ++a) {
    shape.node[a] = connectivity(e, a);
    shape.value[a] = N[a];
    shape.gradient[a][0] = dNdx[a][0];
    shape.gradient[a][1] = dNdx[a][1];
  }
  for (int a = Shape::kNodes; a < kMaxElementNodes; ++a) {
    shape.node[a] = -1;
    shape.value[a] = 0;
    shape.gradient[a][0] = shape.gradient[a][1] = 0;
  }
}

/// The record of a point outside the mesh: node -1 and zero weights.
KOKKOS_INLINE_FUNCTION void setLostPointShape(PointShape& shape) {
  for (int a = 0; a < kMaxElementNodes; ++a) {
    shape.node[a] = -1;
    shape.value[a] = 0;
    shape.gradient[a][0] = shape.gradient[a][1] = 0;
  }
}

struct PointShapes {
  template <class T>
  using View = Kokkos::View<T, MemSpace>;

  /// One record per point (112 bytes): a kernel reads a point's nodes, values and gradients
  /// from one place at fixed offsets. Three Views (nodes, values, gradients) cost three
  /// memory streams and runtime row strides: ~10 % more instructions and time in P2G and
  /// G2P on Serial (verification/benchmark). A GPU port may want them split again.
  ///
  /// Written for every point by evaluatePointShapes; by the relocation with
  /// AffineElementMaps for the points of every chunk that is not computed (computed_c).
  /// Read a point's shapes through of(), which knows which; a kernel that takes a chunk at
  /// once asks computed_c. Like the records, the chunks hold for the point order they were
  /// made in: points sorted or migrated are relocated before their shapes are read.
  View<PointShape*> stored_p;
  /// 1 for a chunk c of kLanes points (p / kLanes = c) whose shapes are computed where they
  /// are read, from 16 bytes of local coordinates a point instead of a 112-byte record (the
  /// same bits), and which has no records; 0 for a chunk with records. Set by the
  /// relocation with AffineElementMaps (computedChunk decides), 0 everywhere after the other
  /// evaluations.
  View<int*> computed_c;
  ElementType type = ElementType::Quad4;  ///< element shape the kernels dispatch on

  /// The shape functions the transfers use (Mesh::shape_functions, or Linear where a caller
  /// asks for the element's own, e.g. the implicit path). GIMP and B-spline: every located
  /// point has a TensorShape in grid_p, which is all their kernels read; stored_p holds the
  /// linear shapes of its element after evaluatePointShapes and after a relocation by the
  /// element route, and is left as it was by the grid's relocation (GridRelocation.hpp).
  ShapeFamily family = ShapeFamily::Linear;
  View<TensorShape*> grid_p;  ///< GIMP, B-spline: each point's 3 x 3 stencil
  int grid_row = 0;           ///< GIMP, B-spline: nodes per grid row (cells[0] + 1)
  /// Whether the transfers use the grid families' records (grid_p).
  KOKKOS_INLINE_FUNCTION bool onGrid() const { return family != ShapeFamily::Linear; }

  /// Set by relocateAndEvaluateShapes with AffineElementMaps, empty after the other
  /// evaluations: the shapes of a located point p whose element e has affine_e(e) = 1 are
  /// nodes connectivity(e, a) and affineShapes(xi_p, inverse_jacobian_e(e)), xi_p =
  /// points.local(p).
  Kokkos::View<const Real* [4], MemSpace> inverse_jacobian_e;
  Kokkos::View<const int*, MemSpace> affine_e;
  Kokkos::View<const int**, MemSpace> connectivity;
  /// Whether the views above are set.
  KOKKOS_INLINE_FUNCTION bool fromAffineMaps() const { return affine_e.extent(0) > 0; }

  /// Whether the relocation makes a chunk's shapes computed (computed_c): all kLanes of its
  /// points exist and lie in one element (`one_element`, `element`) that is affine, with the
  /// maps set. Only whole chunks in one element: a Quad4 mesh seeded four points an element
  /// and sorted is made of them, and where the points of a chunk straddle elements (Tri3,
  /// boundaries) reading the records is cheaper than computing each lane's element.
  KOKKOS_INLINE_FUNCTION bool computedChunk(int element, bool one_element) const {
    return one_element && element >= 0 && fromAffineMaps() && affine_e(element) != 0;
  }

  /// The shapes of point p at local coordinates local_p(p, .) in element element_p(p): its
  /// record, or computed into `scratch` in a computed chunk (the bits the record would
  /// hold). A lost point's record has node -1 and zero weights.
  template <class ElementView, class LocalView>
  KOKKOS_FORCEINLINE_FUNCTION const PointShape& of(int p, const ElementView& element_p,
                                                   const LocalView& local_p,
                                                   PointShape& scratch) const {
    if (!computed_c(static_cast<unsigned>(p) / kLanes)) return stored_p(p);  // p >= 0
    const Real xi[kDim] = {local_p(p, 0), local_p(p, 1)};
    computeIn(element_p(p), xi, scratch);
    return scratch;
  }

  /// Allocate for n points.
  void allocate(int n);
  /// grid_p sized for n points (kept when it is) and grid_row set for `grid`: what each
  /// evaluation of the tensor shapes does first.
  void prepareGrid(int n, const StructuredGrid& grid);
  /// Number of points allocated for.
  KOKKOS_INLINE_FUNCTION int count() const { return static_cast<int>(stored_p.extent(0)); }

 private:
  /// The shapes at xi in element e of a computed chunk (kept out of of(), which every
  /// per-point kernel inlines).
  KOKKOS_INLINE_FUNCTION void computeIn(int e, const Real xi[kDim], PointShape& shape) const {
    const Real inverse[4] = {inverse_jacobian_e(e, 0), inverse_jacobian_e(e, 1),
                             inverse_jacobian_e(e, 2), inverse_jacobian_e(e, 3)};
    if (type == ElementType::Tri3)
      computeIn<Tri3>(e, xi, inverse, shape);
    else
      computeIn<Quad4>(e, xi, inverse, shape);
  }
  template <class Shape>
  KOKKOS_INLINE_FUNCTION void computeIn(int e, const Real xi[kDim], const Real inverse[4],
                                        PointShape& shape) const {
    Real N[Shape::kNodes], dNdx[Shape::kNodes][kDim];
    affineShapes<Shape>(xi, inverse, N, dNdx);
    setPointShape<Shape>(connectivity, e, N, dNdx, shape);
  }
};

/// A point's shapes on the grid families, expanded from its TensorShape: what a kernel that
/// is not written for the tensor product reads (nodes -1 and zero weights for a lost point).
struct GridShapeRecord {
  int node[kGridStencilNodes];
  Real value[kGridStencilNodes];
  Real gradient[kGridStencilNodes][kDim];
};

/// Node a = ax + kGridStencil ay of a tensor shape on a grid of `row` nodes per row, its N and
/// dN/dx: the one expansion of TensorShape.
KOKKOS_INLINE_FUNCTION int gridNode(const TensorShape& t, int row, int a) {
  const int ax = a % kGridStencil, ay = a / kGridStencil;
  return t.line[0][ax] < 0 ? -1 : t.line[0][ax] + t.line[1][ay] * row;
}
KOKKOS_INLINE_FUNCTION Real gridValue(const TensorShape& t, int a) {
  return t.value[0][a % kGridStencil] * t.value[1][a / kGridStencil];
}
KOKKOS_INLINE_FUNCTION Real gridGradient(const TensorShape& t, int a, int d) {
  const int ax = a % kGridStencil, ay = a / kGridStencil;
  return d == 0 ? t.gradient[0][ax] * t.value[1][ay] : t.value[0][ax] * t.gradient[1][ay];
}
KOKKOS_INLINE_FUNCTION void expandGridShape(const TensorShape& t, int row, GridShapeRecord& out) {
  for (int a = 0; a < kGridStencilNodes; ++a) {
    out.node[a] = gridNode(t, row, a);
    out.value[a] = gridValue(t, a);
    out.gradient[a][0] = gridGradient(t, a, 0);
    out.gradient[a][1] = gridGradient(t, a, 1);
  }
}
/// The tensor shape of a point outside the mesh: line -1 and zero weights.
KOKKOS_INLINE_FUNCTION void setLostTensorShape(TensorShape& t) {
  for (int d = 0; d < kDim; ++d)
    for (int k = 0; k < kGridStencil; ++k) {
      t.line[d][k] = d == 0 ? -1 : 0;
      t.value[d][k] = t.gradient[d][k] = 0;
    }
}

/// The shape-function families as policies a kernel is written against once and
/// instantiated for each (withShapeFamily): kNodes nodes a point, Record the type of()
/// fills, kElementCentre whether the advective flux div(c w) (4.12, 4.16) is taken at the
/// element centre by the element families' strain kernel (linear: true) or at the centre of
/// the point's cell by the grid families' own kernel (GridPointTransfers.hpp), and
/// fluxCentre: the weights N_a and gradients dN_a/dx with which that flux reads node a's
/// c_a and w_a, c = sum N_a c_a, grad c = sum dN_a/dx c_a (the point's liquid mass changes by
/// -dt V (c sum dN_a/dx . w_a + grad c . sum N_a w_a)).
template <int Nodes>
struct ElementShapeFamily {
  static constexpr int kNodes = Nodes;
  static constexpr bool kElementCentre = true;
  using Record = PointShape;
  template <class ElementView, class LocalView>
  KOKKOS_FORCEINLINE_FUNCTION static const PointShape& of(const PointShapes& shapes, int p,
                                                          const ElementView& element_p,
                                                          const LocalView& local_p,
                                                          PointShape& scratch) {
    return shapes.of(p, element_p, local_p, scratch);
  }
  /// The nodes of point p's stencil (node[0] < 0: lost), for a kernel that asks whether it
  /// needs a point before it reads the weights: here of()'s, which reads them anyway.
  template <class ElementView, class LocalView>
  KOKKOS_FORCEINLINE_FUNCTION static const int* nodesOf(const PointShapes& shapes, int p,
                                                        const ElementView& element_p,
                                                        const LocalView& local_p,
                                                        PointShape& scratch) {
    return of(shapes, p, element_p, local_p, scratch).node;
  }
  /// The element centre's N = 1 / kNodes, the point's own gradients.
  KOKKOS_INLINE_FUNCTION static void fluxCentre(const PointShapes&, int, const PointShape& shape,
                                                Real value[kNodes], Real gradient[kNodes][kDim]) {
    for (int a = 0; a < kNodes; ++a) {
      value[a] = Real(1) / kNodes;
      for (int d = 0; d < kDim; ++d) gradient[a][d] = shape.gradient[a][d];
    }
  }
};

struct GridShapeFamily {
  static constexpr int kNodes = kGridStencilNodes;
  static constexpr bool kElementCentre = false;
  using Record = GridShapeRecord;
  template <class ElementView, class LocalView>
  KOKKOS_INLINE_FUNCTION static const GridShapeRecord& of(const PointShapes& shapes, int p,
                                                          const ElementView&, const LocalView&,
                                                          GridShapeRecord& scratch) {
    expandGridShape(shapes.grid_p(p), shapes.grid_row, scratch);
    return scratch;
  }
  /// The nodes of point p's stencil (node[0] < 0: lost) from its tensor lines alone, without
  /// expanding the nine weights and gradients of().
  template <class ElementView, class LocalView>
  KOKKOS_INLINE_FUNCTION static const int* nodesOf(const PointShapes& shapes, int p,
                                                   const ElementView&, const LocalView&,
                                                   GridShapeRecord& scratch) {
    const TensorShape& t = shapes.grid_p(p);
    for (int a = 0; a < kGridStencilNodes; ++a) scratch.node[a] = gridNode(t, shapes.grid_row, a);
    return scratch.node;
  }
  /// The bilinear shapes of the point's cell at its centre (cellCentreWeights1D): N = 1/4
  /// and dN/dx = (-+1/h) 1/2 at the cell's four corners, 0 at the stencil's other nodes;
  /// gridStrainIncrements' cellCentreAdvectiveFlux reads the nodes with these.
  KOKKOS_INLINE_FUNCTION static void fluxCentre(const PointShapes& shapes, int p,
                                                const GridShapeRecord&, Real value[kNodes],
                                                Real gradient[kNodes][kDim]) {
    const TensorShape& t = shapes.grid_p(p);
    Real weight[kDim][kGridStencil], slope[kDim][kGridStencil];
    for (int d = 0; d < kDim; ++d) cellCentreWeights1D(t, d, weight[d], slope[d]);
    for (int a = 0; a < kNodes; ++a) {
      const int ax = a % kGridStencil, ay = a / kGridStencil;
      value[a] = weight[0][ax] * weight[1][ay];
      gradient[a][0] = slope[0][ax] * weight[1][ay];
      gradient[a][1] = weight[0][ax] * slope[1][ay];
    }
  }
};

/// Calls f(family) with the policy of `shapes`: GridShapeFamily on the grid families, else
/// ElementShapeFamily of the element's node count. Chosen once per call, not per point.
template <class Function>
decltype(auto) withShapeFamily(const PointShapes& shapes, Function&& f) {
  if (shapes.onGrid()) return f(GridShapeFamily{});
  if (shapes.type == ElementType::Tri3) return f(ElementShapeFamily<3>{});
  return f(ElementShapeFamily<4>{});
}

/// Every point's shapes as PointShapes::of gives them (stored or computed), in one View: for
/// tests and checks that compare shapes, not for the step.
Kokkos::View<PointShape*, MemSpace> everyPointShape(const PointShapes& shapes,
                                                    const MaterialPoints& points);

/// Evaluate N and dN/dx at every point from its element and local coordinates (points with
/// element < 0, lost from the mesh, get node -1 and zero weights). Reallocates `shapes` when
/// the number of points changed. Dispatches once on mesh.type. The family is
/// mesh.shape_functions; the grid families also get their tensor shapes (evaluateGridShapes).
void evaluatePointShapes(const Mesh& mesh, const MaterialPoints& points, PointShapes& shapes);
/// The same with the family given: Linear where a path has only the element's own shapes
/// (the implicit seepage assembly).
void evaluatePointShapes(const Mesh& mesh, const MaterialPoints& points, PointShapes& shapes,
                         ShapeFamily family);

/// The grid families' tensor shapes of every point from its position (GridShapes.hpp; uGIMP
/// half-width from the point's initial volume, gimpHalfWidth), and a lost point's (element
/// -1) zero record. Returns the number of located points whose stencil differs from the one
/// grid_p held (for the active nodes). Needs shapes.family GIMP or B-spline and a structured
/// mesh.
int evaluateGridShapes(const Mesh& mesh, const MaterialPoints& points, PointShapes& shapes);

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
/// (J^-1 instead of Cramer's rule; J of a parallelogram Quad4 taken at its centre). On the
/// grid families with AffineElementMaps::cell_element: relocateOnGrid (GridRelocation.hpp;
/// the element and tensor shape from the position alone, so the same bits again after a
/// sort), changed_element then counting changed stencils too.
RelocationCounts relocateAndEvaluateShapes(const Mesh& mesh, const PointLocator& locator,
                                           const AffineElementMaps& maps, MaterialPoints& points,
                                           PointShapes& shapes);

}  // namespace argine

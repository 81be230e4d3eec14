#include "argine/transfer/PointShapes.hpp"

#include <stdexcept>

#include "GridRelocation.hpp"
#include "argine/core/UntrackedViews.hpp"
#include "argine/mesh/Mesh.hpp"
#include "argine/mesh/PointLocator.hpp"
#include "argine/mesh/ShapeFunctions.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/AffineElementMaps.hpp"

namespace argine {

void PointShapes::allocate(int n) {
  stored_p = View<PointShape*>("stored_p", n);
  computed_c = View<int*>("computed_c", (n + kLanes - 1) / kLanes);
  grid_p = View<TensorShape*>("grid_p", onGrid() ? n : 0);
}

void PointShapes::prepareGrid(int n, const StructuredGrid& grid) {
  if (static_cast<int>(grid_p.extent(0)) != n) grid_p = View<TensorShape*>("grid_p", n);
  grid_row = grid.cells[0] + 1;
}

Kokkos::View<PointShape*, MemSpace> everyPointShape(const PointShapes& shapes,
                                                    const MaterialPoints& points) {
  Kokkos::View<PointShape*, MemSpace> out("every_point_shape", points.count);
  const PointShapes s = untracked(shapes);
  const auto element_p = points.element;
  const auto local_p = points.local;
  Kokkos::parallel_for(
      "every_point_shape", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p) {
        PointShape scratch;
        out(p) = s.of(p, element_p, local_p, scratch);
      });
  return out;
}

namespace {

template <class Shape>
void evaluate(const Mesh& mesh, const MaterialPoints& points, PointShapes& shapes) {
  constexpr int kNodes = Shape::kNodes;
  const auto coordinates = mesh.coordinates;
  const auto connectivity = mesh.connectivity;
  const auto element_p = points.element;
  const auto local_p = points.local;
  const auto shape_p = shapes.stored_p;
  Kokkos::parallel_for(
      "evaluate_point_shapes", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p) {
        const int e = element_p(p);
        if (e < 0) {
          setLostPointShape(shape_p(p));
          return;
        }
        Real X[kNodes][kDim];
        gatherElementCoordinates<Shape>(coordinates, connectivity, e, X);
        const Real xi[kDim] = {local_p(p, 0), local_p(p, 1)};
        Real N[kNodes];
        Real dNdx[kNodes][kDim];
        Shape::values(xi, N);
        physicalGradients<Shape>(X, xi, dNdx);
        setPointShape<Shape>(connectivity, e, N, dNdx, shape_p(p));
      });
}

/// Local coordinates of x in an element: closed form when the element is affine (every
/// Tri3, and the parallelogram Quad4s of structured meshes, whose bilinear term vanishes),
/// else the Newton inverse of ShapeFunctions.hpp.
template <class Shape>
KOKKOS_INLINE_FUNCTION bool localCoordinates(const Real X[][kDim], const Real x[kDim],
                                             Real xi[kDim]) {
  if constexpr (Shape::kNodes == 4) {
    // x = c + J xi + d xi eta with c, J, d from the nodes; d = 0 for a parallelogram.
    Real d[kDim], J[kDim][kDim], c[kDim];
    for (int i = 0; i < kDim; ++i) {
      d[i] = 0.25 * (X[0][i] - X[1][i] + X[2][i] - X[3][i]);
      J[i][0] = 0.25 * (-X[0][i] + X[1][i] + X[2][i] - X[3][i]);
      J[i][1] = 0.25 * (-X[0][i] - X[1][i] + X[2][i] + X[3][i]);
      c[i] = 0.25 * (X[0][i] + X[1][i] + X[2][i] + X[3][i]);
    }
    const Real size2 =
        J[0][0] * J[0][0] + J[1][0] * J[1][0] + J[0][1] * J[0][1] + J[1][1] * J[1][1];
    if (d[0] * d[0] + d[1] * d[1] <= 1e-28 * size2) {
      const Real det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
      if (!(det != 0.0)) return false;
      const Real r0 = x[0] - c[0], r1 = x[1] - c[1];
      xi[0] = (r0 * J[1][1] - J[0][1] * r1) / det;
      xi[1] = (J[0][0] * r1 - r0 * J[1][0]) / det;
      return true;
    }
  }
  return mapToLocal<Shape>(X, x, xi);
}

/// The relocation of one point and the writing of its record: the two halves of a chunk's
/// relocation (relocate), so that a chunk whose shapes are computed writes no record.
template <class Shape>
struct PointRelocation {
  static constexpr int kNodes = Shape::kNodes;
  decltype(Mesh::coordinates) coordinates;
  decltype(Mesh::connectivity) connectivity;
  decltype(MaterialPoints::element) element_p;
  decltype(MaterialPoints::local) local_p;
  decltype(MaterialPoints::position) position_p;
  decltype(PointShapes::stored_p) shape_p;
  decltype(AffineElementMaps::inverse_jacobian_e) inverse_e;
  decltype(AffineElementMaps::origin_e) origin_e;
  decltype(AffineElementMaps::affine_e) affine_e;
  PointLocator locator;
  bool with_maps;  // AffineElementMaps given (PointShapes::fromAffineMaps)

  KOKKOS_FORCEINLINE_FUNCTION bool affine(int e) const { return with_maps && affine_e(e) != 0; }

  /// xi = J^-1 (x - x_0) in an affine element, whichever path found the element, so
  /// relocating a point twice from one position gives the same shapes bit for bit. Inlined
  /// by force, like the members below: called, it returned xi through the stack as two
  /// scalars read back as a vector, a store-forwarding stall that doubled the relocation.
  KOKKOS_FORCEINLINE_FUNCTION void affineLocal(int e, const Real x[kDim], Real xi[kDim]) const {
    const Real y0 = x[0] - origin_e(e, 0), y1 = x[1] - origin_e(e, 1);
    xi[0] = inverse_e(e, 0) * y0 + inverse_e(e, 1) * y1;
    xi[1] = inverse_e(e, 2) * y0 + inverse_e(e, 3) * y1;
  }

  /// Point p's element (-1: outside the mesh) and local coordinates xi from its position,
  /// stored (xi is not set for a point outside); counts the points `outside` and those whose
  /// element changed (`moved`).
  KOKKOS_FORCEINLINE_FUNCTION int locate(int p, int& outside, int& moved, Real xi[kDim]) const {
    const Real x[kDim] = {position_p(p, 0), position_p(p, 1)};
    int e = element_p(p);
    bool found = false;
    if (e >= 0) {  // fast path: still strictly inside the same element
      Real trial[kDim];
      bool mapped = true;
      if (affine(e)) {
        affineLocal(e, x, trial);
      } else {
        Real X[kNodes][kDim];
        gatherElementCoordinates<Shape>(coordinates, connectivity, e, X);
        mapped = localCoordinates<Shape>(X, x, trial);
      }
      if (mapped && Shape::margin(trial) >= locator.tolerance()) {
        xi[0] = trial[0];
        xi[1] = trial[1];
        found = true;
      }
    }
    if (!found) {
      const int old = e;
      e = locator.locate(x, xi, e);
      element_p(p) = e;
      if (e != old) ++moved;
      if (e < 0) {
        ++outside;
        return e;
      }
      if (affine(e)) affineLocal(e, x, xi);
    }
    local_p(p, 0) = xi[0];
    local_p(p, 1) = xi[1];
    return e;
  }

  /// Point p's record at xi in element e (located by locate()).
  KOKKOS_FORCEINLINE_FUNCTION void writeShape(int p, int e, const Real xi[kDim]) const {
    PointShape& shape = shape_p(p);
    if (e < 0) {
      setLostPointShape(shape);
      return;
    }
    Real N[kNodes];
    Real dNdx[kNodes][kDim];
    if (affine(e)) {  // dN/dx = dN/dxi J^-1, J constant
      const Real inverse[4] = {inverse_e(e, 0), inverse_e(e, 1), inverse_e(e, 2), inverse_e(e, 3)};
      affineShapes<Shape>(xi, inverse, N, dNdx);
    } else {
      Real X[kNodes][kDim];
      gatherElementCoordinates<Shape>(coordinates, connectivity, e, X);
      Shape::values(xi, N);
      physicalGradients<Shape>(X, xi, dNdx);
    }
    setPointShape<Shape>(connectivity, e, N, dNdx, shape);
  }
};

template <class Shape>
RelocationCounts relocate(const Mesh& mesh, const PointLocator& locator,
                          const AffineElementMaps& maps, MaterialPoints& points,
                          PointShapes& shapes) {
  const PointRelocation<Shape> relocation = untracked(
      PointRelocation<Shape>{mesh.coordinates, mesh.connectivity, points.element, points.local,
                             points.position, shapes.stored_p, maps.inverse_jacobian_e,
                             maps.origin_e, maps.affine_e, locator, shapes.fromAffineMaps()});
  const int count = points.count;
  RelocationCounts counts;
  // By chunks of kLanes points, the chunks of the transfers: a chunk found in one affine
  // element (PointShapes::computedChunk) gets no records, 112 bytes a point. A chunk that
  // was in one before is located first and writes its records only if it no longer is; any
  // other chunk writes them as it goes (one pass, as before chunks) and stays a chunk with
  // records until the next relocation, even if its points have come together.
  const PointShapes rule = untracked(shapes);
  const auto computed_c = untracked(shapes.computed_c);
  Kokkos::parallel_reduce(
      "relocate_and_evaluate_shapes",
      Kokkos::RangePolicy<ExecSpace>(0, (count + kLanes - 1) / kLanes),
      KOKKOS_LAMBDA(const int chunk, int& outside, int& moved) {
        const int first = chunk * kLanes;
        bool was_one_element = first + kLanes <= count;
        for (int l = 1; l < kLanes && was_one_element; ++l)
          was_one_element = relocation.element_p(first + l) == relocation.element_p(first);
        if (!was_one_element || !rule.computedChunk(relocation.element_p(first), true)) {
          computed_c(chunk) = 0;
          for (int p = first; p < first + kLanes && p < count; ++p) {
            Real xi[kDim];
            relocation.writeShape(p, relocation.locate(p, outside, moved, xi), xi);
          }
          return;
        }
        int element[kLanes];
        Real xi[kLanes][kDim];
        for (int l = 0; l < kLanes; ++l)
          element[l] = relocation.locate(first + l, outside, moved, xi[l]);
        bool one_element = true;
        for (int l = 1; l < kLanes; ++l) one_element &= element[l] == element[0];
        const bool computed = rule.computedChunk(element[0], one_element);
        computed_c(chunk) = computed;
        if (computed) return;
        for (int l = 0; l < kLanes; ++l) relocation.writeShape(first + l, element[l], xi[l]);
      },
      counts.lost, counts.changed_element);
  return counts;
}

}  // namespace

int evaluateGridShapes(const Mesh& mesh, const MaterialPoints& points, PointShapes& shapes) {
  shapes.prepareGrid(points.count, mesh.structured);
  const StructuredGrid grid = mesh.structured;
  const ShapeFamily family = shapes.family;
  const auto grid_p = shapes.grid_p;
  const auto element_p = points.element;
  const auto position_p = points.position;
  const auto volume0_p = points.initial_volume;
  int changed = 0;
  Kokkos::parallel_reduce(
      "evaluate_grid_shapes", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p, int& count) {
        TensorShape& shape = grid_p(p);
        if (element_p(p) < 0) {
          setLostTensorShape(shape);
          return;
        }
        const int old_x = shape.line[0][0], old_y = shape.line[1][0];
        const Real x[kDim] = {position_p(p, 0), position_p(p, 1)};
        tensorShape(family, grid, x, gimpHalfWidth(volume0_p(p), grid), shape);
        if (shape.line[0][0] != old_x || shape.line[1][0] != old_y) ++count;
      },
      changed);
  return changed;
}

namespace {

/// clearOfGridEdges on every point, moving its position and displacement together.
void keepPointsClearOfGridEdges(const StructuredGrid& grid, MaterialPoints& points) {
  const auto position_p = points.position;
  const auto displacement_p = points.displacement;
  const auto volume0_p = points.initial_volume;
  Kokkos::parallel_for(
      "keep_points_clear_of_grid_edges", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p) {
        const Real l = gimpHalfWidth(volume0_p(p), grid);
        for (int d = 0; d < kDim; ++d) {
          const Real xi = (position_p(p, d) - grid.origin[d]) / grid.spacing[d];
          const Real kept = clearOfGridEdges(xi, grid.cells[d], l);
          if (kept == xi) continue;
          const Real shift = (kept - xi) * grid.spacing[d];
          position_p(p, d) += shift;
          displacement_p(p, d) += shift;
        }
      });
}

}  // namespace

RelocationCounts relocateAndEvaluateShapes(const Mesh& mesh, const PointLocator& locator,
                                           const AffineElementMaps& maps, MaterialPoints& points,
                                           PointShapes& shapes) {
  if (shapes.count() != points.count) shapes.allocate(points.count);
  shapes.type = mesh.type;
  if (shapes.onGrid()) {
    // By index arithmetic where the elements are the grid's cells (the transfers read only
    // the tensor shapes; it keeps the points clear of the grid's edges in the same pass), else
    // by the element route: the element's linear shapes, plus:
    if (maps.cell_element.extent(0) > 0)
      return relocateOnGrid(mesh, locator.tolerance(), maps.cell_element, points, shapes);
    keepPointsClearOfGridEdges(mesh.structured, points);
    RelocationCounts counts = withShape(mesh.type, [&](auto shape) {
      return relocate<decltype(shape)>(mesh, locator, AffineElementMaps{}, points, shapes);
    });
    counts.changed_element += evaluateGridShapes(mesh, points, shapes);
    return counts;
  }
  const bool with_maps = maps.count() == mesh.numElements() && mesh.numElements() > 0;
  shapes.inverse_jacobian_e =
      with_maps ? maps.inverse_jacobian_e : decltype(maps.inverse_jacobian_e){};
  shapes.affine_e = with_maps ? maps.affine_e : decltype(maps.affine_e){};
  shapes.connectivity = with_maps ? mesh.connectivity : decltype(mesh.connectivity){};
  return withShape(mesh.type, [&](auto shape) {
    return relocate<decltype(shape)>(mesh, locator, maps, points, shapes);
  });
}

int relocateAndEvaluateShapes(const Mesh& mesh, const PointLocator& locator, MaterialPoints& points,
                              PointShapes& shapes) {
  return relocateAndEvaluateShapes(mesh, locator, AffineElementMaps{}, points, shapes).lost;
}

void evaluatePointShapes(const Mesh& mesh, const MaterialPoints& points, PointShapes& shapes) {
  evaluatePointShapes(mesh, points, shapes, mesh.shape_functions);
}

void evaluatePointShapes(const Mesh& mesh, const MaterialPoints& points, PointShapes& shapes,
                         ShapeFamily family) {
  if (family != ShapeFamily::Linear && !mesh.structured.valid())
    throw std::logic_error("GIMP and B-spline shape functions need a structured grid");
  const bool family_changed = shapes.family != family;
  shapes.family = family;
  if (shapes.count() != points.count || family_changed) shapes.allocate(points.count);
  shapes.type = mesh.type;
  shapes.inverse_jacobian_e = {};
  shapes.affine_e = {};
  shapes.connectivity = {};
  Kokkos::deep_copy(shapes.computed_c, 0);  // every record stored
  withShape(mesh.type, [&](auto shape) { evaluate<decltype(shape)>(mesh, points, shapes); });
  if (shapes.onGrid()) evaluateGridShapes(mesh, points, shapes);
}

}  // namespace argine

#include "argine/transfer/PointShapes.hpp"

#include "argine/mesh/Mesh.hpp"
#include "argine/mesh/PointLocator.hpp"
#include "argine/mesh/ShapeFunctions.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/AffineElementMaps.hpp"

namespace argine {

void PointShapes::allocate(int n) {
  shape_p = View<PointShape*>("shape_p", n);
}

namespace {

template <class Shape>
void evaluate(const Mesh& mesh, const MaterialPoints& points, PointShapes& shapes) {
  constexpr int kNodes = Shape::kNodes;
  const auto coordinates = mesh.coordinates;
  const auto connectivity = mesh.connectivity;
  const auto element_p = points.element;
  const auto local_p = points.local;
  const auto shape_p = shapes.shape_p;
  Kokkos::parallel_for(
      "evaluate_point_shapes", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p) {
        PointShape& shape = shape_p(p);
        const int e = element_p(p);
        if (e < 0) {
          for (int a = 0; a < kMaxElementNodes; ++a) {
            shape.node[a] = -1;
            shape.value[a] = 0;
            shape.gradient[a][0] = 0;
            shape.gradient[a][1] = 0;
          }
          return;
        }
        Real X[kNodes][kDim];
        gatherElementCoordinates<Shape>(coordinates, connectivity, e, X);
        const Real xi[kDim] = {local_p(p, 0), local_p(p, 1)};
        Real N[kNodes];
        Real dNdx[kNodes][kDim];
        Shape::values(xi, N);
        physicalGradients<Shape>(X, xi, dNdx);
        for (int a = 0; a < kNodes; ++a) {
          shape.node[a] = connectivity(e, a);
          shape.value[a] = N[a];
          shape.gradient[a][0] = dNdx[a][0];
          shape.gradient[a][1] = dNdx[a][1];
        }
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

template <class Shape>
RelocationCounts relocate(const Mesh& mesh, const PointLocator& locator,
                          const AffineElementMaps& maps, MaterialPoints& points,
                          PointShapes& shapes) {
  constexpr int kNodes = Shape::kNodes;
  const auto coordinates = mesh.coordinates;
  const auto connectivity = mesh.connectivity;
  const auto element_p = points.element;
  const auto local_p = points.local;
  const auto position_p = points.position;
  const auto shape_p = shapes.shape_p;
  const auto inverse_e = maps.inverse_jacobian_e;
  const auto origin_e = maps.origin_e;
  const auto affine_e = maps.affine_e;
  const bool with_maps = shapes.fromAffineMaps();  // set from `maps` by the caller
  RelocationCounts counts;
  Kokkos::parallel_reduce(
      "relocate_and_evaluate_shapes", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p, int& outside, int& moved) {
        PointShape& shape = shape_p(p);
        const Real x[kDim] = {position_p(p, 0), position_p(p, 1)};
        // xi = J^-1 (x - x_0) in an affine element, whichever path found the element, so
        // relocating a point twice from one position gives the same shapes bit for bit.
        auto affineLocal = [&](const int element, Real local[kDim]) {
          const Real y0 = x[0] - origin_e(element, 0), y1 = x[1] - origin_e(element, 1);
          local[0] = inverse_e(element, 0) * y0 + inverse_e(element, 1) * y1;
          local[1] = inverse_e(element, 2) * y0 + inverse_e(element, 3) * y1;
        };
        int e = element_p(p);
        Real X[kNodes][kDim];
        bool gathered = false;  // X holds the nodes of element e
        Real xi[kDim] = {local_p(p, 0), local_p(p, 1)};
        bool found = false;
        if (e >= 0) {  // fast path: still strictly inside the same element
          Real trial[kDim];
          bool mapped;
          if (with_maps && affine_e(e)) {
            affineLocal(e, trial);
            mapped = true;
          } else {
            gatherElementCoordinates<Shape>(coordinates, connectivity, e, X);
            gathered = true;
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
          gathered = false;
          if (e < 0) {
            ++outside;
            for (int a = 0; a < kMaxElementNodes; ++a) {
              shape.node[a] = -1;
              shape.value[a] = 0;
              shape.gradient[a][0] = shape.gradient[a][1] = 0;
            }
            return;
          }
          if (with_maps && affine_e(e)) affineLocal(e, xi);
        }
        local_p(p, 0) = xi[0];
        local_p(p, 1) = xi[1];
        Real N[kNodes];
        Real dNdx[kNodes][kDim];
        if (with_maps && affine_e(e)) {  // dN/dx = dN/dxi J^-1, J constant
          const Real inverse[4] = {inverse_e(e, 0), inverse_e(e, 1), inverse_e(e, 2),
                                   inverse_e(e, 3)};
          affineShapes<Shape>(xi, inverse, N, dNdx);
        } else {
          Shape::values(xi, N);
          if (!gathered) gatherElementCoordinates<Shape>(coordinates, connectivity, e, X);
          physicalGradients<Shape>(X, xi, dNdx);
        }
        for (int a = 0; a < kNodes; ++a) {
          shape.node[a] = connectivity(e, a);
          shape.value[a] = N[a];
          shape.gradient[a][0] = dNdx[a][0];
          shape.gradient[a][1] = dNdx[a][1];
        }
      },
      counts.lost, counts.changed_element);
  return counts;
}

}  // namespace

RelocationCounts relocateAndEvaluateShapes(const Mesh& mesh, const PointLocator& locator,
                                           const AffineElementMaps& maps, MaterialPoints& points,
                                           PointShapes& shapes) {
  if (shapes.count() != points.count) shapes.allocate(points.count);
  shapes.type = mesh.type;
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
  if (shapes.count() != points.count) shapes.allocate(points.count);
  shapes.type = mesh.type;
  shapes.inverse_jacobian_e = {};
  shapes.affine_e = {};
  shapes.connectivity = {};
  withShape(mesh.type, [&](auto shape) { evaluate<decltype(shape)>(mesh, points, shapes); });
}

}  // namespace argine

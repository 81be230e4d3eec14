#include "argine/transfer/PointShapes.hpp"

#include "argine/mesh/Mesh.hpp"
#include "argine/mesh/PointLocator.hpp"
#include "argine/mesh/ShapeFunctions.hpp"
#include "argine/points/MaterialPoints.hpp"

namespace argine {

void PointShapes::allocate(int n) {
  node_p = View<int* [kMaxElementNodes]>("shape_node_p", n);
  value_p = View<Real* [kMaxElementNodes]>("shape_value_p", n);
  gradient_p = View<Real* [kMaxElementNodes][kDim]>("shape_gradient_p", n);
}

namespace {

template <class Shape>
void evaluate(const Mesh& mesh, const MaterialPoints& points, PointShapes& shapes) {
  constexpr int kNodes = Shape::kNodes;
  const auto coordinates = mesh.coordinates;
  const auto connectivity = mesh.connectivity;
  const auto element_p = points.element;
  const auto local_p = points.local;
  const auto node_p = shapes.node_p;
  const auto value_p = shapes.value_p;
  const auto gradient_p = shapes.gradient_p;
  Kokkos::parallel_for(
      "evaluate_point_shapes", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p) {
        const int e = element_p(p);
        if (e < 0) {
          for (int a = 0; a < kMaxElementNodes; ++a) {
            node_p(p, a) = -1;
            value_p(p, a) = 0;
            gradient_p(p, a, 0) = 0;
            gradient_p(p, a, 1) = 0;
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
          node_p(p, a) = connectivity(e, a);
          value_p(p, a) = N[a];
          gradient_p(p, a, 0) = dNdx[a][0];
          gradient_p(p, a, 1) = dNdx[a][1];
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
int relocate(const Mesh& mesh, const PointLocator& locator, MaterialPoints& points,
             PointShapes& shapes) {
  constexpr int kNodes = Shape::kNodes;
  const auto coordinates = mesh.coordinates;
  const auto connectivity = mesh.connectivity;
  const auto element_p = points.element;
  const auto local_p = points.local;
  const auto position_p = points.position;
  const auto node_p = shapes.node_p;
  const auto value_p = shapes.value_p;
  const auto gradient_p = shapes.gradient_p;
  int lost = 0;
  Kokkos::parallel_reduce(
      "relocate_and_evaluate_shapes", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p, int& outside) {
        const Real x[kDim] = {position_p(p, 0), position_p(p, 1)};
        int e = element_p(p);
        Real X[kNodes][kDim];
        Real xi[kDim] = {local_p(p, 0), local_p(p, 1)};
        bool found = false;
        if (e >= 0) {  // fast path: still strictly inside the same element
          gatherElementCoordinates<Shape>(coordinates, connectivity, e, X);
          Real trial[kDim];
          if (localCoordinates<Shape>(X, x, trial) && Shape::margin(trial) >= locator.tolerance()) {
            xi[0] = trial[0];
            xi[1] = trial[1];
            found = true;
          }
        }
        if (!found) {
          e = locator.locate(x, xi, e);
          element_p(p) = e;
          if (e < 0) {
            ++outside;
            for (int a = 0; a < kMaxElementNodes; ++a) {
              node_p(p, a) = -1;
              value_p(p, a) = 0;
              gradient_p(p, a, 0) = gradient_p(p, a, 1) = 0;
            }
            return;
          }
          gatherElementCoordinates<Shape>(coordinates, connectivity, e, X);
        }
        local_p(p, 0) = xi[0];
        local_p(p, 1) = xi[1];
        Real N[kNodes];
        Real dNdx[kNodes][kDim];
        Shape::values(xi, N);
        physicalGradients<Shape>(X, xi, dNdx);
        for (int a = 0; a < kNodes; ++a) {
          node_p(p, a) = connectivity(e, a);
          value_p(p, a) = N[a];
          gradient_p(p, a, 0) = dNdx[a][0];
          gradient_p(p, a, 1) = dNdx[a][1];
        }
      },
      lost);
  return lost;
}

}  // namespace

int relocateAndEvaluateShapes(const Mesh& mesh, const PointLocator& locator, MaterialPoints& points,
                              PointShapes& shapes) {
  if (shapes.count() != points.count) shapes.allocate(points.count);
  shapes.type = mesh.type;
  return withShape(mesh.type, [&](auto shape) {
    return relocate<decltype(shape)>(mesh, locator, points, shapes);
  });
}

void evaluatePointShapes(const Mesh& mesh, const MaterialPoints& points, PointShapes& shapes) {
  if (shapes.count() != points.count) shapes.allocate(points.count);
  shapes.type = mesh.type;
  withShape(mesh.type, [&](auto shape) { evaluate<decltype(shape)>(mesh, points, shapes); });
}

}  // namespace argine

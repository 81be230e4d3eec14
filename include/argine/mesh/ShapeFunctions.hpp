#pragma once
/// @file ShapeFunctions.hpp
/// Linear shape functions of the background elements (Tri3, Quad4) and the maps between
/// reference and physical coordinates. This is the single source of shape functions of
/// argine: point location, seeding, P2G/G2P and the implicit assembly all call these.
/// Everything is KOKKOS_INLINE_FUNCTION and works on small fixed-size arrays, so it can be
/// called inside kernels. Element node coordinates are passed as X[a][i] (node a, axis i),
/// nodes counter-clockwise.

#include "argine/core/Lanes.hpp"
#include "argine/core/Types.hpp"
#include "argine/mesh/Mesh.hpp"

namespace argine {

/// 3-node linear triangle on the reference triangle (0,0), (1,0), (0,1).
/// N0 = 1 - xi - eta, N1 = xi, N2 = eta.
struct Tri3 {
  static constexpr int kNodes = 3;                         ///< nodes (= sides)
  static constexpr Real kReferenceArea = 0.5;              ///< area of the reference cell
  static constexpr bool kAffine = true;                    ///< constant Jacobian
  static constexpr ElementType kType = ElementType::Tri3;  ///< runtime tag

  /// Shape function values N[a] at xi, of one point (T = Real) or of kLanes (T = Lanes).
  template <class T>
  static KOKKOS_INLINE_FUNCTION void values(const T xi[kDim], T N[kNodes]) {
    N[0] = 1.0 - xi[0] - xi[1];
    N[1] = xi[0];
    N[2] = xi[1];
  }

  /// Local gradients dN[a][j] = dN_a / dxi_j (constant for Tri3).
  template <class T>
  static KOKKOS_INLINE_FUNCTION void localGradients(const T /*xi*/[kDim], T dN[kNodes][kDim]) {
    dN[0][0] = splat<T>(-1.0);
    dN[0][1] = splat<T>(-1.0);
    dN[1][0] = splat<T>(1.0);
    dN[1][1] = splat<T>(0.0);
    dN[2][0] = splat<T>(0.0);
    dN[2][1] = splat<T>(1.0);
  }

  /// Smallest signed distance (in local coordinates) from xi to the reference boundary:
  /// positive inside, zero on an edge, negative outside.
  static KOKKOS_INLINE_FUNCTION Real margin(const Real xi[kDim]) {
    const Real third = 1.0 - xi[0] - xi[1];
    const Real low = xi[0] < xi[1] ? xi[0] : xi[1];
    return low < third ? low : third;
  }

  /// True if xi lies in the reference triangle enlarged by `tolerance` (local units).
  /// A NaN xi is never inside.
  static KOKKOS_INLINE_FUNCTION bool inside(const Real xi[kDim], Real tolerance) {
    return xi[0] >= -tolerance && xi[1] >= -tolerance && xi[0] + xi[1] <= 1.0 + tolerance;
  }

  /// Local coordinates of the centroid (1/3, 1/3).
  static KOKKOS_INLINE_FUNCTION void centroid(Real xi[kDim]) {
    xi[0] = 1.0 / 3.0;
    xi[1] = 1.0 / 3.0;
  }

  /// Local coordinates of node a.
  static KOKKOS_INLINE_FUNCTION void node(int a, Real xi[kDim]) {
    xi[0] = a == 1 ? 1.0 : 0.0;
    xi[1] = a == 2 ? 1.0 : 0.0;
  }
};

/// 4-node bilinear quadrilateral on the reference square [-1,1]^2, nodes counter-clockwise
/// from (-1,-1): N_a = (1 + xi xi_a)(1 + eta eta_a) / 4.
struct Quad4 {
  static constexpr int kNodes = 4;                          ///< nodes (= sides)
  static constexpr Real kReferenceArea = 4.0;               ///< area of the reference cell
  static constexpr bool kAffine = false;                    ///< Jacobian varies in general
  static constexpr ElementType kType = ElementType::Quad4;  ///< runtime tag

  /// Local coordinates of node a: (-1,-1), (1,-1), (1,1), (-1,1).
  static KOKKOS_INLINE_FUNCTION void node(int a, Real xi[kDim]) {
    xi[0] = (a == 1 || a == 2) ? 1.0 : -1.0;
    xi[1] = (a >= 2) ? 1.0 : -1.0;
  }

  /// Shape function values N[a] at xi, of one point (T = Real) or of kLanes (T = Lanes).
  template <class T>
  static KOKKOS_INLINE_FUNCTION void values(const T xi[kDim], T N[kNodes]) {
    const T xm = 1.0 - xi[0], xp = 1.0 + xi[0];
    const T ym = 1.0 - xi[1], yp = 1.0 + xi[1];
    N[0] = 0.25 * xm * ym;
    N[1] = 0.25 * xp * ym;
    N[2] = 0.25 * xp * yp;
    N[3] = 0.25 * xm * yp;
  }

  /// Local gradients dN[a][j] = dN_a / dxi_j.
  template <class T>
  static KOKKOS_INLINE_FUNCTION void localGradients(const T xi[kDim], T dN[kNodes][kDim]) {
    const T xm = 1.0 - xi[0], xp = 1.0 + xi[0];
    const T ym = 1.0 - xi[1], yp = 1.0 + xi[1];
    dN[0][0] = -0.25 * ym;
    dN[0][1] = -0.25 * xm;
    dN[1][0] = 0.25 * ym;
    dN[1][1] = -0.25 * xp;
    dN[2][0] = 0.25 * yp;
    dN[2][1] = 0.25 * xp;
    dN[3][0] = -0.25 * yp;
    dN[3][1] = 0.25 * xm;
  }

  /// Smallest signed distance (local units) from xi to the reference boundary:
  /// positive inside, zero on an edge, negative outside.
  static KOKKOS_INLINE_FUNCTION Real margin(const Real xi[kDim]) {
    const Real mx = 1.0 - Kokkos::Experimental::fabs(xi[0]);
    const Real my = 1.0 - Kokkos::Experimental::fabs(xi[1]);
    return mx < my ? mx : my;
  }

  /// True if xi lies in [-1-tolerance, 1+tolerance]^2. A NaN xi is never inside.
  static KOKKOS_INLINE_FUNCTION bool inside(const Real xi[kDim], Real tolerance) {
    const Real limit = 1.0 + tolerance;
    return xi[0] >= -limit && xi[0] <= limit && xi[1] >= -limit && xi[1] <= limit;
  }

  /// Local coordinates of the centroid of the reference square (0, 0).
  static KOKKOS_INLINE_FUNCTION void centroid(Real xi[kDim]) {
    xi[0] = 0.0;
    xi[1] = 0.0;
  }
};

/// Copy the node coordinates of `element` into X[a][i].
template <class Shape, class CoordinateView, class ConnectivityView>
KOKKOS_INLINE_FUNCTION void gatherElementCoordinates(const CoordinateView& coordinates,
                                                     const ConnectivityView& connectivity,
                                                     int element, Real X[][kDim]) {
  for (int a = 0; a < Shape::kNodes; ++a) {
    const int n = connectivity(element, a);
    for (int i = 0; i < kDim; ++i) X[a][i] = coordinates(n, i);
  }
}

/// Jacobian J[i][j] = dx_i / dxi_j at xi; returns det J.
template <class Shape>
KOKKOS_INLINE_FUNCTION Real jacobian(const Real X[][kDim], const Real xi[kDim],
                                     Real J[kDim][kDim]) {
  Real dN[Shape::kNodes][kDim];
  Shape::localGradients(xi, dN);
  for (int i = 0; i < kDim; ++i)
    for (int j = 0; j < kDim; ++j) {
      J[i][j] = 0.0;
      for (int a = 0; a < Shape::kNodes; ++a) J[i][j] += X[a][i] * dN[a][j];
    }
  return J[0][0] * J[1][1] - J[0][1] * J[1][0];
}

/// Physical gradients dNdx[a][i] = dN_a / dx_i at xi; returns det J (the caller decides
/// what a non-positive determinant means; the gradients are then not finite).
template <class Shape>
KOKKOS_INLINE_FUNCTION Real physicalGradients(const Real X[][kDim], const Real xi[kDim],
                                              Real dNdx[][kDim]) {
  Real dN[Shape::kNodes][kDim];
  Shape::localGradients(xi, dN);
  Real J[kDim][kDim];
  for (int i = 0; i < kDim; ++i)
    for (int j = 0; j < kDim; ++j) {
      J[i][j] = 0.0;
      for (int a = 0; a < Shape::kNodes; ++a) J[i][j] += X[a][i] * dN[a][j];
    }
  const Real det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
  const Real inv = 1.0 / det;
  // dN/dx_i = sum_j dN/dxi_j (J^-1)_ji, with J^-1 = [[J11, -J01], [-J10, J00]] / det.
  const Real Jinv[kDim][kDim] = {{J[1][1] * inv, -J[0][1] * inv}, {-J[1][0] * inv, J[0][0] * inv}};
  for (int a = 0; a < Shape::kNodes; ++a)
    for (int i = 0; i < kDim; ++i) dNdx[a][i] = dN[a][0] * Jinv[0][i] + dN[a][1] * Jinv[1][i];
  return det;
}

/// Physical position x = sum_a N_a(xi) X_a.
template <class Shape>
KOKKOS_INLINE_FUNCTION void mapToPhysical(const Real X[][kDim], const Real xi[kDim], Real x[kDim]) {
  Real N[Shape::kNodes];
  Shape::values(xi, N);
  for (int i = 0; i < kDim; ++i) {
    x[i] = 0.0;
    for (int a = 0; a < Shape::kNodes; ++a) x[i] += N[a] * X[a][i];
  }
}

/// Local coordinates xi of the physical point x (which may lie outside the element).
/// Works relative to node 0 so that large absolute coordinates (e.g. UTM) lose no accuracy.
/// Tri3: closed form. Quad4: Newton iteration started from the centre; its first step is
/// the parallelogram (affine) approximation, so distorted quads converge in a few steps.
/// Returns false when the map cannot be inverted (degenerate element, Newton diverging
/// or not converging, which happens only for points far outside a distorted quad).
template <class Shape>
KOKKOS_INLINE_FUNCTION bool mapToLocal(const Real X[][kDim], const Real x[kDim], Real xi[kDim]) {
  Real Y[Shape::kNodes][kDim];  // nodes relative to node 0
  for (int a = 0; a < Shape::kNodes; ++a)
    for (int i = 0; i < kDim; ++i) Y[a][i] = X[a][i] - X[0][i];
  const Real y[kDim] = {x[0] - X[0][0], x[1] - X[0][1]};

  if constexpr (Shape::kAffine) {
    // y = J xi with J = [Y1 Y2] (columns); xi = J^-1 y by Cramer's rule.
    const Real det = Y[1][0] * Y[2][1] - Y[2][0] * Y[1][1];
    if (!(det != 0.0)) return false;
    xi[0] = (y[0] * Y[2][1] - Y[2][0] * y[1]) / det;
    xi[1] = (Y[1][0] * y[1] - y[0] * Y[1][1]) / det;
    return true;
  } else {
    constexpr int kMaxIterations = 30;
    constexpr Real kStepTolerance = 1e-13;  // local units; quadratic convergence reaches it
    constexpr Real kDivergence = 1e3;       // |xi| beyond this: far outside, give up
    xi[0] = 0.0;
    xi[1] = 0.0;
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
      Real r[kDim];
      mapToPhysical<Shape>(Y, xi, r);
      r[0] = y[0] - r[0];
      r[1] = y[1] - r[1];
      Real J[kDim][kDim];
      const Real det = jacobian<Shape>(Y, xi, J);
      if (!(det != 0.0)) return false;
      const Real d0 = (r[0] * J[1][1] - J[0][1] * r[1]) / det;
      const Real d1 = (J[0][0] * r[1] - r[0] * J[1][0]) / det;
      xi[0] += d0;
      xi[1] += d1;
      if (!(Kokkos::Experimental::fabs(xi[0]) < kDivergence &&
            Kokkos::Experimental::fabs(xi[1]) < kDivergence))
        return false;
      if (Kokkos::Experimental::fabs(d0) < kStepTolerance &&
          Kokkos::Experimental::fabs(d1) < kStepTolerance)
        return true;
    }
    return false;
  }
}

/// Signed area of the element (positive for counter-clockwise nodes), by the shoelace
/// formula over its straight sides; exact for Tri3 and Quad4.
template <class Shape>
KOKKOS_INLINE_FUNCTION Real elementArea(const Real X[][kDim]) {
  Real twice = 0.0;
  for (int a = 0; a < Shape::kNodes; ++a) {
    const int b = (a + 1) % Shape::kNodes;
    // Relative to node 0: avoids cancellation for large absolute coordinates.
    twice += (X[a][0] - X[0][0]) * (X[b][1] - X[0][1]) - (X[b][0] - X[0][0]) * (X[a][1] - X[0][1]);
  }
  return 0.5 * twice;
}

/// Calls f(Tri3{}) or f(Quad4{}) according to `type`: the runtime -> compile-time switch,
/// taken once on the host, outside kernels, e.g.
///   withShape(mesh.type, [&](auto shape) { return runKernel<decltype(shape)>(...); });
/// Launch kernels from a named function template as above: nvcc rejects a KOKKOS_LAMBDA
/// written directly inside a generic lambda.
template <class Function>
decltype(auto) withShape(ElementType type, Function&& f) {
  if (type == ElementType::Tri3) return f(Tri3{});
  return f(Quad4{});
}

}  // namespace argine

#pragma once
/// @file GridShapes.hpp
/// Shape functions on a StructuredGrid that reach beyond the point's cell: uGIMP and
/// quadratic B-splines, each the tensor product of two 1D functions of the point's position
/// in cells, xi = (x - origin) / h. A point touches at most 3 grid lines per axis (9 nodes).
/// The single source of these functions: the transfers, the active nodes and the tests call
/// them. KOKKOS_INLINE_FUNCTION throughout, for kernels.
///
/// At the edges of the grid a node that would lie outside it (a "ghost") is folded into its
/// two inner neighbours as if its value were extrapolated linearly, v_ghost = 2 v_edge -
/// v_next: N_edge += 2 N_ghost, N_next -= N_ghost. The functions keep the partition of unity
/// and reproduce linear fields (so APIC's D_p and the momenta stay exact), and the B-spline
/// becomes the linear hat in the outer half cell: it interpolates at the edge node, where a
/// fixed node then fixes the material (Steffen et al. 2008 modify the cubic spline in the same
/// spirit).

#include "argine/core/Lanes.hpp"
#include "argine/core/Types.hpp"
#include "argine/mesh/Mesh.hpp"

namespace argine {

/// Grid lines (nodes) a point's shape functions touch along one axis.
inline constexpr int kGridStencil = 3;
/// Nodes of a point's 2D stencil.
inline constexpr int kGridStencilNodes = kGridStencil * kGridStencil;

/// Quadratic B-spline of a node at distance r (cells) from the point: value and dB/dr.
///   |r| <= 1/2: 3/4 - r^2;   1/2 < |r| < 3/2: (3/2 - |r|)^2 / 2;   else 0.
KOKKOS_INLINE_FUNCTION void quadraticBSpline(Real r, Real& value, Real& slope) {
  const Real a = r < 0 ? -r : r;
  const Real sign = r < 0 ? -1 : 1;
  if (a <= 0.5) {
    value = 0.75 - r * r;
    slope = -2 * r;
  } else if (a < 1.5) {
    const Real b = 1.5 - a;
    value = 0.5 * b * b;
    slope = -sign * b;
  } else {
    value = 0;
    slope = 0;
  }
}

/// uGIMP (Bardenhagen & Kober 2004, Eq. 37): the linear hat averaged over the point's domain
/// of half-width l (cells, 0 < l <= 1/2), at distance r (cells): value and dS/dr.
///   |r| < l: 1 - (r^2 + l^2) / (2 l);  l <= |r| <= 1 - l: 1 - |r|;
///   1 - l < |r| < 1 + l: (1 + l - |r|)^2 / (4 l);  else 0.
KOKKOS_INLINE_FUNCTION void gimp(Real r, Real l, Real& value, Real& slope) {
  const Real a = r < 0 ? -r : r;
  const Real sign = r < 0 ? -1 : 1;
  if (a < l) {
    value = 1 - (r * r + l * l) / (2 * l);
    slope = -r / l;
  } else if (a <= 1 - l) {
    value = 1 - a;
    slope = -sign;
  } else if (a < 1 + l) {
    const Real b = 1 + l - a;
    value = b * b / (4 * l);
    slope = -sign * b / (2 * l);
  } else {
    value = 0;
    slope = 0;
  }
}

/// quadraticBSpline of the four distances in r at once, with selects instead of branches:
/// the same formulas in the same order, so every lane has the scalar function's bits. A
/// point's three slots change piece where it crosses a half cell, which the branch
/// predictor cannot foresee; the selects cost a few vector instructions.
KOKKOS_INLINE_FUNCTION void quadraticBSplineLanes(Lanes r, Lanes& value, Lanes& slope) {
  const LaneMask negative = r < 0;
  const Lanes a = select(negative, -r, r);
  const Lanes sign = select(negative, splat<Lanes>(-1), splat<Lanes>(1));
  const Lanes b = 1.5 - a;
  const LaneMask centre = a <= 0.5, reached = a < 1.5;
  value = select(centre, 0.75 - r * r, select(reached, 0.5 * b * b, Lanes{}));
  slope = select(centre, -2 * r, select(reached, -sign * b, Lanes{}));
}

/// gimp of the four distances in r at once (half-width l), with selects instead of branches:
/// the same formulas in the same order, so every lane has the scalar function's bits. The
/// pieces' two quotients share one division each for the value and the slope (the piece
/// picks numerator and denominator), the linear piece and the zero outside take none. With
/// 2 x 2 points per cell (l = 1/4) the points sit where the pieces meet (|r| = l, 1 - l), so
/// the scalar function's branches went either way at random.
KOKKOS_INLINE_FUNCTION void gimpLanes(Lanes r, Real l, Lanes& value, Lanes& slope) {
  const LaneMask negative = r < 0;
  const Lanes a = select(negative, -r, r);
  const Lanes sign = select(negative, splat<Lanes>(-1), splat<Lanes>(1));
  const LaneMask inner = a < l, linear = a <= 1 - l, outer = a < 1 + l;
  const Lanes b = (1 + l) - a;
  // inner: (r^2 + l^2) / (2 l) and -r / l; outer: b^2 / (4 l) and -sign b / (2 l)
  const Lanes twice_l = splat<Lanes>(2 * l);
  const Lanes value_quotient =
      select(inner, r * r + l * l, b * b) / select(inner, twice_l, splat<Lanes>(4 * l));
  const Lanes slope_quotient =
      select(inner, -r, -sign * b) / select(inner, splat<Lanes>(l), twice_l);
  value = select(inner, 1 - value_quotient,
                 select(linear, 1 - a, select(outer, value_quotient, Lanes{})));
  slope =
      select(inner, slope_quotient, select(linear, -sign, select(outer, slope_quotient, Lanes{})));
}

/// A point's shape functions along one axis: grid lines (node indices along the axis),
/// values and derivatives (1/m).
struct GridStencil1D {
  int line[kGridStencil];
  Real value[kGridStencil];
  Real gradient[kGridStencil];
};

/// The 1D stencil of a point at xi (cells from the grid origin) on an axis of `cells` cells
/// of size h (m): lines base .. base + 2 with base = floor(xi - 1/2) (every line the B-spline
/// or a uGIMP function of half-width l <= 1/2 reaches), ghosts folded (file comment); a slot
/// whose ghost was folded keeps value and gradient 0 on the edge line.
KOKKOS_INLINE_FUNCTION void gridStencil1D(ShapeFamily family, Real xi, int cells, Real h,
                                          Real half_width, GridStencil1D& s) {
  const int base = static_cast<int>(Kokkos::Experimental::floor(xi - 0.5));
  // the three slots' distances xi - line (lane 3 repeats slot 2 and is not read)
  const Lanes lines = {Real(base), Real(base + 1), Real(base + 2), Real(base + 2)};
  const Lanes r = xi - lines;
  Lanes value, slope;
  if (family == ShapeFamily::BSpline)
    quadraticBSplineLanes(r, value, slope);
  else
    gimpLanes(r, half_width, value, slope);
  const Lanes gradient = slope / h;
  for (int k = 0; k < kGridStencil; ++k) {
    s.line[k] = base + k;
    s.value[k] = value[k];
    s.gradient[k] = gradient[k];
  }
  if (base >= 0 && base + kGridStencil - 1 <= cells) return;  // no ghost (most points)
  for (int k = 0; k < kGridStencil; ++k) {
    const int line = s.line[k];
    if (line >= 0 && line <= cells) continue;
    // ghost: its edge and next lines are in the stencil (base >= -1, base + 2 <= cells + 1)
    const int edge = line < 0 ? 0 : cells;
    const int next = line < 0 ? 1 : cells - 1;
    for (int j = 0; j < kGridStencil; ++j) {
      if (s.line[j] == edge) {
        s.value[j] += 2 * s.value[k];
        s.gradient[j] += 2 * s.gradient[k];
      } else if (s.line[j] == next) {
        s.value[j] -= s.value[k];
        s.gradient[j] -= s.gradient[k];
      }
    }
    s.line[k] = edge;
    s.value[k] = 0;
    s.gradient[k] = 0;
  }
}

/// A point's 2D stencil: the two 1D stencils; node (a, b) = line[0][a] + line[1][b] (cells[0]
/// + 1), N = value[0][a] value[1][b]. 120 bytes, expanded where read (GridShapeRecord).
struct TensorShape {
  int line[kDim][kGridStencil];
  Real value[kDim][kGridStencil];
  Real gradient[kDim][kGridStencil];
};

/// The tensor shape of a point at x (m) on `grid`; `half_width` (cells) for uGIMP.
KOKKOS_INLINE_FUNCTION void tensorShape(ShapeFamily family, const StructuredGrid& grid,
                                        const Real x[kDim], Real half_width, TensorShape& shape) {
  for (int d = 0; d < kDim; ++d) {
    GridStencil1D s;
    const Real xi = (x[d] - grid.origin[d]) / grid.spacing[d];
    gridStencil1D(family, xi, grid.cells[d], grid.spacing[d], half_width, s);
    for (int k = 0; k < kGridStencil; ++k) {
      shape.line[d][k] = s.line[k];
      shape.value[d][k] = s.value[k];
      shape.gradient[d][k] = s.gradient[k];
    }
  }
}

/// The centre of the point's cell on the stencil lines of axis d (cellCentre1D): the slot of
/// the cell's lower line (the upper line is the next slot) and 1/h.
struct CellCentre1D {
  int slot;
  Real inverse_h;
};

/// The cell of the point's centre on axis d: that of xi = sum_k N_k line_k (both families
/// reproduce linear fields, and the fold keeps that), kept within the stencil's lines (a
/// folded ghost slot repeats its neighbour's line and is no line of the cell); its lower
/// line's slot, and 1/h = sum_k dN_k/dx line_k. The stencil's other lines are consecutive
/// from the first unfolded slot, so the cell's lines are two consecutive slots.
KOKKOS_INLINE_FUNCTION CellCentre1D cellCentre1D(const TensorShape& t, int d) {
  Real xi = 0;
  for (int k = 0; k < kGridStencil; ++k) xi += t.value[d][k] * t.line[d][k];
  const int first = t.line[d][0] == t.line[d][1] ? 1 : 0;  // a folded lower ghost
  const int last = t.line[d][2] == t.line[d][1] ? 1 : 2;   // a folded upper ghost
  int cell = static_cast<int>(Kokkos::Experimental::floor(xi));
  if (cell > t.line[d][last] - 1) cell = t.line[d][last] - 1;
  if (cell < t.line[d][first]) cell = t.line[d][first];
  Real inverse_h = 0;
  for (int k = 0; k < kGridStencil; ++k) inverse_h += t.gradient[d][k] * t.line[d][k];
  return {first + (cell - t.line[d][first]), inverse_h};
}

/// The weights of the centre of the point's cell on the stencil lines of axis d: 1/2 on the
/// cell's two lines, 0 on the third. Both families take 1/2, 1/2 at a cell centre (the
/// B-spline's third line is 1.5 cells away; uGIMP is linear there), also in an edge cell,
/// whose ghost line has no weight at its centre (cellCentre1D finds the cell). Used where a
/// value must be one per cell, as the element centre is for linear shapes (the advective flux
/// of 4.16).
KOKKOS_INLINE_FUNCTION void cellCentreWeights1D(const TensorShape& t, int d, Real w[kGridStencil],
                                                Real* slope = nullptr) {
  const CellCentre1D centre = cellCentre1D(t, d);
  // d/dx at the centre: -1/h, +1/h on the cell's lines
  for (int k = 0; k < kGridStencil; ++k) {
    const bool in_cell = k == centre.slot || k == centre.slot + 1;
    w[k] = in_cell ? Real(0.5) : Real(0);
    if (slope)
      slope[k] = !in_cell ? Real(0) : k == centre.slot ? -centre.inverse_h : centre.inverse_h;
  }
}

/// uGIMP half-width (cells) of a point of initial volume V0 on cells of area hx hy: the
/// domain of a point seeded m x m per cell is a cell scaled by 1/m, l = 1/(2m) =
/// sqrt(V0 / (hx hy)) / 2, at most 1/2 (one point per cell).
KOKKOS_INLINE_FUNCTION Real gimpHalfWidth(Real initial_volume, const StructuredGrid& grid) {
  const Real l =
      0.5 * Kokkos::Experimental::sqrt(initial_volume / (grid.spacing[0] * grid.spacing[1]));
  return l < 0.5 ? l : 0.5;
}

/// The coordinate (cells) a point at xi on an axis of `cells` cells keeps, with its domain of
/// half-width l (cells, gimpHalfWidth): xi itself, or l / 2 from an edge of the grid where
/// it came closer. A point may be pressed against a wall at the grid's edge until half its
/// domain lies beyond it (a volumetric strain of 50 % normal to the wall, more than any soil
/// takes), not further: nearer the edge line the folded weight of the next line inwards
/// falls to xi (the linear hat) while its gradient stays 1/h, so a node of vanishing mass
/// gets a finite force and APIC's C_p carries that node's runaway velocity into the point
/// (doc/theory.md Sec. 3.11, "Points at the grid's edge"). A centre outside the grid is
/// left as it is (the point leaves the mesh).
KOKKOS_INLINE_FUNCTION Real clearOfGridEdges(Real xi, int cells, Real half_width) {
  const Real clearance = 0.5 * half_width;
  if (xi >= 0 && xi < clearance) return clearance;
  if (xi <= cells && xi > cells - clearance) return cells - clearance;
  return xi;
}

}  // namespace argine

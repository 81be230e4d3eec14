#pragma once
/// @file GridPointTransfers.hpp
/// The per-point bodies of the explicit step's three transfer kernels on the grid families
/// (GIMP, B-spline; TwoPhaseTransfer.cpp calls them for GridShapeFamily): the P2G sums, the
/// velocity update with the momentum remap, and the strain increments of one point.
///
/// Why not the bodies the element families share (PointShapesAt): those are written node by
/// node and slot by slot, which on a 9-node stencil costs 6-9x the 4-node kernels. Here a
/// node's values are four slots at once (one Lanes, the rows of NodeRecords are packed in
/// blocks of kLanes): a P2G node row is four vector expressions of N, dN/dx and dN/dy, a G2P
/// gather one vector load and three vector sums per node. The stencil's N and dN/dx are
/// expanded once per point and kernel from its TensorShape (GridStencil).
///
/// Same bits as the slot-by-slot bodies: every lane computes the products and sums of its
/// slot in the same order (-ffp-contract=off), and where those bodies add an exact zero to a
/// slot a point has no part in, these add a product with a zero factor (+0 or -0), which
/// leaves every sum as it was (sums start at +0; x + -0 = x).

#include "PointShapesAt.hpp"
#include "argine/core/Lanes.hpp"
#include "argine/materials/KernelMath.hpp"
#include "argine/materials/ObjectiveStressRate.hpp"
#include "argine/mesh/GridShapes.hpp"
#include "argine/physics/BishopStress.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/FlipShare.hpp"
#include "argine/transfer/NodeRecords.hpp"
#include "argine/transfer/PointRates.hpp"
#include "argine/transfer/TransferScheme.hpp"

namespace argine {

/// The kLanes values from `first` (four consecutive slots of a packed row).
KOKKOS_FORCEINLINE_FUNCTION Lanes loadBlock(const Real* first) {
  Lanes out;
  std::memcpy(&out, first, sizeof out);
  return out;
}

/// Writes v to the kLanes values from `first`.
KOKKOS_FORCEINLINE_FUNCTION void storeBlock(Real* first, Lanes v) {
  std::memcpy(first, &v, sizeof v);
}

/// Four ints, one vector register (GCC's vector extension, as Lanes).
using IntLanes = int __attribute__((vector_size(kLanes * sizeof(int))));

/// A point's 3 x 3 stencil expanded for a kernel: node a = ax + 3 ay, its N and dN/dx (the
/// bits of gridValue and gridGradient), and the x of the stencil's columns and the y of its
/// rows (APIC's offsets x_a - x_p: on the grid a node's x depends on its column only).
struct GridStencil {
  /// One more than the nodes: a row of the stencil's nodes is written as four ints.
  int node[kGridStencilNodes + 1];
  /// One more than the nodes: a row of the stencil is written as one Lanes (constructor).
  Real N[kGridStencilNodes + 1], dx[kGridStencilNodes + 1], dy[kGridStencilNodes + 1];

  /// The stencil of a located point, a row of three nodes at a time: the x functions in lanes
  /// 0-2 (lane 3 the first y value, overwritten by the next row or left in the padding) times
  /// the row's y function, three vector products a row where the compiler's own vectorising of
  /// the 27 scalar products costs more in shuffles than the products.
  KOKKOS_FORCEINLINE_FUNCTION GridStencil(const TensorShape& t, int row) {
    static_assert(sizeof(t.value[0]) == kGridStencil * sizeof(Real) && kGridStencil + 1 == kLanes,
                  "a row of x values and the first y value are one Lanes");
    static_assert(sizeof(t.line[0]) == kGridStencil * sizeof(int), "rows of lines as values");
    const Lanes wx = loadBlock(&t.value[0][0]), gx = loadBlock(&t.gradient[0][0]);
    // the x lines in lanes 0-2 (lane 3 the first y line: padding, as for the values); read
    // once, so that the stores to node[] need not reload them
    IntLanes lines_x;
    std::memcpy(&lines_x, &t.line[0][0], sizeof lines_x);
    int row_start[kGridStencil];
    for (int ay = 0; ay < kGridStencil; ++ay) row_start[ay] = t.line[1][ay] * row;
    for (int ay = 0; ay < kGridStencil; ++ay) {
      const Real wy = t.value[1][ay], gy = t.gradient[1][ay];
      storeBlock(&N[kGridStencil * ay], wx * wy);
      storeBlock(&dx[kGridStencil * ay], gx * wy);
      storeBlock(&dy[kGridStencil * ay], wx * gy);
      const IntLanes nodes = lines_x + row_start[ay];
      std::memcpy(&node[kGridStencil * ay], &nodes, sizeof nodes);
    }
  }
};

/// x_a - x_p of the stencil's columns (x) and y of its rows (y), from the node coordinates
/// (APIC): the values nodeOffset gives each node of a grid whose columns are straight.
struct GridOffsets {
  Real x[kGridStencil], y[kGridStencil];

  KOKKOS_INLINE_FUNCTION GridOffsets() : x{}, y{} {}
  template <class Coordinates>
  KOKKOS_INLINE_FUNCTION GridOffsets(const TensorShape& t, int row,
                                     const Coordinates& coordinates_i, Real xp, Real yp) {
    for (int k = 0; k < kGridStencil; ++k) {
      x[k] = coordinates_i(t.line[0][k] + t.line[1][0] * row, 0) - xp;
      y[k] = coordinates_i(t.line[0][0] + t.line[1][k] * row, 1) - yp;
    }
  }
};

/// x in every lane, one broadcast: splat<Lanes> adds x to +0 for the lanes' bits of the scalar
/// formulas (-0 becomes +0), an instruction more. Here the value only multiplies into terms
/// that are summed, and a product of -0 instead of +0 adds -0 instead of +0 to a sum, which
/// leaves it as it was (sums start at +0).
KOKKOS_FORCEINLINE_FUNCTION Lanes broadcast(Real x) {
  return Lanes{x, x, x, x};
}

/// (a, b, c, d) as one Lanes.
KOKKOS_FORCEINLINE_FUNCTION Lanes lanesOf(Real a, Real b, Real c, Real d) {
  return Lanes{a, b, c, d};
}

/// What point p, located, `wet` or dry, adds to its nodes (mapPointToGrid's sums, 4.40-4.47)
/// in blocks of the packed row: 0 the masses and drag, 1 the momenta (APIC: with C_p (x_a -
/// x_p), kAffine), 2 the liquid volume, the mixture force and x of the liquid force, 3 y of
/// the liquid force.
template <bool kAffine, class Views, class Sums>
KOKKOS_INLINE_FUNCTION void mapGridPointToGrid(const TensorShape& t, int row, bool wet,
                                               Real gravity, const Views& v, const Sums& sums,
                                               int p) {
  const GridStencil s(t, row);
  const Real volume = v.volume_p(p);
  const Real m_solid = v.mass_solid_p(p);
  const Real m_liquid = wet ? v.mass_liquid_p(p) : 0;
  const Real bishop = wet ? bishopPorePressure(v.saturation_p(p), v.pressure_p(p)) : 0;
  // the stress row (XX, YY, ZZ, XY) less chi p_L on the diagonal, one load and one
  // subtraction (XY - +0 is XY to the bit): (sxx, syy, -, sxy)
  static_assert(XX == 0 && YY == 1 && XY == 3 && kStressComponents == kLanes,
                "a point's stress is one Lanes (LayoutRight row)");
  // `Conjugate Mean Stress`: the element's mean stress and p_L instead of the point's
  const Real mean_shift = v.shifted ? v.mean_shift_p(p, 0) : 0;
  const Real pressure_shift = v.shifted ? v.mean_shift_p(p, 1) : 0;
  const Real diagonal = bishop - mean_shift;
  const Lanes stress = loadBlock(&v.stress_p(p, 0)) - lanesOf(diagonal, diagonal, 0, 0);
  const Real weight_mixture = -(m_solid + m_liquid) * gravity;  // 4.42
  // liquid (4.41, 4.43, 4.45, 4.46): zero factors for a dry point
  Real m_intrinsic = 0, drag = 0, pressure_volume = 0, weight_liquid = 0, liquid_volume = 0;
  Real vl[kDim] = {0, 0};
  if (wet) {
    const Real rho = v.density_liquid_p(p);
    m_intrinsic = rho * volume;
    drag =
        v.porosity_p(p) * v.saturation_p(p) * rho * kStandardGravity / v.conductivity_p(p) * volume;
    pressure_volume = (v.pressure_p(p) + pressure_shift) * volume;
    weight_liquid = -m_intrinsic * gravity;
    liquid_volume = volume;
    vl[0] = v.velocity_liquid_p(p, 0);
    vl[1] = v.velocity_liquid_p(p, 1);
  }
  // APIC: C_S and C_L (C_00, C_01, C_10, C_11 each, a dry point's C_L zero) turned into
  // C_d0 and C_d1 of each velocity by two shuffles of the rows (the compiler had moved the
  // eight components through the stack)
  static_assert(kAffineComponents == kLanes, "a point's C_p is one Lanes (LayoutRight row)");
  Lanes affine_x = {}, affine_y = {};
  if constexpr (kAffine) {
    const Lanes solid = loadBlock(&v.affine_solid_p(p, 0));
    const Lanes liquid = wet ? loadBlock(&v.affine_liquid_p(p, 0)) : Lanes{};
    affine_x = __builtin_shufflevector(solid, liquid, 0, 2, 4, 6);
    affine_y = __builtin_shufflevector(solid, liquid, 1, 3, 5, 7);
  }
  // per block: its slots as factors of N, dN/dx and dN/dy
  const Lanes masses = lanesOf(m_solid, m_liquid, m_intrinsic, drag);
  const Lanes momentum_mass = lanesOf(m_solid, m_solid, m_intrinsic, m_intrinsic);
  const Lanes velocity = lanesOf(v.velocity_solid_p(p, 0), v.velocity_solid_p(p, 1), vl[0], vl[1]);
  // block 2: -(s dN)_d V for the mixture, dN/dx p_L V for the liquid, N V and N W
  const Lanes liquid_force = lanesOf(0, pressure_volume, 0, 0);
  const Lanes force_x = __builtin_shufflevector(stress, liquid_force, 4, 0, 3, 5);  // 0 sxx sxy pV
  const Lanes force_y = __builtin_shufflevector(stress, liquid_force, 4, 3, 1, 6);  // 0 sxy syy 0
  const Lanes force_scale = lanesOf(0, -volume, -volume, 1);
  const Lanes force_n = lanesOf(liquid_volume, 0, weight_mixture, 0);
  // block 3: dN/dy p_L V + N W_L
  const Lanes liquid_y = lanesOf(pressure_volume, 0, 0, 0);
  const Lanes liquid_n = lanesOf(weight_liquid, 0, 0, 0);
  Real xp = 0, yp = 0;
  if constexpr (kAffine) {
    xp = v.position_p(p, 0);
    yp = v.position_p(p, 1);
  }
  const GridOffsets offset = kAffine ? GridOffsets(t, row, v.coordinates_i, xp, yp) : GridOffsets{};
  // v + C (x_a - x_p) as affineVelocity sums it, (v + C_.0 dx) + C_.1 dy: the columns' part
  Lanes column_velocity[kGridStencil];
  for (int ax = 0; ax < kGridStencil; ++ax)
    column_velocity[ax] = kAffine ? velocity + affine_x * offset.x[ax] : velocity;
  for (int ay = 0; ay < kGridStencil; ++ay) {
    const Lanes row_part = affine_y * offset.y[ay];
    for (int ax = 0; ax < kGridStencil; ++ax) {
      const int a = ax + kGridStencil * ay;
      const Lanes N = broadcast(s.N[a]), dx = broadcast(s.dx[a]), dy = broadcast(s.dy[a]);
      const Lanes va = kAffine ? column_velocity[ax] + row_part : velocity;
      const Lanes blocks[4] = {N * masses, N * momentum_mass * va,
                               (dx * force_x + dy * force_y) * force_scale + N * force_n,
                               dy * liquid_y + N * liquid_n};
      sums.addBlocks(s.node[a], blocks, 0, wet);
    }
  }
}

/// The velocity update of point p, located, `wet` or dry (updatePointVelocityAt's formulas
/// for each TransferScheme), and its momenta added to its nodes (block 1 of the row).
template <TransferScheme kScheme, class Views, class Values, class Sums>
KOKKOS_INLINE_FUNCTION void updateGridPointVelocity(const TensorShape& t, int row, bool wet,
                                                    Real dt, Real pic_solid, Real pic_liquid,
                                                    const Values& values_i, const Views& v,
                                                    const Sums& sums, int p, Real& ks, Real& kl,
                                                    int& bad) {
  constexpr bool kAffine = kScheme == TransferScheme::Apic;    // the remap carries C_p
  constexpr bool kFromGrid = kScheme != TransferScheme::Flip;  // v_p = sum N v~_i
  static_assert(kReadVelocitySolid == kLanes && kReadVelocityLiquid == kLanes + kDim,
                "v_S and v_L fill block 1 of a read row, a_S and a_L block 0");
  const GridStencil s(t, row);
  // sum N v~_i (block 1: v_S, v_L of the grid) and, APIC, sum v~_i dN/dx, sum v~_i dN/dy;
  // FLIP: sum N a_i (block 0), and sum N v_i where a PIC blend asks for it
  Lanes grid_velocity = {}, gradient_x = {}, gradient_y = {}, acceleration = {};
  const bool blend = pic_solid > 0 || (wet && pic_liquid > 0);
  for (int a = 0; a < kGridStencilNodes; ++a) {
    const Real* values = &values_i(s.node[a], 0);
    const Lanes N = broadcast(s.N[a]);
    if constexpr (kFromGrid) {
      const Lanes vi = loadBlock(values + kReadVelocitySolid);
      grid_velocity += N * vi;
      if constexpr (kAffine) {
        gradient_x += vi * s.dx[a];
        gradient_y += vi * s.dy[a];
      }
    } else {
      acceleration += N * loadBlock(values + kReadAccelerationSolid);
    }
  }
  if constexpr (!kFromGrid)
    if (blend)
      for (int a = 0; a < kGridStencilNodes; ++a)
        grid_velocity += broadcast(s.N[a]) * loadBlock(&values_i(s.node[a], kReadVelocitySolid));
  Real v_solid[kDim];
  if constexpr (kFromGrid) {
    v_solid[0] = grid_velocity[0];
    v_solid[1] = grid_velocity[1];
    if constexpr (kAffine)
      if (pic_solid < 1 || (wet && pic_liquid < 1)) {
        // a FLIP share (VelocityBlend): v_APIC + (1 - alpha) (v_p + dt sum N a_i - v_APIC),
        // the accelerations of both phases (block 0)
        for (int a = 0; a < kGridStencilNodes; ++a)
          acceleration +=
              broadcast(s.N[a]) * loadBlock(&values_i(s.node[a], kReadAccelerationSolid));
        Real flip[kDim];
        loadComponents(v.velocity_solid_p, p, flip);
        for (int d = 0; d < kDim; ++d)
          v_solid[d] = withFlipShare(v_solid[d], flip[d] + dt * acceleration[d], pic_solid);
      }
  } else {
    // FLIP v_p + dt sum N a_i, blended: + alpha (sum N v_i - v_p) (TwoPhaseTransfer.hpp)
    loadComponents(v.velocity_solid_p, p, v_solid);
    for (int d = 0; d < kDim; ++d)
      v_solid[d] = v_solid[d] + dt * acceleration[d] + pic_solid * (grid_velocity[d] - v_solid[d]);
  }
  if constexpr (kAffine) {
    const Real cs[kAffineComponents] = {gradient_x[0], gradient_y[0], gradient_x[1], gradient_y[1]};
    storeComponents(v.affine_solid_p, p, cs);
  }
  storeComponents(v.velocity_solid_p, p, v_solid);
  const Real vsx = v_solid[0], vsy = v_solid[1];
  const Real ms = v.mass_solid_p(p);
  ks += 0.5 * ms * (vsx * vsx + vsy * vsy);
  if (!(kmath::isFinite(vsx) && kmath::isFinite(vsy))) ++bad;
  Real v_liquid[kDim] = {0, 0}, ml = 0;
  if (wet) {
    if constexpr (kFromGrid) {
      v_liquid[0] = grid_velocity[2];
      v_liquid[1] = grid_velocity[3];
      if constexpr (kAffine) {
        const Real cl[kAffineComponents] = {gradient_x[2], gradient_y[2], gradient_x[3],
                                            gradient_y[3]};
        storeComponents(v.affine_liquid_p, p, cl);
        if (pic_liquid < 1) {  // a FLIP share, as the solid's
          Real flip[kDim];
          loadComponents(v.velocity_liquid_p, p, flip);
          for (int d = 0; d < kDim; ++d)
            v_liquid[d] =
                withFlipShare(v_liquid[d], flip[d] + dt * acceleration[kDim + d], pic_liquid);
        }
      }
    } else {
      // the relative velocity w_p = v_L - v_S relaxes towards the grid's sum N w_i; with
      // pic_liquid = 0 this is FLIP
      loadComponents(v.velocity_liquid_p, p, v_liquid);
      for (int d = 0; d < kDim; ++d) {
        const Real al = acceleration[kDim + d];
        const Real vl = pic_liquid > 0 ? grid_velocity[kDim + d] : 0;
        const Real vs_grid = grid_velocity[d];  // 0 without a blend
        const Real flip = v_liquid[d] + dt * al;
        const Real relative_pic = v_solid[d] + vl - vs_grid + dt * (al - acceleration[d]);
        v_liquid[d] = pic_liquid > 0 ? flip + pic_liquid * (relative_pic - flip) : flip;
      }
    }
    const Real vlx = v_liquid[0], vly = v_liquid[1];
    storeComponents(v.velocity_liquid_p, p, v_liquid);
    kl += 0.5 * v.mass_liquid_p(p) * (vlx * vlx + vly * vly);
    if (!(kmath::isFinite(vlx) && kmath::isFinite(vly))) ++bad;
    ml = v.density_liquid_p(p) * v.volume_p(p);
  }
  // the remap: N m (v + C (x_a - x_p)) (APIC), N m v (FLIP, TPIC); a dry point's liquid
  // lanes have zero factors
  const Lanes momentum_mass = lanesOf(ms, ms, ml, ml);
  const Lanes velocity = lanesOf(v_solid[0], v_solid[1], v_liquid[0], v_liquid[1]);
  if constexpr (kAffine) {
    const Lanes affine_x = wet ? gradient_x : lanesOf(gradient_x[0], gradient_x[1], 0, 0);
    const Lanes affine_y = wet ? gradient_y : lanesOf(gradient_y[0], gradient_y[1], 0, 0);
    const GridOffsets offset(t, row, v.coordinates_i, v.position_p(p, 0), v.position_p(p, 1));
    Lanes column_velocity[kGridStencil];  // as in mapGridPointToGrid
    for (int ax = 0; ax < kGridStencil; ++ax)
      column_velocity[ax] = velocity + affine_x * offset.x[ax];
    for (int ay = 0; ay < kGridStencil; ++ay) {
      const Lanes row_part = affine_y * offset.y[ay];
      for (int ax = 0; ax < kGridStencil; ++ax) {
        const int a = ax + kGridStencil * ay;
        const Lanes block[1] = {broadcast(s.N[a]) * momentum_mass *
                                (column_velocity[ax] + row_part)};
        sums.addBlocks(s.node[a], block, 1, wet);
      }
    }
  } else {
    for (int a = 0; a < kGridStencilNodes; ++a) {
      const Lanes block[1] = {broadcast(s.N[a]) * momentum_mass * velocity};
      sums.addBlocks(s.node[a], block, 1, wet);
    }
  }
}

/// div(c w) of 4.12 / 4.16 at the centre of the point's cell (cellCentreWeights1D), c = rho_L n
/// S_L and w = v_L - v_S, one value per cell as linear elements take it at the element
/// centre: at the point, with its own N and grad N, the points of a cell got different flux
/// divergences, and where the storage is tiny (saturated) and the stiffness jumps between
/// neighbours (a wetting front) the difference was stored as a pressure pattern the nodal
/// forces cannot see (V3 on B-splines: p_L 137 % of the range off; doc/theory.md Sec. 3.11).
/// The cell's four corners in the order of the stencil's nodes (the other five have no
/// weight at the centre), each with N = 1/2 1/2 and dN/dx = (-+1/h) 1/2, the products of
/// cellCentreWeights1D's weights: the same bits as the sum over the nine nodes.
///
/// The six sums in two Lanes, each lane one sum and its terms in corner order, as the scalar
/// sums had them (their spills and moves between registers were half the strain kernel):
/// `weighted` (w_x, w_y, c, -) += N (w_x, w_y, c, c) and `sloped` (w . grad N, -, c dN/dx,
/// c dN/dy) += (w_x dN/dx + w_y dN/dy, -, c dN/dx + 0, c dN/dy + 0): the products' vector
/// plus its lane 1 moved to lane 0 (one in-lane swap and a blend with zeros). The + 0 turns a
/// -0 term into +0, which leaves the sum as it was (it starts at +0 and never becomes -0).
template <class Values>
KOKKOS_INLINE_FUNCTION Real cellCentreAdvectiveFlux(const TensorShape& t, const GridStencil& s,
                                                    const Values& values_i) {
  static_assert(kReadStrainVelocitySolid == 0 && kReadStrainVelocityLiquid == kDim &&
                    kReadStrainLiquidContent == kLanes,
                "v_S and v_L fill block 0 of a read row, the liquid content opens block 1");
  const CellCentre1D centre_x = cellCentre1D(t, 0), centre_y = cellCentre1D(t, 1);
  const Real half = 0.5;
  const Real N = half * half;
  // dN/dx of the cell's lower and upper lines, dN/dy of its lower and upper rows
  const Real gx[2] = {-centre_x.inverse_h * half, centre_x.inverse_h * half};
  const Real gy[2] = {half * -centre_y.inverse_h, half * centre_y.inverse_h};
  const Lanes zero = {};
  Lanes weighted = {}, sloped = {};
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 2; ++i) {
      const int a = centre_x.slot + i + kGridStencil * (centre_y.slot + j);
      const Real* values = &values_i(s.node[a], 0);
      const Lanes velocities = loadBlock(values);  // v_S, v_L
      const Lanes w = __builtin_shufflevector(velocities, velocities, 2, 3, 2, 3) - velocities;
      const Lanes content = loadBlock(values + kReadStrainLiquidContent);   // lane 0
      const Lanes terms = __builtin_shufflevector(w, content, 0, 1, 4, 4);  // w_x, w_y, c, c
      weighted += N * terms;
      const Lanes products = terms * lanesOf(gx[i], gy[j], gx[i], gy[j]);
      sloped += products + __builtin_shufflevector(products, zero, 1, 5, 6, 7);
    }
  }
  return weighted[2] * sloped[0] + sloped[2] * weighted[0] + sloped[3] * weighted[1];
}

/// The strain, spin, displacement and liquid increments of point p, located, `wet` or dry
/// (strainIncrementsAt on the grid; the advective flux at the centre of the point's cell);
/// kStoreGradients (TPIC): C_p = grad v of the remapped fields.
template <bool kStoreGradients, class Values, class Views>
KOKKOS_INLINE_FUNCTION void gridStrainIncrements(const TensorShape& t, int row, bool wet, Real dt,
                                                 const Values& values_i, const Views& v,
                                                 const PointRates& rates, int p) {
  static_assert(kReadStrainVelocitySolid == 0 && kReadStrainVelocityLiquid == kDim &&
                    kReadStrainLiquidContent == kLanes,
                "v_S and v_L fill block 0 of a read row, the liquid content opens block 1");
  const GridStencil s(t, row);
  // block 0 (v_S, v_L): sum N v, sum v dN/dx, sum v dN/dy; L_jk = d v_S,j / d x_k
  Lanes velocity = {}, gradient_x = {}, gradient_y = {};
  // wet: the divergence sum (v_L . grad N) node by node (lane 2: v_L,x dN/dx + v_L,y dN/dy)
  Lanes divergences = {};
  const auto gather = [&](auto with_liquid) {
  // One row of the stencil an iteration: unrolled in full, the compiler computes all nine
  // nodes' products ahead of the in-order sums and spills them (27 instructions a point
  // more); one node an iteration costs the loop's count and compare nine times.
#pragma GCC unroll 3
    for (int a = 0; a < kGridStencilNodes; ++a) {
      const Real* values = &values_i(s.node[a], 0);
      const Lanes N = broadcast(s.N[a]), dx = broadcast(s.dx[a]), dy = broadcast(s.dy[a]);
      const Lanes vi = loadBlock(values);
      const Lanes vx = vi * dx, vy = vi * dy;
      velocity += N * vi;
      gradient_x += vx;
      gradient_y += vy;
      if constexpr (decltype(with_liquid)::value)
        divergences += vx + __builtin_shufflevector(vy, vy, 1, 0, 3, 2);
    }
  };
  if (wet)
    gather(std::true_type{});
  else
    gather(std::false_type{});
  const Real L[kDim][kDim] = {{gradient_x[0], gradient_y[0]}, {gradient_x[1], gradient_y[1]}};
  const Real strain[kStressComponents] = {dt * L[0][0], dt * L[1][1], 0,    // plane strain
                                          0.5 * dt * (L[0][1] + L[1][0])};  // tensor shear
  storeComponents(rates.strain_increment_p, p, strain);
  store(rates.spin_increment_p, p, spinIncrement(dt, L[0][1], L[1][0]));  // Jaumann rotation
  const Real displacement[kDim] = {dt * velocity[0], dt * velocity[1]};
  storeComponents(rates.displacement_increment_p, p, displacement);
  if constexpr (kStoreGradients) {
    const Real C[kAffineComponents] = {L[0][0], L[0][1], L[1][0], L[1][1]};
    storeComponents(v.affine_solid_p, p, C);
    if (wet) {
      const Real liquid_gradient[kAffineComponents] = {gradient_x[2], gradient_y[2], gradient_x[3],
                                                       gradient_y[3]};
      storeComponents(v.affine_liquid_p, p, liquid_gradient);
    }
  }
  const Real divergence = divergences[2];
  const Real flux = wet ? dt * cellCentreAdvectiveFlux(t, s, values_i) : 0;
  // A point alone exchanges no liquid (strainIncrementsAt): every node of weight is its
  // alone (its liquid volume no more than the point's own N V) and unconditioned.
  // The stencil's centre node first: it always has weight (the middle slot of both 1D
  // stencils, also folded), and in a body of points it is shared, which decides at once; the
  // first node has no weight for some points and weight for others, a branch that went either
  // way. The same test of every node, in another order.
  bool alone = wet;
  if (wet) {
    const Real volume = v.volume_p(p);
    const auto alone_at = [&](int a) {
      const Real own = s.N[a] * volume;
      return s.N[a] == 0 || (values_i(s.node[a], kReadStrainLiquidVolume) <= own &&
                             values_i(s.node[a], kReadStrainConditioned) == 0);
    };
    constexpr int kCentre = kGridStencilNodes / 2;
    alone = alone_at(kCentre);
    for (int a = 0; a < kGridStencilNodes && alone; ++a)
      if (a != kCentre) alone = alone_at(a);
  }
  store(rates.liquid_divergence_increment_p, p, alone ? dt * (L[0][0] + L[1][1]) : dt * divergence);
  store(rates.content_flux_divergence_increment_p, p, alone ? 0 : flux);
}

}  // namespace argine

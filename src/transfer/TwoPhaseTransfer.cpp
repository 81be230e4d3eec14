#include "argine/transfer/TwoPhaseTransfer.hpp"

#include <Kokkos_ScatterView.hpp>

#include "GridPointTransfers.hpp"
#include "PointShapesAt.hpp"
#include "argine/core/UntrackedViews.hpp"
#include "argine/materials/KernelMath.hpp"
#include "argine/materials/ObjectiveStressRate.hpp"
#include "argine/mesh/ShapeFunctions.hpp"
#include "argine/physics/BishopStress.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/CompensatedSum.hpp"
#include "argine/transfer/FlipShare.hpp"
#include "argine/transfer/GridFields.hpp"
#include "argine/transfer/NodeRecords.hpp"
#include "argine/transfer/PointRates.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine {

namespace {

namespace KE = Kokkos::Experimental;

/// A transfer scheme as a type: Scheme<TransferScheme::Apic>{}.
template <TransferScheme kScheme>
using Scheme = std::integral_constant<TransferScheme, kScheme>;

/// Calls f(family, scheme) with the shape family of `shapes` (withShapeFamily) and the
/// kernels' scheme of `transfer` (kernelScheme) as a Scheme<>: both chosen once per call.
template <class Function>
void withFamilyAndScheme(const PointShapes& shapes, const TransferSettings& transfer,
                         Function&& f) {
  withShapeFamily(shapes, [&](auto family) {
    switch (kernelScheme(transfer.scheme)) {
      case TransferScheme::Apic:
        return f(family, Scheme<TransferScheme::Apic>{});
      case TransferScheme::Tpic:
        return f(family, Scheme<TransferScheme::Tpic>{});
      case TransferScheme::Flip:
      case TransferScheme::Xpic:
        break;
    }
    f(family, Scheme<TransferScheme::Flip>{});
  });
}

/// Whether Family is the grid families' (one point at a time, GridPointTransfers.hpp).
template <class Family>
inline constexpr bool kOnGrid = std::is_same_v<Family, GridShapeFamily>;

/// The element of the transfers' kNodes.
template <int kNodes>
using ShapeOf = std::conditional_t<kNodes == 3, Tri3, Quad4>;

/// Calls f(at) with the shapes of the chunk of kLanes points from `first`, all located:
/// computed from their local coordinates (AffineShapesAt) where the chunk's shapes are
/// (PointShapes::computed_c), else read from their records (PointShapesAt<Lanes>).
template <int kNodes, class ElementView, class LocalView, class F>
KOKKOS_INLINE_FUNCTION void withLaneShapes(const PointShapes& shapes, const ElementView& element_p,
                                           const LocalView& local_p, int first, bool one_element,
                                           const F& f) {
  if (shapes.computed_c(first / kLanes)) {
    f(AffineShapesAt<ShapeOf<kNodes>>(shapes, local_p, first, element_p(first)));
    return;
  }
  f(PointShapesAt<Lanes>(shapes, first, one_element));
}

/// Where a P2G kernel adds its points' contributions, as rows of slots (NodeSumSlot) per
/// point and node, for one point (T = Real) or kLanes points (T = Lanes): row[a][slot] for
/// the point's node a, added for the blocks of kLanes slots [first_block, end_block). Every
/// (node, slot) sum gets the points' contributions in point order, so the sums are the
/// one-point sums to the bit.
///
/// Here: the packed rows of NodeRecords::sums_i. On Serial the ScatterView is the View
/// itself (no duplicate, no atomics), so a point's block of kLanes slots is added to a node
/// with one vector instruction; on other backends through the ScatterView access, slot by
/// slot. A point adds zeros to the slots it has no part in (a dry point's liquid sums, the
/// row's padding); every sum starts at +0 and so never becomes -0, and x + 0 = x then.
template <class Access>
struct PackedSums {
  Access& access;
  Kokkos::View<Real* [kNodeSumRow], MemSpace> rows;

  template <int kNodes, class At, class T>
  KOKKOS_INLINE_FUNCTION void addRows(const At& at, const T (&row)[kNodes][kNodeSumRow],
                                      int first_block, int end_block, bool /*wet*/) const {
    constexpr int kPoints = At::kCount;
    constexpr int kBlocks = kNodeSumRow / kLanes;
    Lanes block[kPoints][kNodes][kBlocks];  // the blocks of each point and node
    for (int a = 0; a < kNodes; ++a)
      for (int b = first_block; b < end_block; ++b) {
        if constexpr (kPoints == 1) {
          std::memcpy(&block[0][a][b], &row[a][b * kLanes], sizeof(Lanes));
        } else {
          Lanes points[kLanes];
          transposeLanes(&row[a][b * kLanes], points);
          for (int l = 0; l < kLanes; ++l) block[l][a][b] = points[l];
        }
      }
    for (int l = 0; l < kPoints; ++l)
      for (int a = 0; a < kNodes; ++a) {
        const int i = at.node(a, l);
        for (int b = first_block; b < end_block; ++b) {
          if constexpr (std::is_same_v<ExecSpace, Kokkos::Serial>) {
            Real* sums = &rows(i, b * kLanes);
            Lanes value;
            std::memcpy(&value, sums, sizeof value);
            value = value + block[l][a][b];
            std::memcpy(sums, &value, sizeof value);
          } else {
            for (int k = 0; k < kLanes; ++k) access(i, b * kLanes + k) += block[l][a][b][k];
          }
        }
      }
  }

  /// The same for one point's blocks [first_block, first_block + kCount) of node i, computed
  /// as blocks (GridPointTransfers.hpp).
  template <int kCount>
  KOKKOS_INLINE_FUNCTION void addBlocks(int i, const Lanes (&blocks)[kCount], int first_block,
                                        bool /*wet*/) const {
    Real* const row = &rows(i, 0);  // once a node: the stores may alias the View's fields
    for (int b = 0; b < kCount; ++b) {
      const int slot = (first_block + b) * kLanes;
      if constexpr (std::is_same_v<ExecSpace, Kokkos::Serial>) {
        Real* sums = row + slot;  // LayoutRight rows of kNodeSumRow
        Lanes value;
        std::memcpy(&value, sums, sizeof value);
        value = value + blocks[b];
        std::memcpy(sums, &value, sizeof value);
      } else {
        for (int k = 0; k < kLanes; ++k) access(i, slot + k) += blocks[b][k];
      }
    }
  }
};

/// ... or the GridFields sums `hi`, reproducible with their low parts in `lo` (binned sums,
/// CompensatedSum.hpp; Serial only, so plain references), slot by slot: the slots a point
/// has a part in (all but the liquid ones for a dry point), in point order.
struct CompensatedSums {
  /// Per part (the sums' own fields, then each low part) and P2G slot: the value of node 0,
  /// and the distance between nodes (the low parts are allocated as the sums).
  Real* base[kSumParts][kSumSlotCount];
  std::size_t node_stride[kSumSlotCount];

  CompensatedSums(const GridFields& hi, const LowParts<GridFields>& lo) {
    for (int k = 0; k < kSumParts; ++k) {
      const GridFields& g = k == 0 ? hi : lo[k - 1];
      base[k][kSumMassSolid] = g.mass_solid_i.data();
      base[k][kSumMassLiquid] = g.mass_liquid_i.data();
      base[k][kSumMassIntrinsic] = g.mass_liquid_intrinsic_i.data();
      base[k][kSumDrag] = g.drag_i.data();
      base[k][kSumVolumeLiquid] = g.volume_liquid_i.data();
      for (int d = 0; d < kDim; ++d) {
        base[k][kSumMomentumSolid + d] = &g.momentum_solid_i(0, d);
        base[k][kSumMomentumLiquid + d] = &g.momentum_liquid_i(0, d);
        base[k][kSumForceMixture + d] = &g.force_mixture_i(0, d);
        base[k][kSumForceLiquid + d] = &g.force_liquid_i(0, d);
      }
    }
    for (const int slot :
         {kSumMassSolid, kSumMassLiquid, kSumMassIntrinsic, kSumDrag, kSumVolumeLiquid})
      node_stride[slot] = hi.mass_solid_i.stride(0);
    for (int d = 0; d < kDim; ++d)
      for (const int slot :
           {kSumMomentumSolid, kSumMomentumLiquid, kSumForceMixture, kSumForceLiquid})
        node_stride[slot + d] = hi.momentum_solid_i.stride(0);
  }

  KOKKOS_INLINE_FUNCTION void add(int i, int slot, Real v) const {
    const std::size_t offset = i * node_stride[slot];
    addToSumParts([&](int k) -> Real& { return base[k][slot][offset]; }, v);
  }

  template <int kNodes, class At, class T>
  KOKKOS_INLINE_FUNCTION void addRows(const At& at, const T (&row)[kNodes][kNodeSumRow],
                                      int first_block, int end_block, bool wet) const {
    for (int l = 0; l < At::kCount; ++l)
      for (int a = 0; a < kNodes; ++a)
        for (int slot = first_block * kLanes; slot < end_block * kLanes; ++slot)
          if (slot < kSumSlotCount && (wet || isSolidSumSlot(slot)))
            add(at.node(a, l), slot, lane(row[a][slot], l));
  }

  template <int kCount>
  KOKKOS_INLINE_FUNCTION void addBlocks(int i, const Lanes (&blocks)[kCount], int first_block,
                                        bool wet) const {
    for (int b = 0; b < kCount; ++b)
      for (int k = 0; k < kLanes; ++k) {
        const int slot = (first_block + b) * kLanes + k;
        if (slot < kSumSlotCount && (wet || isSolidSumSlot(slot))) add(i, slot, blocks[b][k]);
      }
  }
};

/// Runs body(p, sums, r0, r1, n) for every point, with `sums` the packed rows of `records` or,
/// with `compensation`, the reproducible GridFields sums (grid, *compensation), and r0, r1, n
/// the body's totals, summed in point order (Serial); the packed sums are added to `grid` at
/// the active nodes afterwards (all slots, or the momenta alone).
template <class Body>
KineticTotals scatterFromPoints(const char* name, int count, const Body& body,
                                const ActiveNodes& active, NodeRecords& records, GridFields& grid,
                                const LowParts<GridFields>* compensation, bool momenta_only) {
  KineticTotals totals;
  const auto policy = Kokkos::RangePolicy<ExecSpace>(0, count);
  if (compensation) {
    const CompensatedSums sums(grid, *compensation);
    Kokkos::parallel_reduce(
        name, policy,
        KOKKOS_LAMBDA(const int p, Real& r0, Real& r1, int& n) { body(p, sums, r0, r1, n); },
        totals.solid, totals.liquid, totals.non_finite_points);
    return totals;
  }
  records.allocate(grid.numNodes());
  auto scatter = KE::create_scatter_view(records.sums_i);
  const auto rows = records.sums_i;
  Kokkos::parallel_reduce(
      name, policy,
      KOKKOS_LAMBDA(const int p, Real& r0, Real& r1, int& n) {
        auto access = scatter.access();
        body(p, PackedSums<decltype(access)>{access, rows}, r0, r1, n);
      },
      totals.solid, totals.liquid, totals.non_finite_points);
  KE::contribute(records.sums_i, scatter);
  if (momenta_only)
    addMomentumSumsToGrid(active, records, grid);
  else
    addNodeSumsToGrid(active, records, grid);
  return totals;
}

/// The nodal sums of the P2G (4.40-4.47), as point fields and their totals.
struct P2GPointViews {
  Kokkos::View<int*, MemSpace> material_p;
  Kokkos::View<Real*, MemSpace> volume_p, mass_solid_p, mass_liquid_p, density_liquid_p, porosity_p,
      saturation_p, conductivity_p, pressure_p;
  Kokkos::View<Real* [kStressComponents], MemSpace> stress_p;
  Kokkos::View<Real*[kDim], MemSpace> velocity_solid_p, velocity_liquid_p;
  // APIC only
  Kokkos::View<Real* [kDim], MemSpace> position_p;
  Kokkos::View<Real*[kAffineComponents], MemSpace> affine_solid_p, affine_liquid_p;
  Kokkos::View<const Real* [kDim], MemSpace> coordinates_i;
  // `Conjugate Mean Stress`: the shifts of the mixture's mean stress and of p_L (shifted)
  MeanStressShifts mean_shift_p;
  bool shifted = false;
};

/// What the momentum of a point adds at its node a: m (v + C (x_a - x_p)) with APIC (kAffine),
/// m v otherwise, for one point or kLanes. `offset` is x_a - x_p.
template <bool kAffine, class T>
KOKKOS_INLINE_FUNCTION void affineVelocity(const T v[kDim], const T C[kAffineComponents],
                                           const T offset[kDim], T out[kDim]) {
  for (int d = 0; d < kDim; ++d) {
    out[d] = v[d];
    if constexpr (kAffine)
      for (int k = 0; k < kDim; ++k) out[d] = out[d] + C[d * kDim + k] * offset[k];
  }
}

/// x_a - x_p for node a of the point(s) at `at`, `xp` their position (APIC).
template <class At, class Coordinates, class T>
KOKKOS_INLINE_FUNCTION void nodeOffset(const At& at, const Coordinates& coordinates_i, int a,
                                       const T xp[kDim], T offset[kDim]) {
  for (int d = 0; d < kDim; ++d) offset[d] = at.nodal(coordinates_i, a, d) - xp[d];
}

/// What point p (T = Real) or points p .. p + kLanes - 1 (Lanes), located and all `wet` or
/// all dry, add to their nodes (4.40-4.47): one row of NodeSumSlot values per node, computed
/// for all lanes at once and added by `sums` (PackedSums, CompensatedSums) in point order.
template <int kNodes, bool kAffine, class At, class Sums>
KOKKOS_INLINE_FUNCTION void mapPointToGrid(const At& at, bool wet, Real gravity,
                                           const P2GPointViews& v, const Sums& sums, int p) {
  using T = typename At::Value;
  const T volume = load<T>(v.volume_p, p);
  const T m_solid = load<T>(v.mass_solid_p, p);
  const T m_liquid = wet ? load<T>(v.mass_liquid_p, p) : splat<T>(0);
  // Bishop total stress, chi = S_L (4.5), p_L compression positive.
  const T bishop =
      wet ? bishopPorePressure(load<T>(v.saturation_p, p), load<T>(v.pressure_p, p)) : splat<T>(0);
  T stress[kStressComponents];
  loadComponents(v.stress_p, p, stress);
  T sxx = stress[XX] - bishop, syy = stress[YY] - bishop;
  const T sxy = stress[XY];
  T pressure_shift = splat<T>(0);  // `Conjugate Mean Stress`: the element's means instead
  if (v.shifted) {
    const T mean_shift = load<T>(v.mean_shift_p, p, 0);
    sxx = sxx + mean_shift;
    syy = syy + mean_shift;
    pressure_shift = load<T>(v.mean_shift_p, p, 1);
  }
  const T weight_mixture = -(m_solid + m_liquid) * gravity;  // 4.42, m_m = M_S + M_L
  const T vs[kDim] = {load<T>(v.velocity_solid_p, p, 0), load<T>(v.velocity_solid_p, p, 1)};
  // APIC: the affine matrices and the offsets x_a - x_p
  T cs[kAffineComponents] = {}, cl[kAffineComponents] = {}, xp[kDim] = {},
    offset[kNodes][kDim] = {};
  if constexpr (kAffine) {
    loadComponents(v.affine_solid_p, p, cs);
    if (wet) loadComponents(v.affine_liquid_p, p, cl);
    xp[0] = load<T>(v.position_p, p, 0);
    xp[1] = load<T>(v.position_p, p, 1);
    for (int a = 0; a < kNodes; ++a) nodeOffset(at, v.coordinates_i, a, xp, offset[a]);
  }
  T row[kNodes][kNodeSumRow];
  for (int a = 0; a < kNodes; ++a) {
    for (int slot = 0; slot < kNodeSumRow; ++slot)  // the liquid's when dry, and the padding
      if (!isSolidSumSlot(slot)) row[a][slot] = splat<T>(0);
    const T N = at.value(a);
    const T dx = at.gradient(a, 0), dy = at.gradient(a, 1);
    T va[kDim];
    affineVelocity<kAffine>(vs, cs, offset[a], va);
    row[a][kSumMassSolid] = N * m_solid;
    row[a][kSumMomentumSolid] = N * m_solid * va[0];
    row[a][kSumMomentumSolid + 1] = N * m_solid * va[1];
    row[a][kSumForceMixture] = -(sxx * dx + sxy * dy) * volume;
    row[a][kSumForceMixture + 1] = -(sxy * dx + syy * dy) * volume + N * weight_mixture;
  }
  if (wet) {
    const T rho = load<T>(v.density_liquid_p, p);
    const T m_intrinsic = rho * volume;  // 4.46
    // Darcy drag per unit liquid volume n S_L rho_L g / k (4.2-4.3, 4.45), g = 9.81.
    const T drag = load<T>(v.porosity_p, p) * load<T>(v.saturation_p, p) * rho * kStandardGravity /
                   load<T>(v.conductivity_p, p) * volume;
    const T pressure_volume = (load<T>(v.pressure_p, p) + pressure_shift) * volume;
    const T weight_liquid = -m_intrinsic * gravity;  // 4.41 with M~_L
    const T vl[kDim] = {load<T>(v.velocity_liquid_p, p, 0), load<T>(v.velocity_liquid_p, p, 1)};
    for (int a = 0; a < kNodes; ++a) {
      const T N = at.value(a);
      T va[kDim];
      affineVelocity<kAffine>(vl, cl, offset[a], va);
      row[a][kSumMassLiquid] = N * m_liquid;
      row[a][kSumMassIntrinsic] = N * m_intrinsic;
      row[a][kSumDrag] = N * drag;
      row[a][kSumVolumeLiquid] = N * volume;
      row[a][kSumMomentumLiquid] = N * m_intrinsic * va[0];
      row[a][kSumMomentumLiquid + 1] = N * m_intrinsic * va[1];
      // -f_L^int = sum B^T p_L m V with p_L compression positive (4.43).
      row[a][kSumForceLiquid] = at.gradient(a, 0) * pressure_volume;
      row[a][kSumForceLiquid + 1] = at.gradient(a, 1) * pressure_volume + N * weight_liquid;
    }
  }
  sums.template addRows<kNodes>(at, row, 0, (kSumSlotCount + kLanes - 1) / kLanes, wet);
}

/// Whether the kLanes points from `first` (of `count`) can be mapped as Lanes: all located
/// and all wet or all dry (`wet` is set to that); `one_element`: all in one element.
KOKKOS_INLINE_FUNCTION bool lanesMapTogether(const Kokkos::View<int*, MemSpace>& element_p,
                                             const Kokkos::View<int*, MemSpace>& material_p,
                                             const LiquidCarrying& liquid_m, int first, int count,
                                             bool& wet, bool& one_element) {
  if (first + kLanes > count) return false;
  wet = liquid_m(material_p(first)) != 0;
  one_element = true;
  for (int p = first; p < first + kLanes; ++p) {
    if (element_p(p) < 0 || (liquid_m(material_p(p)) != 0) != wet) return false;
    one_element = one_element && element_p(p) == element_p(first);
  }
  return true;
}

template <class Family, TransferScheme kScheme>
void mapPointsToGridImpl(const MaterialPoints& points, const PointShapes& shapes,
                         const LiquidCarrying& liquid_m, Real gravity,
                         const TransferSettings& transfer, const ActiveNodes& active,
                         NodeRecords& records, GridFields& grid,
                         const LowParts<GridFields>* compensation) {
  const P2GPointViews v = untracked(P2GPointViews{
      points.material, points.volume, points.mass_solid, points.mass_liquid, points.density_liquid,
      points.porosity, points.saturation, points.conductivity, points.pressure_liquid,
      points.stress_effective, points.velocity_solid, points.velocity_liquid, points.position,
      points.affine_velocity_solid, points.affine_velocity_liquid, transfer.node_coordinates,
      transfer.mean_stress_shift, transfer.mean_stress_shift.extent(0) > 0});
  const auto element_p = points.element;
  const auto local_p = points.local;
  const int count = points.count;
  constexpr int kNodes = Family::kNodes;
  // the momenta of step 1's P2G carry C_p (x_i - x_p) where the points have C_p
  constexpr bool kAffine = carriesAffineVelocity(kScheme);
  // One call per kLanes points (lanesMapTogether), else point by point: the same bits. The
  // grid families: point by point, by blocks of slots (GridPointTransfers.hpp).
  const auto body = KOKKOS_LAMBDA(const int chunk, const auto& sums, Real&, Real&, int&) {
    const int first = chunk * kLanes;
    if constexpr (kOnGrid<Family>) {
      for (int p = first; p < first + kLanes && p < count; ++p)
        if (element_p(p) >= 0)
          mapGridPointToGrid<kAffine>(shapes.grid_p(p), shapes.grid_row,
                                      liquid_m(v.material_p(p)) != 0, gravity, v, sums, p);
    } else {
      bool wet = false, one_element = false;
      if (lanesMapTogether(element_p, v.material_p, liquid_m, first, count, wet, one_element)) {
        withLaneShapes<kNodes>(shapes, element_p, local_p, first, one_element, [&](const auto& at) {
          mapPointToGrid<kNodes, kAffine>(at, wet, gravity, v, sums, first);
        });
        return;
      }
      for (int p = first; p < first + kLanes && p < count; ++p) {
        if (element_p(p) < 0) continue;
        mapPointToGrid<kNodes, kAffine>(PointShapesAt<Real>(shapes, element_p, local_p, p),
                                        liquid_m(v.material_p(p)) != 0, gravity, v, sums, p);
      }
    }
  };
  scatterFromPoints("p2g_two_phase", (count + kLanes - 1) / kLanes, body, active, records, grid,
                    compensation, false);
}

/// The point fields of the velocity update and remap.
struct G2PPointViews {
  Kokkos::View<Real*, MemSpace> volume_p, mass_solid_p, mass_liquid_p, density_liquid_p;
  Kokkos::View<Real*[kDim], MemSpace> velocity_solid_p, velocity_liquid_p;
  // APIC only
  Kokkos::View<Real* [kDim], MemSpace> position_p;
  Kokkos::View<Real*[kAffineComponents], MemSpace> affine_solid_p, affine_liquid_p;
  Kokkos::View<const Real* [kDim], MemSpace> coordinates_i;
};

/// TPIC's G2P of one phase: v_p = sum N v~_i from the grid velocities in `slot` (x, y).
template <int kNodes, class At, class Values, class T>
KOKKOS_INLINE_FUNCTION void interpolateGridVelocity(const At& at, const Values& values_i, int slot,
                                                    T v[kDim]) {
  for (int d = 0; d < kDim; ++d) v[d] = splat<T>(0);
  for (int a = 0; a < kNodes; ++a) {
    const T N = at.value(a);
    for (int d = 0; d < kDim; ++d) v[d] += N * at.nodal(values_i, a, slot + d);
  }
}

/// APIC's G2P of one phase: v_p = sum N v~_i and C_p = sum v~_i (grad N_i)^T (C_jk =
/// sum v~_i,j dN_i/dx_k) from the grid velocities in `slot` (x, y) of `values_i`.
template <int kNodes, class At, class Values, class T>
KOKKOS_INLINE_FUNCTION void affineVelocityFromGrid(const At& at, const Values& values_i, int slot,
                                                   T v[kDim], T C[kAffineComponents]) {
  for (int d = 0; d < kDim; ++d) v[d] = splat<T>(0);
  for (int c = 0; c < kAffineComponents; ++c) C[c] = splat<T>(0);
  for (int a = 0; a < kNodes; ++a) {
    const T N = at.value(a);
    const T gradient[kDim] = {at.gradient(a, 0), at.gradient(a, 1)};
    for (int d = 0; d < kDim; ++d) {
      const T vi = at.nodal(values_i, a, slot + d);
      v[d] += N * vi;
      for (int k = 0; k < kDim; ++k) C[d * kDim + k] += vi * gradient[k];
    }
  }
}

/// A FLIP share in APIC's update of one phase (VelocityBlend): v <- v_APIC + (1 - alpha)
/// (v_p + dt sum N a_i - v_APIC), v_p in `velocity_p`, a_i in `slot` (x, y) of `values_i`,
/// alpha = `grid_share`.
template <int kNodes, class At, class Values, class Velocities, class T>
KOKKOS_INLINE_FUNCTION void addFlipShare(const At& at, const Values& values_i, int slot,
                                         const Velocities& velocity_p, int p, Real dt,
                                         Real grid_share, T v[kDim]) {
  T flip[kDim], acceleration[kDim] = {};
  loadComponents(velocity_p, p, flip);
  for (int a = 0; a < kNodes; ++a) {
    const T N = at.value(a);
    for (int d = 0; d < kDim; ++d) acceleration[d] += N * at.nodal(values_i, a, slot + d);
  }
  for (int d = 0; d < kDim; ++d)
    v[d] = withFlipShare(v[d], flip[d] + dt * acceleration[d], grid_share);
}

/// The velocity update of point p (T = Real) or points p .. p + kLanes - 1 (Lanes), located
/// and all `wet` or all dry, from the nodal values of readVelocityUpdateValues, and their
/// momenta added to the nodes (the remap; slots 4-7, one block). The kinetic energies and
/// the count of non-finite velocities are summed in point order, per TransferScheme: FLIP
/// (v += dt sum N a), APIC (v and C from the grid's v~, momenta with C), TPIC (v from the
/// grid's v~, momenta without C: C is step 4's velocity gradient, strainIncrementsAt).
template <int kNodes, TransferScheme kScheme, class At, class Values, class Sums>
KOKKOS_INLINE_FUNCTION void updatePointVelocityAt(const At& at, bool wet, Real dt, Real pic_solid,
                                                  Real pic_liquid, const Values& values_i,
                                                  const G2PPointViews& v, const Sums& sums, int p,
                                                  Real& ks, Real& kl, int& bad) {
  using T = typename At::Value;
  constexpr int kPoints = At::kCount;
  constexpr bool kAffine = kScheme == TransferScheme::Apic;    // the remap carries C_p
  constexpr bool kFromGrid = kScheme != TransferScheme::Flip;  // v_p = sum N v~_i
  T v_solid[kDim], cs[kAffineComponents] = {}, xp[kDim] = {}, offset[kNodes][kDim] = {};
  T as[kDim] = {}, vs_grid[kDim] = {};  // FLIP
  if constexpr (kAffine) {
    affineVelocityFromGrid<kNodes>(at, values_i, kReadVelocitySolid, v_solid, cs);
    storeComponents(v.affine_solid_p, p, cs);
    if (pic_solid < 1)
      addFlipShare<kNodes>(at, values_i, kReadAccelerationSolid, v.velocity_solid_p, p, dt,
                           pic_solid, v_solid);
    xp[0] = load<T>(v.position_p, p, 0);
    xp[1] = load<T>(v.position_p, p, 1);
    for (int a = 0; a < kNodes; ++a) nodeOffset(at, v.coordinates_i, a, xp, offset[a]);
  } else if constexpr (kFromGrid) {
    interpolateGridVelocity<kNodes>(at, values_i, kReadVelocitySolid, v_solid);
  } else {
    // solid: FLIP v_p + dt sum N a_i, blended: + alpha (sum N v_i - v_p) (the header). Each
    // interpolation a loop of its own: the conditions are tested once per point, not per node.
    loadComponents(v.velocity_solid_p, p, v_solid);
    const auto interpolate = [&](int slot, T sum[kDim]) {
      for (int a = 0; a < kNodes; ++a) {
        const T N = at.value(a);
        for (int d = 0; d < kDim; ++d) sum[d] += N * at.nodal(values_i, a, slot + d);
      }
    };
    interpolate(kReadAccelerationSolid, as);
    if (pic_solid > 0 || (wet && pic_liquid > 0)) interpolate(kReadVelocitySolid, vs_grid);
    for (int d = 0; d < kDim; ++d)
      v_solid[d] = v_solid[d] + dt * as[d] + pic_solid * (vs_grid[d] - v_solid[d]);
  }
  storeComponents(v.velocity_solid_p, p, v_solid);
  const T vsx = v_solid[0], vsy = v_solid[1];
  const T ms = load<T>(v.mass_solid_p, p);
  Real energy[kPoints];
  spill(0.5 * ms * (vsx * vsx + vsy * vsy), energy);
  const auto solid_finite = both(kmath::isFinite(vsx), kmath::isFinite(vsy));
  for (int l = 0; l < kPoints; ++l) {
    ks += energy[l];
    if (!lane(solid_finite, l)) ++bad;
  }
  T row[kNodes][kNodeSumRow];
  for (int a = 0; a < kNodes; ++a) {
    const T N = at.value(a);
    T va[kDim];
    affineVelocity<kAffine>(v_solid, cs, offset[a], va);
    row[a][kSumMomentumSolid] = N * ms * va[0];
    row[a][kSumMomentumSolid + 1] = N * ms * va[1];
    row[a][kSumMomentumLiquid] = row[a][kSumMomentumLiquid + 1] = splat<T>(0);
  }
  if (wet) {
    T v_liquid[kDim], cl[kAffineComponents] = {};
    if constexpr (kAffine) {
      affineVelocityFromGrid<kNodes>(at, values_i, kReadVelocityLiquid, v_liquid, cl);
      storeComponents(v.affine_liquid_p, p, cl);
      if (pic_liquid < 1)
        addFlipShare<kNodes>(at, values_i, kReadAccelerationLiquid, v.velocity_liquid_p, p, dt,
                             pic_liquid, v_liquid);
    } else if constexpr (kFromGrid) {
      interpolateGridVelocity<kNodes>(at, values_i, kReadVelocityLiquid, v_liquid);
    } else {
      // liquid: the relative velocity w_p = v_L - v_S relaxes towards the grid's sum N w_i
      // (the header); with pic_liquid = 0 this is FLIP.
      T al[kDim] = {}, vl[kDim] = {};
      for (int a = 0; a < kNodes; ++a) {
        const T N = at.value(a);
        for (int d = 0; d < kDim; ++d)
          al[d] += N * at.nodal(values_i, a, kReadAccelerationLiquid + d);
      }
      if (pic_liquid > 0)
        for (int a = 0; a < kNodes; ++a) {
          const T N = at.value(a);
          for (int d = 0; d < kDim; ++d)
            vl[d] += N * at.nodal(values_i, a, kReadVelocityLiquid + d);
        }
      loadComponents(v.velocity_liquid_p, p, v_liquid);
      for (int d = 0; d < kDim; ++d) {
        const T flip = v_liquid[d] + dt * al[d];
        const T relative_pic = v_solid[d] + vl[d] - vs_grid[d] + dt * (al[d] - as[d]);
        v_liquid[d] = pic_liquid > 0 ? flip + pic_liquid * (relative_pic - flip) : flip;
      }
    }
    const T vlx = v_liquid[0], vly = v_liquid[1];
    storeComponents(v.velocity_liquid_p, p, v_liquid);
    spill(0.5 * load<T>(v.mass_liquid_p, p) * (vlx * vlx + vly * vly), energy);
    const auto liquid_finite = both(kmath::isFinite(vlx), kmath::isFinite(vly));
    for (int l = 0; l < kPoints; ++l) {
      kl += energy[l];
      if (!lane(liquid_finite, l)) ++bad;
    }
    const T ml = load<T>(v.density_liquid_p, p) * load<T>(v.volume_p, p);
    for (int a = 0; a < kNodes; ++a) {
      const T N = at.value(a);
      T va[kDim];
      affineVelocity<kAffine>(v_liquid, cl, offset[a], va);
      row[a][kSumMomentumLiquid] = N * ml * va[0];
      row[a][kSumMomentumLiquid + 1] = N * ml * va[1];
    }
  }
  static_assert(kSumMomentumSolid == kLanes && kSumMomentumLiquid + kDim == 2 * kLanes,
                "the momenta fill block 1 of a row");
  sums.template addRows<kNodes>(at, row, 1, 2, wet);
}

template <class Family, TransferScheme kScheme>
KineticTotals updateVelocitiesAndMapMomentaImpl(
    const PointShapes& shapes, const LiquidCarrying& liquid_m, const ActiveNodes& active, Real dt,
    const TransferSettings& transfer, MaterialPoints& points, NodeRecords& records,
    GridFields& grid, const LowParts<GridFields>* compensation) {
  const auto material_p = points.material;
  const auto element_p = points.element;
  const auto local_p = points.local;
  const G2PPointViews v = untracked(G2PPointViews{
      points.volume, points.mass_solid, points.mass_liquid, points.density_liquid,
      points.velocity_solid, points.velocity_liquid, points.position, points.affine_velocity_solid,
      points.affine_velocity_liquid, transfer.node_coordinates});
  readVelocityUpdateValues(active, grid, records);
  const auto values_i = records.values_i;
  const VelocityBlend shares = gridShares(kScheme, transfer.blend, dt);
  const Real pic_solid = shares.solid, pic_liquid = shares.liquid;
  const int count = points.count;
  constexpr int kNodes = Family::kNodes;
  // One call per kLanes points (lanesMapTogether), else point by point: the same bits. The
  // grid families: point by point, by blocks of slots (GridPointTransfers.hpp).
  const auto body = KOKKOS_LAMBDA(const int chunk, const auto& sums, Real& ks, Real& kl, int& bad) {
    const int first = chunk * kLanes;
    if constexpr (kOnGrid<Family>) {
      for (int p = first; p < first + kLanes && p < count; ++p)
        if (element_p(p) >= 0)
          updateGridPointVelocity<kScheme>(shapes.grid_p(p), shapes.grid_row,
                                           liquid_m(material_p(p)) != 0, dt, pic_solid, pic_liquid,
                                           values_i, v, sums, p, ks, kl, bad);
    } else {
      bool wet = false, one_element = false;
      if (lanesMapTogether(element_p, material_p, liquid_m, first, count, wet, one_element)) {
        withLaneShapes<kNodes>(shapes, element_p, local_p, first, one_element, [&](const auto& at) {
          updatePointVelocityAt<kNodes, kScheme>(at, wet, dt, pic_solid, pic_liquid, values_i, v,
                                                 sums, first, ks, kl, bad);
        });
        return;
      }
      for (int p = first; p < first + kLanes && p < count; ++p) {
        if (element_p(p) < 0) continue;
        updatePointVelocityAt<kNodes, kScheme>(PointShapesAt<Real>(shapes, element_p, local_p, p),
                                               liquid_m(material_p(p)) != 0, dt, pic_solid,
                                               pic_liquid, values_i, v, sums, p, ks, kl, bad);
      }
    }
  };
  return scatterFromPoints("g2p_velocities_p2g_momenta", (count + kLanes - 1) / kLanes, body,
                           active, records, grid, compensation, true);
}

/// The strain, spin, displacement and liquid-divergence increments of point p (T = Real) or
/// of points p .. p + kLanes - 1 (Lanes), all located and all `wet` or all dry, from the
/// nodal values of readStrainValues (interpolateVelocityGradients).
/// The point fields the strain kernel reads or writes besides the rates: the volume (is the
/// point alone for the liquid), and TPIC's affine matrices (the velocity gradients).
struct StrainPointViews {
  Kokkos::View<Real*, MemSpace> volume_p;
  Kokkos::View<Real*[kAffineComponents], MemSpace> affine_solid_p, affine_liquid_p;
};

template <int kNodes, bool kCentre, bool kStoreGradients, class At, class Values>
KOKKOS_INLINE_FUNCTION void strainIncrementsAt(const At& at, bool wet, Real dt,
                                               const Values& values_i, const StrainPointViews& v,
                                               const PointRates& rates, int p) {
  using T = typename At::Value;
  T L[kDim][kDim] = {};  // L_jk = d v_S,j / d x_k
  T velocity[kDim] = {};
  for (int a = 0; a < kNodes; ++a) {
    const T N = at.value(a);
    const T dx = at.gradient(a, 0), dy = at.gradient(a, 1);
    const T vx = at.nodal(values_i, a, kReadStrainVelocitySolid),
            vy = at.nodal(values_i, a, kReadStrainVelocitySolid + 1);
    L[0][0] += vx * dx;
    L[0][1] += vx * dy;
    L[1][0] += vy * dx;
    L[1][1] += vy * dy;
    velocity[0] += N * vx;
    velocity[1] += N * vy;
  }
  const T strain[kStressComponents] = {dt * L[0][0], dt * L[1][1],
                                       splat<T>(0),                      // plane strain
                                       0.5 * dt * (L[0][1] + L[1][0])};  // tensor shear
  storeComponents(rates.strain_increment_p, p, strain);
  store(rates.spin_increment_p, p, spinIncrement(dt, L[0][1], L[1][0]));  // Jaumann rotation
  const T displacement[kDim] = {dt * velocity[0], dt * velocity[1]};
  storeComponents(rates.displacement_increment_p, p, displacement);
  if constexpr (kStoreGradients) {  // TPIC: C_p = grad v_S of the remapped field
    const T C[kAffineComponents] = {L[0][0], L[0][1], L[1][0], L[1][1]};
    storeComponents(v.affine_solid_p, p, C);
  }

  T divergence = {}, relative_divergence = {}, content = {};
  T w[kDim] = {}, gradient[kDim] = {};
  T liquid_gradient[kAffineComponents] = {};                              // TPIC: grad v_L
  auto alone = both(divergence == divergence, divergence == divergence);  // true in every lane
  if (wet) {
    // c = rho_L n S_L and w = v_L - v_S enter the advective flux div(c w) (4.12, 4.16)
    // at the element centre (N = 1/kNodes), not at the point: per-point values differ
    // between rows of points in one element, a pressure mode the momentum equations
    // cannot see (a one-element-wide quad4 column shows it), which then grows. (The grid
    // families take the centre of the point's cell: gridStrainIncrements.)
    static_assert(kCentre, "the grid families have their own kernel (GridPointTransfers.hpp)");
    constexpr Real centre = Real(1) / kNodes;
    for (int a = 0; a < kNodes; ++a) {
      const T weight = splat<T>(centre);
      const T dx = at.gradient(a, 0), dy = at.gradient(a, 1);
      const T vlx = at.nodal(values_i, a, kReadStrainVelocityLiquid),
              vly = at.nodal(values_i, a, kReadStrainVelocityLiquid + 1);
      const T wx = vlx - at.nodal(values_i, a, kReadStrainVelocitySolid),
              wy = vly - at.nodal(values_i, a, kReadStrainVelocitySolid + 1);
      const T c = at.nodal(values_i, a, kReadStrainLiquidContent);
      // the point shares node a when the node's liquid volume exceeds its own N V (the same
      // product as the P2G's: a node of its alone holds exactly it)
      const T own = at.value(a) * load<T>(v.volume_p, p);
      const T shared_volume = at.nodal(values_i, a, kReadStrainLiquidVolume);
      const T conditioned = at.nodal(values_i, a, kReadStrainConditioned);
      const auto untouched = at.value(a) == 0;  // a stencil slot of no weight
      alone = both(alone, either(untouched, both(shared_volume <= own, conditioned == 0)));
      divergence += vlx * dx + vly * dy;
      relative_divergence += wx * dx + wy * dy;
      if constexpr (kStoreGradients) {
        liquid_gradient[0] += vlx * dx;
        liquid_gradient[1] += vlx * dy;
        liquid_gradient[2] += vly * dx;
        liquid_gradient[3] += vly * dy;
      }
      w[0] += weight * wx;
      w[1] += weight * wy;
      content += weight * c;
      gradient[0] += c * dx;
      gradient[1] += c * dy;
    }
  }
  if constexpr (kStoreGradients)
    if (wet) storeComponents(v.affine_liquid_p, p, liquid_gradient);
  // A point alone exchanges no liquid (interpolateVelocityGradients): div v_L = div v_S and
  // no content flux, so its liquid mass stays.
  const T flux = dt * (content * relative_divergence + gradient[0] * w[0] + gradient[1] * w[1]);
  if (!(wet && anyLane(alone))) {
    store(rates.liquid_divergence_increment_p, p, dt * divergence);
    store(rates.content_flux_divergence_increment_p, p, flux);
    return;
  }
  store(rates.liquid_divergence_increment_p, p,
        select(alone, dt * (L[0][0] + L[1][1]), dt * divergence));
  store(rates.content_flux_divergence_increment_p, p, select(alone, splat<T>(0), flux));
}

/// The increments of a point outside the mesh: none.
KOKKOS_INLINE_FUNCTION void clearStrainIncrements(const PointRates& rates, int p) {
  for (int c = 0; c < kStressComponents; ++c) rates.strain_increment_p(p, c) = 0;
  rates.displacement_increment_p(p, 0) = rates.displacement_increment_p(p, 1) = 0;
  rates.spin_increment_p(p) = 0;
  rates.liquid_divergence_increment_p(p) = 0;
  rates.content_flux_divergence_increment_p(p) = 0;
}

/// One call per kLanes consecutive points: all of them at once where they are located and
/// all wet or all dry (strainIncrementsAt<Lanes>), else one by one. The same bits.
template <class Family, bool kStoreGradients>
void interpolateVelocityGradientsImpl(const MaterialPoints& points, const PointShapes& shapes,
                                      const LiquidCarrying& liquid_m, const ActiveNodes& active,
                                      const GridFields& grid, NodeRecords& records, Real dt,
                                      PointRates& rates,
                                      Kokkos::View<const unsigned char*, MemSpace> conditioned_i) {
  const auto material_p = points.material;
  const auto element_p = points.element;
  const auto local_p = points.local;
  const StrainPointViews strain_v = untracked(
      StrainPointViews{points.volume, points.affine_velocity_solid, points.affine_velocity_liquid});
  records.allocate(grid.numNodes());
  readStrainValues(active, grid, conditioned_i, records);
  const auto values_i = records.values_i;
  const PointRates r = rates;
  const int count = points.count;
  constexpr int kNodes = Family::kNodes;
  constexpr bool kCentre = Family::kElementCentre;
  Kokkos::parallel_for(
      "g2p_velocity_gradients", Kokkos::RangePolicy<ExecSpace>(0, (count + kLanes - 1) / kLanes),
      KOKKOS_LAMBDA(const int chunk) {
        const int first = chunk * kLanes;
        const int end = first + kLanes < count ? first + kLanes : count;
        if constexpr (kOnGrid<Family>) {
          for (int p = first; p < end; ++p) {
            if (element_p(p) < 0)
              clearStrainIncrements(r, p);
            else
              gridStrainIncrements<kStoreGradients>(shapes.grid_p(p), shapes.grid_row,
                                                    liquid_m(material_p(p)) != 0, dt, values_i,
                                                    strain_v, r, p);
          }
        } else {
          bool wet = false, one_element = false;
          if (lanesMapTogether(element_p, material_p, liquid_m, first, count, wet, one_element)) {
            withLaneShapes<kNodes>(shapes, element_p, local_p, first, one_element,
                                   [&](const auto& at) {
                                     strainIncrementsAt<kNodes, kCentre, kStoreGradients>(
                                         at, wet, dt, values_i, strain_v, r, first);
                                   });
            return;
          }
          for (int p = first; p < end; ++p) {
            if (element_p(p) < 0)
              clearStrainIncrements(r, p);
            else
              strainIncrementsAt<kNodes, kCentre, kStoreGradients>(
                  PointShapesAt<Real>(shapes, element_p, local_p, p), liquid_m(material_p(p)) != 0,
                  dt, values_i, strain_v, r, p);
          }
        }
      });
}

}  // namespace

void mapPointsToGrid(const MaterialPoints& points, const PointShapes& shapes,
                     const LiquidCarrying& liquid_m, Real gravity, const TransferSettings& transfer,
                     const ActiveNodes& active, NodeRecords& records, GridFields& grid,
                     const LowParts<GridFields>* compensation) {
  // the kernel's captures count no references (UntrackedViews.hpp)
  withFamilyAndScheme(shapes, transfer, [&](auto family, auto scheme) {
    mapPointsToGridImpl<decltype(family), decltype(scheme)::value>(
        untracked(points), untracked(shapes), liquid_m, gravity, transfer, active, records, grid,
        compensation);
  });
}

void computeNodalVelocities(const ActiveNodes& active, GridFields& grid) {
  const auto nodes = active.nodes();
  const GridFields g = untracked(grid);
  Kokkos::parallel_for(
      "nodal_velocities", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        const Real ms = g.mass_solid_i(i);
        for (int d = 0; d < kDim; ++d)
          g.velocity_solid_i(i, d) = ms > 0 ? g.momentum_solid_i(i, d) / ms : 0;
        const Real ml = g.mass_liquid_intrinsic_i(i);
        for (int d = 0; d < kDim; ++d)
          g.velocity_liquid_i(i, d) =
              ml > 0 ? g.momentum_liquid_i(i, d) / ml : g.velocity_solid_i(i, d);
        const Real vl = g.volume_liquid_i(i);
        g.liquid_content_i(i) = vl > 0 ? g.mass_liquid_i(i) / vl : 0;
      });
}

void advanceNodalVelocities(const ActiveNodes& active, Real dt, GridFields& grid) {
  const auto nodes = active.nodes();
  const GridFields g = untracked(grid);
  Kokkos::parallel_for(
      "advance_nodal_velocities", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        const bool liquid = g.mass_liquid_intrinsic_i(i) > 0;
        for (int d = 0; d < kDim; ++d) {
          g.velocity_solid_i(i, d) += dt * g.acceleration_solid_i(i, d);
          g.velocity_liquid_i(i, d) =
              liquid ? g.velocity_liquid_i(i, d) + dt * g.acceleration_liquid_i(i, d)
                     : g.velocity_solid_i(i, d);
        }
      });
}

KineticTotals updatePointVelocitiesAndMapMomenta(
    const PointShapes& shapes, const LiquidCarrying& liquid_m, const ActiveNodes& active, Real dt,
    const TransferSettings& transfer, MaterialPoints& points, NodeRecords& records,
    GridFields& grid, const LowParts<GridFields>* compensation) {
  records.allocate(grid.numNodes());
  const auto nodes = active.nodes();
  const auto momentum_solid_i = grid.momentum_solid_i;
  const auto momentum_liquid_i = grid.momentum_liquid_i;
  Kokkos::parallel_for(
      "zero_momenta", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        for (int d = 0; d < kDim; ++d) momentum_solid_i(i, d) = momentum_liquid_i(i, d) = 0;
      });
  KineticTotals totals;
  MaterialPoints points_k = untracked(points);  // the kernel's captures (UntrackedViews.hpp)
  withFamilyAndScheme(shapes, transfer, [&](auto family, auto scheme) {
    totals = updateVelocitiesAndMapMomentaImpl<decltype(family), decltype(scheme)::value>(
        untracked(shapes), liquid_m, active, dt, transfer, points_k, records, grid, compensation);
  });
  return totals;
}

void interpolateVelocityGradients(const MaterialPoints& points, const PointShapes& shapes,
                                  const LiquidCarrying& liquid_m, const ActiveNodes& active,
                                  const GridFields& grid, NodeRecords& records, Real dt,
                                  PointRates& rates,
                                  Kokkos::View<const unsigned char*, MemSpace> conditioned_i,
                                  TransferScheme scheme) {
  if (rates.count() != points.count) rates.allocate(points.count);
  const MaterialPoints points_k = untracked(points);  // the kernel's captures (UntrackedViews.hpp)
  const PointShapes shapes_k = untracked(shapes);
  withShapeFamily(shapes, [&](auto family) {
    if (scheme == TransferScheme::Tpic)
      interpolateVelocityGradientsImpl<decltype(family), true>(
          points_k, shapes_k, liquid_m, active, grid, records, dt, rates, conditioned_i);
    else
      interpolateVelocityGradientsImpl<decltype(family), false>(
          points_k, shapes_k, liquid_m, active, grid, records, dt, rates, conditioned_i);
  });
}

}  // namespace argine

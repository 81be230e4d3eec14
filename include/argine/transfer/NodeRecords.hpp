#pragma once
/// @file NodeRecords.hpp
/// The nodal values the point kernels of the explicit step add or read, packed one row per
/// node: a point reaches all of a node's values through one address at fixed offsets.
///
/// Why: GridFields keeps one View per field (what the nodal solves, the boundary conditions
/// and the output want). A point kernel that adds 13 sums to 4 nodes through 13 Views keeps
/// 13 base pointers and row strides live, more than the registers hold, and reloads them;
/// through one packed row per node it computes one address per node. The P2G kernels add
/// into `sums_i` and the sums are then added to GridFields over the active nodes (one pass
/// over ~1/4 as many nodes as points); the G2P kernels read `values_i`, filled from
/// GridFields over the active nodes just before. Same operations in the same order, so the
/// same values to the bit. Measured on the 1e5-point Mohr-Coulomb block: 2,212 -> 2,139
/// instructions per point update (scripts/count_instructions.sh), about +4 % in time; no
/// gain on the dry block, whose light kernels save less than the node passes cost
/// (doc/scaling.md).

#include "argine/core/Types.hpp"

namespace argine {

class ActiveNodes;
struct GridFields;

/// Slots of a P2G row (NodeRecords::sums_i): the sums of mapPointsToGrid, and the momenta
/// again for the remap of updatePointVelocitiesAndMapMomenta. Vectors take kDim slots. The
/// order puts the four momenta in one aligned block of kLanes slots (slots 4-7), which the
/// remap adds with one vector instruction per node (TwoPhaseTransfer.cpp).
enum NodeSumSlot : int {
  kSumMassSolid = 0,                              ///< M_S (4.40)
  kSumMassLiquid,                                 ///< M_L (4.39)
  kSumMassIntrinsic,                              ///< M~_L (4.38, 4.46)
  kSumDrag,                                       ///< Q_L (4.45)
  kSumMomentumSolid,                              ///< x, y: sum N M_S v_S
  kSumMomentumLiquid = kSumMomentumSolid + kDim,  ///< x, y: sum N rho_L V v_L
  kSumVolumeLiquid = kSumMomentumLiquid + kDim,   ///< sum N V of liquid-carrying points
  kSumForceMixture,                               ///< x, y: mixture f^ext - f^int (4.42, 4.44)
  kSumForceLiquid = kSumForceMixture + kDim,      ///< x, y: liquid f^ext - f^int (4.41, 4.43)
  kSumSlotCount = kSumForceLiquid + kDim
};

/// Whether a P2G slot is one a point without liquid adds to too (the solid and mixture sums).
KOKKOS_INLINE_FUNCTION constexpr bool isSolidSumSlot(int slot) {
  return slot == kSumMassSolid || slot == kSumMomentumSolid || slot == kSumMomentumSolid + 1 ||
         slot == kSumForceMixture || slot == kSumForceMixture + 1;
}

/// Slots of a G2P row (NodeRecords::values_i) as the velocity update reads it.
enum NodeVelocityUpdateSlot : int {
  kReadAccelerationSolid = 0,                               ///< x, y: a_S
  kReadAccelerationLiquid = kReadAccelerationSolid + kDim,  ///< x, y: a_L
  kReadVelocitySolid = kReadAccelerationLiquid + kDim,      ///< x, y: v_S of t^k
  kReadVelocityLiquid = kReadVelocitySolid + kDim,          ///< x, y: v_L of t^k
  kReadVelocityUpdateCount = kReadVelocityLiquid + kDim
};

/// Slots of a G2P row as the strain interpolation reads it.
enum NodeStrainSlot : int {
  kReadStrainVelocitySolid = 0,                                 ///< x, y: v_S of t^{k+1}
  kReadStrainVelocityLiquid = kReadStrainVelocitySolid + kDim,  ///< x, y: v_L of t^{k+1}
  kReadStrainLiquidContent = kReadStrainVelocityLiquid + kDim,  ///< rho_L n S_L (4.16)
  kReadStrainLiquidVolume,  ///< sum N V over liquid-carrying points: who shares the node
  kReadStrainConditioned,   ///< 1 where a hydraulic condition acts on the node, else 0
  kReadStrainCount
};

/// Row widths: 16 and 8 doubles, two and one cache lines.
inline constexpr int kNodeSumRow = 16;
inline constexpr int kNodeReadRow = 8;
static_assert(kSumSlotCount <= kNodeSumRow && kReadVelocityUpdateCount <= kNodeReadRow &&
              kReadStrainCount <= kNodeReadRow);

/// Scratch of the transfer kernels (nothing here is state between steps).
struct NodeRecords {
  Kokkos::View<Real* [kNodeSumRow], MemSpace> sums_i;     ///< zero outside a P2G kernel
  Kokkos::View<Real* [kNodeReadRow], MemSpace> values_i;  ///< filled before each G2P kernel

  /// Sized for `num_nodes` nodes (zeroed); nothing happens when it already is.
  void allocate(int num_nodes);
  int numNodes() const { return static_cast<int>(sums_i.extent(0)); }
};

/// grid += the P2G sums of `records` at the active nodes (every field of NodeSumSlot), and
/// the sums back to zero there.
void addNodeSumsToGrid(const ActiveNodes& active, NodeRecords& records, GridFields& grid);
/// The same for the momenta alone (the remap).
void addMomentumSumsToGrid(const ActiveNodes& active, NodeRecords& records, GridFields& grid);
/// values_i = a_S, a_L, v_S, v_L of `grid` at the active nodes (NodeVelocityUpdateSlot).
void readVelocityUpdateValues(const ActiveNodes& active, const GridFields& grid,
                              NodeRecords& records);
/// values_i = v_S, v_L, rho_L n S_L, sum N V of `grid` and the flag of `conditioned_i` (1
/// where a hydraulic condition acts; none when empty) at the active nodes (NodeStrainSlot).
void readStrainValues(const ActiveNodes& active, const GridFields& grid,
                      Kokkos::View<const unsigned char*, MemSpace> conditioned_i,
                      NodeRecords& records);

}  // namespace argine

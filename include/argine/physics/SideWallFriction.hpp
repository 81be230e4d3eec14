#pragma once
/// @file SideWallFriction.hpp
/// The side walls of a quasi-2D channel on the explicit step (deck `side walls`,
/// boundary/SideWalls.hpp for the formulas, doc/theory.md Sec. 5.7). Per step:
///  1. mapResistance (after the P2G of the masses): each node's wall resistance
///     R_i = sum_p N_ip V_p 2 mu max(-sigma'_zz,p, 0) / W (N), from the points' state at t^k;
///  2. constrainAccelerations (after the fixities and the frictional walls, once a step):
///     the trial solid velocity v* = v_S + dt a_S loses dt R_i / (s M) of its speed against
///     its direction, or stops (stick), with M the mass whose momentum the walls act on (the
///     solid's; solid and liquid when the liquid moves with the solid) and s the mass
///     scaling; a_S = (v' - v_S) / dt. The liquid equation (4.36) is untouched: the walls
///     hold the skeleton, the pore liquid slides along them;
///  3. holdStuckNodes (the velocity form, after the remap): a node the walls stopped stays
///     at rest, as a stuck frictional-wall node does (FLIP's remap would move it).
/// Scaling a velocity towards zero keeps every fixity and wall condition it met, so the
/// order after them is safe. In fixed-skeleton stages nothing moves and nothing is done.

#include <optional>

#include "argine/boundary/SideWalls.hpp"
#include "argine/core/Types.hpp"
#include "argine/transfer/CompensatedSum.hpp"

namespace argine {

class ActiveNodes;
class NodalExchange;
struct PointShapes;
struct GridFields;
struct MaterialPoints;
struct MomentumSettings;

class SideWallFriction {
 public:
  SideWallFriction() = default;
  /// The walls of a stage (none: nothing is done), for a mesh of `num_nodes` nodes.
  void configure(const std::optional<SideWallParameters>& walls, int num_nodes);
  bool active() const { return active_; }

  /// Step 1 on the nodes `active` (zeroed there first); with `exchange` the sums are
  /// completed at shared nodes, binned when `reproducible` (same bits on any number of
  /// ranks).
  void mapResistance(const MaterialPoints& points, const PointShapes& shapes,
                     const ActiveNodes& active, NodalExchange* exchange, bool reproducible);
  /// Step 2 on `grid`'s accelerations for a step `dt` > 0.
  void constrainAccelerations(const ActiveNodes& active, const MomentumSettings& settings, Real dt,
                              GridFields& grid);
  /// Step 3 on `grid`'s velocities.
  void holdStuckNodes(const ActiveNodes& active, const MomentumSettings& settings,
                      GridFields& grid) const;

  /// R_i (N) of the last mapResistance, for tests.
  Kokkos::View<const Real*, MemSpace> resistance() const { return resistance_i_; }
  /// 1 where the last constrainAccelerations stopped the node.
  Kokkos::View<const unsigned char*, MemSpace> stuck() const { return stuck_i_; }

 private:
  bool active_ = false;
  SideWallParameters walls_;
  Kokkos::View<Real*, MemSpace> resistance_i_;
  LowParts<Kokkos::View<Real*, MemSpace>> resistance_lo_;  ///< low parts of the binned sums
  Kokkos::View<unsigned char*, MemSpace> stuck_i_;
};

}  // namespace argine

#pragma once
/// @file PointBorneLoads.hpp
/// The hydraulic loads (4.50 into 4.41 and 4.42) applied at the soil's surface through its
/// boundary points, for a background mesh that does not follow the surface (a soil region
/// in a `rectangle` grid, a body that has moved through its mesh): `Hydraulic Loads: at
/// boundary points` (doc/theory.md Sec. 5.5, "Loads where the mesh does not follow the
/// surface").
///
/// The plan (HydraulicConditions) integrates the pressure along the free sides, a staircase
/// of element edges that can lie up to an element outside the soil, and gives each side's
/// load to the side's end nodes. Where a cell is partly filled, such a node is carried by
/// the few points near it, which must then balance all of the load: in the grid levee the
/// river's head put +70 kPa on a point whose hydrostatic value is 16 kPa. Here each node's
/// planned load L_i goes to the points that see it, in proportion to their share of the
/// node's mass (w_p N_i(x_p) / sum_q w_q N_i(x_q), the mixture's mass for f^ext, the liquid
/// volume for f_L^ext), and each point passes its share on to its nodes with its shape
/// functions evaluated at its outer edge, half its size beyond its centre along the outward
/// normal (4.51): N_j(x_p + l n) = N_j(x_p) + l n . grad N_j(x_p), l = sqrt(V_p) / 2. Both
/// weights sum to one, so each load's resultant is kept to round-off.
///
/// The nodes' sums of the weights are the lumped masses of the step's P2G (M_S + M_L and
/// the liquid-carrying points' sum N V, GridFields), already complete over the ranks.
/// Several ranks: the plan is replicated, so every rank holds each node's whole load; the
/// spread loads are summed at the shared nodes afterwards, binned under `Reproducible Sums`
/// (transfer/CompensatedSum.hpp) so that 1 and N ranks give the same bits.

#include "argine/boundary/BoundaryConditions.hpp"
#include "argine/core/Types.hpp"
#include "argine/transfer/CompensatedSum.hpp"

namespace argine {

class ActiveNodes;
class NodalExchange;
struct BoundaryGradientFields;
struct GridFields;
struct MaterialPoints;
struct PointShapes;

/// Nodal work fields of the point-borne loads ("_i": one entry per mesh node).
struct PointBorneLoadFields {
  /// The planned load of each node: mixture (f^ext) components, then liquid (f_L^ext) (N).
  Kokkos::View<Real * [2 * kDim], MemSpace> load_i;
  /// The loads as the points pass them on, laid out as load_i (N).
  Kokkos::View<Real**, MemSpace> spread_i;
  /// The low parts of spread_i's sums when they are compensated (empty otherwise).
  LowParts<Kokkos::View<Real**, MemSpace>> spread_lo;
  void allocate(int num_nodes);
  /// Reproducible (binned) sums into spread_i from now on, or plain ones.
  void compensateSums(bool on);
  bool compensated() const { return compensated_; }
  /// Zero on the listed nodes only.
  void zero(const ActiveNodes& nodes);

 private:
  bool compensated_ = false;
};

/// The planned `loads` into fields.load_i, and each point's share of its nodes' loads
/// (by its part of the nodes' lumped masses in `grid`), passed on with its shape functions at
/// its outer edge (outward normal from `boundary`.mass_gradient_i, complete over the ranks)
/// into fields.spread_i; zero `fields` on the active nodes first. Sum spread_i over the
/// ranks after (sumPointBorneLoadsAtSharedNodes).
void spreadPointBorneLoads(const NodalLoads& loads, const MaterialPoints& points,
                           const PointShapes& shapes,
                           const Kokkos::View<const int*, MemSpace>& liquid_m,
                           const BoundaryGradientFields& boundary, const GridFields& grid,
                           PointBorneLoadFields& fields);

/// Completes spread_i: summed over the ranks at the shared nodes (`exchange`, null on one
/// rank) and, when compensated, folded on the active nodes.
void sumPointBorneLoadsAtSharedNodes(NodalExchange* exchange, const ActiveNodes& active,
                                     PointBorneLoadFields& fields);

/// Adds spread_i to f^ext and f_L^ext of the active nodes that carry solid mass (the liquid
/// part where they carry liquid), as addHydraulicLoads does with the planned loads.
void addPointBorneLoads(const PointBorneLoadFields& fields, const ActiveNodes& nodes,
                        GridFields& grid);

/// The reach l of a point's outer edge beyond its centre: half the side of a square of its
/// area V (m^2 per metre in plane strain), l = sqrt(V) / 2 (m).
KOKKOS_INLINE_FUNCTION Real pointEdgeReach(Real volume) {
  return volume > 0 ? Real(0.5) * Kokkos::Experimental::sqrt(volume) : Real(0);
}

}  // namespace argine

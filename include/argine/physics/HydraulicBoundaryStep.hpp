#pragma once
/// @file HydraulicBoundaryStep.hpp
/// The grid kernels of the hydraulic boundary conditions on the moving free boundary
/// (thesis Sec. 4.1-4.3), called by ExplicitTwoPhaseSolver at these points of the Sec. 3.3
/// step:
///   after the P2G at t^k  mapBoundaryGradients     4.51 mass gradient, n_L = n S_L at the
///                                                  nodes, the flux weights G_i (below)
///                         addHydraulicLoads        head / pressure loads into f_L^ext (4.41)
///                                                  and f^ext (4.42)
///   after steps 1-2       correctHydraulicAccelerations   predictor-corrector 4.53-4.59
///   after step 4 (remap)  correctHydraulicVelocities      the same correction re-imposed on
///                                                  the remapped nodal velocities
///   after step 4          boundaryFluxMasses       liquid mass through each condition, all
///                                                  nodes and the nodes inside the body
///
/// Flux accounting. The point mass balance (PointUpdates, LiquidState) changes a point's
/// liquid mass by -dt V_p div(c w) (complete form, c = rho_L n S_L from the nodes, the
/// advective term at the element centre) or -dt M_L,p div w (simplified), with w_i = v_L - v_S
/// at the nodes. Both are linear in the nodal w_i, so the total change is exactly
/// -dt sum_i w_i . G_i with
///   complete:    G_i = sum_p V_p (c_centre grad N_i(x_p) + N_i(centre) grad c(x_p)) on
///                the element families; on the grid families every N and grad N is that of
///                the bilinear shapes of the point's cell at its centre (fluxCentre)
///   simplified:  G_i = sum_p M_L,p grad N_i(x_p)
/// (the content-weighted form of the unnormalised 4.51 vector). G_i vanishes at nodes whose
/// support is filled with soil (exactly for Tri3 with full elements), so the sum is the flux
/// through the boundary; the sum over the nodes a condition owns is its share.
///
/// Normals. mapBoundaryGradients computes the mass-gradient normal (4.51) at every node;
/// the corrections use instead the normal of the correcting condition's OWN sides at the
/// node (sum of n L / 2, normalised; FluxCorrectionList::normal). The two agree on a smooth
/// surface, but at a corner where the condition covers one face only (the top corners of a
/// column with sealed sides) 4.51 is diagonal, and correcting only the component of w along
/// it leaves the tangential part, which crosses the face: a rain column measured 1000 x the
/// rain through its top with 4.51. The side normals say where the condition is; the flux
/// correction itself acts along the flux weight G_i (restricted to the directions no
/// impermeable lock holds, fluxWeightCorrection): the node's flux is w . G_i, so that is the
/// smallest correction that sets it. On the condition's face of full elements G_i is
/// parallel to the side normals (the thesis form); on a deformed body it need not be, and a
/// correction along the side normals divides by n . G_i, unbounded as they turn
/// perpendicular (a crack opening in the levee drawdown slide: ~1000 m/s in one step).

#include <vector>

#include "argine/boundary/HydraulicConditions.hpp"
#include "argine/core/Types.hpp"
#include "argine/transfer/CompensatedSum.hpp"

namespace argine {

class ActiveNodes;
struct GridFields;
struct MaterialPoints;
struct PointShapes;
struct PointMaterial;

/// Nodal fields of the hydraulic conditions ("_i": one entry per mesh node).
struct BoundaryGradientFields {
  Kokkos::View<Real* [kDim], MemSpace> mass_gradient_i;  ///< sum_p m_m grad N_i (4.51), outward
  Kokkos::View<Real* [kDim], MemSpace> flux_weight_i;    ///< G_i (kg/m^2 per m thickness)
  Kokkos::View<Real*, MemSpace> wet_volume_i;            ///< sum_p N_i n S_L V (m^3)
  /// `Free Surface Liquid Pressure: suction held` only (FreeSurfaceSuction.hpp), else not
  /// mapped: sum_p V grad N_i of the liquid-carrying points (m^2 per m thickness) ...
  Kokkos::View<Real* [kDim], MemSpace> volume_gradient_i;
  Kokkos::View<Real*, MemSpace> pressure_volume_i;  ///< ... and sum_p N_i p_L V (Pa m^3)
  bool with_surface_pressure = false;               ///< whether the two above are mapped
  void allocate(int num_nodes);
  /// Zero on the listed nodes only.
  void zero(const ActiveNodes& nodes);
};

/// Reproducible sums: mapBoundaryGradients' binned sums, complete over the ranks, folded
/// with their low parts at the listed nodes (transfer/CompensatedSum.hpp).
void foldCompensatedBoundarySums(const ActiveNodes& nodes, BoundaryGradientFields& fields,
                                 const LowParts<BoundaryGradientFields>& lo);

/// The outward unit normal of a node from its mass gradient (4.51); zero when the gradient
/// vanishes. Note the sign: sum_p m_p grad N_i(x_p) points OUT of the body at a boundary
/// node (N_i grows towards its node, which lies on the surface), i.e. opposite to the
/// gradient of the nodal mass field sum_i m_i grad N_i, which points inward.
KOKKOS_INLINE_FUNCTION void outwardNormalOfMassGradient(const Real gradient[kDim],
                                                        Real normal[kDim]) {
  const Real length =
      Kokkos::Experimental::sqrt(gradient[0] * gradient[0] + gradient[1] * gradient[1]);
  for (int d = 0; d < kDim; ++d) normal[d] = length > 0 ? gradient[d] / length : 0;
}

/// P2G at t^k of the mass gradient, wet volume and flux weights; `grid` must hold the nodal
/// liquid content of t^k (computeNodalVelocities). Zero `fields` on the active nodes first.
/// With `compensation` (reproducible sums) binned, as mapPointsToGrid.
void mapBoundaryGradients(const MaterialPoints& points, const PointShapes& shapes,
                          const Kokkos::View<const PointMaterial*, MemSpace>& materials_m,
                          const Kokkos::View<const int*, MemSpace>& liquid_m,
                          const GridFields& grid, BoundaryGradientFields& fields,
                          const LowParts<BoundaryGradientFields>* compensation = nullptr);

/// Adds the loads to f^ext and f_L^ext of the nodes that carry solid mass.
void addHydraulicLoads(const NodalLoads& loads, GridFields& grid);

/// Sec. 4.2 steps 2-5 at the correction nodes: predicted v~ = v^k + a dt, q_net (4.53), the
/// switch (correctionApplies), and the corrected accelerations a += dv / dt (4.58, 4.59).
/// Marks corrections.applied. `solid_moves` false in fixed-skeleton stages (4.56).
/// The node's flux is measured with its flux weight G_i (fluxWeightCorrection), so that the
/// liquid the point mass balance lets through the node is exactly the prescribed one;
/// `liquid_density` (kg/m^3) is the reference rho_L that converts G_i to volumes.
/// `constraints` (optional): per entry of `corrections`, the node's NodalConstraintBits: the
/// correction leaves the impermeable-locked directions alone (fluxWeightCorrection) and puts
/// all of the relative change into the liquid where the solid is fixed
/// (correctionOfMeasuredFlux; the fixity applied afterwards would undo a solid share).
void correctHydraulicAccelerations(const FluxCorrectionList& corrections,
                                   const BoundaryGradientFields& fields, Real dt, bool solid_moves,
                                   Real liquid_density, GridFields& grid,
                                   Kokkos::View<const unsigned*, MemSpace> constraints = {});

/// Re-imposes the applied corrections on the remapped nodal velocities v^{k+1}, so the
/// relative flux used by the mass balance is the prescribed one (`constraints` as above).
void correctHydraulicVelocities(const FluxCorrectionList& corrections,
                                const BoundaryGradientFields& fields, bool solid_moves,
                                Real liquid_density, GridFields& grid,
                                Kokkos::View<const unsigned*, MemSpace> constraints = {});

/// The flags of a node's free sides (ExplicitTwoPhaseSolver's free-side node flags).
enum FreeSideNodeBits : unsigned char {
  kNodeOnFreeSide = 1,  ///< an end node of a free side
  kNodeOnOpenSide = 2   ///< ... of a free side no impermeable condition seals
};

/// -dt w_i . G_i (kg per m thickness), w_i = v_L - v_S: the liquid mass the point mass balance
/// gives the points at node i this step (the "Flux accounting" above).
template <class Velocities, class Weights>
KOKKOS_INLINE_FUNCTION Real pointBalanceInflowAtNode(Real dt, const Velocities& velocity_liquid,
                                                     const Velocities& velocity_solid,
                                                     const Weights& flux_weight, int i) {
  Real sum = 0;
  for (int d = 0; d < kDim; ++d)
    sum -= dt * (velocity_liquid(i, d) - velocity_solid(i, d)) * flux_weight(i, d);
  return sum;
}

/// Liquid mass (kg per m thickness) that entered the soil this step through the nodes of
/// each condition: -dt sum_{i owned} w_i . G_i, entries [0, conditions); entry [conditions]
/// is the same sum over ALL active nodes (= the change of the points' liquid mass); entry
/// [conditions + 1] the sum over the active nodes on no side of the free boundary
/// (`free_side`: kNodeOnFreeSide at the nodes of its sides; empty: none), where G_i would vanish if
/// the points filled their cells evenly: the liquid the point mass balance makes inside the body
/// (doc/theory.md Sec. 5.5, "Flux accounting"). `returned_i` (one entry per mesh node; empty:
/// none): the mass the points gave back at each node this step (`Interior Liquid Balance:
/// conservative`, InteriorLiquidBalance.hpp), taken off that node's inflow, so the entries stay the
/// points' actual change. `rank_owned` (several MPI ranks): 1 at the nodes this rank owns; the
/// condition sums then count only those (each node on one rank), as `active` does for the total.
/// Empty: all. With `compensation` (reproducible sums) each entry is a reproducible sum, in
/// (*compensation)[entry], and its value is returned.
std::vector<Real> boundaryFluxMasses(const NodeOwnership& ownership, int conditions,
                                     const ActiveNodes& active,
                                     Kokkos::View<const unsigned char*, MemSpace> free_side,
                                     const BoundaryGradientFields& fields, const GridFields& grid,
                                     Real dt, Kokkos::View<const Real*, MemSpace> returned_i = {},
                                     Kokkos::View<const unsigned char*, MemSpace> rank_owned = {},
                                     std::vector<CompensatedReal>* compensation = nullptr);

}  // namespace argine

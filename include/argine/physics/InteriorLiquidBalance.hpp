#pragma once
/// @file InteriorLiquidBalance.hpp
/// `Interior Liquid Balance: conservative` (stage key): the liquid that the point mass
/// balance makes at nodes inside the body is given back by the points around those nodes.
///
/// Why. A point's liquid changes by -dt V_p div(c w) (complete form; simplified -dt M_L div w)
/// with w = v_L - v_S read from the nodes. Both are linear in the nodal w_i, so the step's
/// total change is -dt sum_i w_i . G_i (HydraulicBoundaryStep.hpp, "Flux accounting"). G_i
/// vanishes at a node whose cells its points fill evenly. Where they do not (a crack at the
/// tension cut-off filled with liquid, a swollen or half-emptied cell of a slide) it does not,
/// and the point balance makes or destroys liquid at a node no boundary passes through
/// (`net_inflow_interior_nodes`): 2.40 L/m into the default levee while its river drains it,
/// and most of the swelling that stops the finest grid slide first (doc/verification.md,
/// "Where the sliding mass's water comes from").
///
/// What. A node is closed when it is active, on no open side of the free boundary and under
/// no hydraulic condition: inside the body, or on sides that impermeable conditions seal
/// (HydraulicConditions::sealsSide: a sealed base, a symmetry axis), where no liquid can
/// enter or leave the model. (At a sealed node the lock holds the normal part of w only,
/// and G_i of unevenly filled cells has a tangential part: liquid passed there too.) At
/// each closed node the step's m_i = -dt w_i . G_i is taken back from the points that carry
/// the node, each its share N_i(x_p) n S_L V_p / W_i of it, W_i = sum_q N_i(x_q) n S_L V_q
/// (the wet volume mapBoundaryGradients sums, complete over the ranks). The shares of a node
/// sum to m_i, so the body's liquid changes only at its boundary and through its conditions,
/// as the weak (Galerkin) balance, whose nodal fluxes sum to zero because sum_i grad N_i = 0,
/// would have it. Where the cells are evenly filled G_i = 0 and nothing changes: the point
/// balance is the thesis' (4.12) there. Where they are not, the liquid a point's own
/// divergence brings is spread over the node's support, one cell each way, by wet volume and
/// not by pressure: where w_i . G_i stays non-zero at rest it keeps moving liquid between the
/// node's points (3 crest points of the default levee dried past the physical p_L range;
/// doc/theory.md Sec. 5.5, "Measured limit"). What kept w_i . G_i non-zero there is the
/// air's pull on the water at part-filled cells at suction; with `Free Surface Liquid
/// Pressure: suction held` (FreeSurfaceSuction.hpp) beside the closure no point leaves the
/// range.
/// `point` (the default, the thesis): no correction.

#include "argine/core/Types.hpp"

namespace argine {

class ActiveNodes;
class MaterialTable;
struct BoundaryGradientFields;
struct GridFields;
struct MaterialPoints;
struct PointRates;
struct PointShapes;

/// made_i (kg per m thickness): -dt w_i . G_i at the active nodes that `free_side`
/// (FreeSideNodeBits; empty: none) and `conditioned` (1 at the nodes of a hydraulic
/// condition; empty: none) leave closed, 0 at the other active nodes. `made_i` has one entry
/// per mesh node.
void liquidMadeAtClosedNodes(const ActiveNodes& active,
                             Kokkos::View<const unsigned char*, MemSpace> free_side,
                             Kokkos::View<const unsigned char*, MemSpace> conditioned,
                             const BoundaryGradientFields& fields, const GridFields& grid, Real dt,
                             Kokkos::View<Real*, MemSpace> made_i);

/// Each wet point p gives back sum_a N_a(x_p) n S_L V_p made_a / W_a of the nodes of its
/// shape functions (addPointLiquidMassChange, before the point update).
void returnLiquidMadeInside(const MaterialTable& table, const MaterialPoints& points,
                            const PointShapes& shapes, const BoundaryGradientFields& fields,
                            Kokkos::View<const Real*, MemSpace> made_i, PointRates& rates);

}  // namespace argine

#pragma once
/// @file FreeSurfaceSuction.hpp
/// `Free Surface Liquid Pressure: suction held` (stage key): where the soil's liquid is at
/// suction, the free surface carries that suction, not p_L = 0.
///
/// Why. The liquid's internal force at node i is sum_p p_L V grad N_i (4.43): its natural
/// condition is p_L = 0 wherever the points end, on the mesh's free sides and inside
/// part-filled cells alike (a crest whose top cells have settled, a crack at the tension
/// cut-off, a cell a slide has half left). With a uniform p_L < 0 the force is p_L sum_p V
/// grad N_i, which points into the soil: the air pulls on the soil's water as if a film of
/// water at p_L = 0 covered every such surface. The atmosphere (Sec. 5.5) corrects the flux
/// at the nodes of the free sides, but a node one row in, whose support a part-filled cell
/// cuts, carries part of the surface in sum_p V grad N_i and is corrected by nothing: the
/// point balance makes water there (`net_inflow_interior_nodes`), and with `Interior Liquid
/// Balance: conservative` the water it cannot make is taken from the points instead, which
/// dries them further and pulls harder (3 crest points of the default levee past the physical
/// p_L range, doc/theory.md Sec. 5.5, "Measured limit").
///
/// What. The surface's liquid pressure is pi_i = min(0, pbar_i), pbar_i = sum_p N_i p_L V /
/// sum_p N_i V the node's liquid pressure: at suction the menisci at the surface hold it and
/// the air pulls on nothing; at p_L >= 0 the surface is at the air's pressure, p_L = 0, and
/// water leaves (the thesis). The internal force becomes sum_p (p_L - pi_i) V grad N_i, i.e.
/// f_L,i -= pi_i sum_p V grad N_i. Inside a body that fills its cells sum_p V grad N_i = 0
/// (the integral of grad N_i over the node's support), so nothing changes there; only the
/// nodes whose support a surface cuts see it. The nodes of a hydraulic condition keep the
/// condition's surface pressure (its loads, 4.50). `zero` (the default): the thesis.
///
/// Only with `Interior Liquid Balance: conservative` (the deck refuses it alone): the term
/// subtracted here has the closure's share (InteriorLiquidBalance.hpp) as its transpose, so
/// the pair keeps the pressure force the transpose of the point balance's divergence, on
/// which the explicit step's energy rests; alone it went unstable on the Tri3 levee at
/// 0.1 m with any step (doc/theory.md Sec. 5.5, "Only with the closure").

#include "argine/core/Types.hpp"

namespace argine {

class ActiveNodes;
struct BoundaryGradientFields;
struct GridFields;

/// pi_i = min(0, pressure_volume_i / volume), the surface's liquid pressure at a node (Pa):
/// the node's liquid pressure where it is at suction, 0 where it is not or has no liquid.
KOKKOS_INLINE_FUNCTION Real surfaceLiquidPressure(Real pressure_volume, Real volume) {
  if (!(volume > 0)) return 0;
  const Real pressure = pressure_volume / volume;
  return pressure < 0 ? pressure : 0;
}

/// f_L,i -= pi_i sum_p V grad N_i at the active nodes not under a hydraulic condition
/// (`conditioned`: 1 at a condition's nodes; empty: none). `fields` must hold
/// volume_gradient_i and pressure_volume_i complete over the ranks (with_surface_pressure).
void holdSuctionAtFreeSurfaces(const ActiveNodes& active,
                               Kokkos::View<const unsigned char*, MemSpace> conditioned,
                               const BoundaryGradientFields& fields, GridFields& grid);

}  // namespace argine

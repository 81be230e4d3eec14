#pragma once
/// @file TwoPhaseTransfer.hpp
/// The particle <-> grid kernels of the explicit two-phase step (thesis Sec. 3.2-3.3).
/// P2G kernels scatter into the packed rows of NodeRecords with
/// Kokkos::Experimental::ScatterView (plain adds on Serial, duplicated on OpenMP, atomics on
/// CUDA) and add them to GridFields at the active nodes; G2P kernels read packed rows filled
/// from GridFields at the active nodes (NodeRecords.hpp: why). The active nodes must include
/// every node of every element holding a point. Every kernel is a template on the element's
/// node count, chosen once per call from PointShapes::type.
///
/// Dry points (their material carries no liquid, `liquid_m(material) == 0`) add nothing to
/// the liquid fields, so a node touched only by dry points has no liquid mass and the
/// physics skips its liquid equation. Points with element < 0 (lost) are skipped.
///
/// Sign conventions: stresses tension positive, p_L compression positive. Bishop total
/// stress (4.5, chi = S_L): sigma = sigma' - S_L p_L m.

#include "argine/core/Types.hpp"
#include "argine/transfer/CompensatedSum.hpp"
#include "argine/transfer/TransferScheme.hpp"

namespace argine {

class ActiveNodes;
struct GridFields;
struct NodeRecords;
struct MaterialPoints;
struct PointRates;
struct PointShapes;

/// 1 for materials that carry liquid (saturated, unsaturated), 0 for dry ones; indexed by
/// the point's material id.
using LiquidCarrying = Kokkos::View<const int*, MemSpace>;

/// P2G of the step's left- and right-hand sides, all at time t^k: lumped masses M_S, M_L,
/// M~_L (4.38-4.40), lumped drag Q_L (4.45, k from the point's conductivity and
/// g = 9.81 m/s^2, the g that defines k), momenta, internal forces (4.43, 4.44) and gravity
/// (4.41, 4.42; `gravity` in m/s^2 acting in -y). Boundary loads are added afterwards by the
/// boundary conditions. The grid must be zero on the nodes the points touch. With
/// `compensation` (reproducible sums, CompensatedSum.hpp) the sums are binned, their low
/// parts in the same fields of `compensation` (zero there too), to be folded once complete.
/// With APIC (`transfer`) the momenta are sum N m (v_p + C_p (x_i - x_p)).
void mapPointsToGrid(const MaterialPoints& points, const PointShapes& shapes,
                     const LiquidCarrying& liquid_m, Real gravity, const TransferSettings& transfer,
                     const ActiveNodes& active, NodeRecords& records, GridFields& grid,
                     const LowParts<GridFields>* compensation = nullptr);

/// Nodal velocities v = momentum / mass and the nodal liquid content rho_L n S_L =
/// M_L / (sum N V) (4.16) on the active nodes. A node without liquid mass gets v_L = v_S.
void computeNodalVelocities(const ActiveNodes& active, GridFields& grid);

/// The grid's own update of the nodal velocities, v~_i = v_i + dt a_i for both phases, on the
/// active nodes (a node without liquid mass: v~_L = v~_S): what APIC interpolates to the
/// points. The caller imposes the velocity conditions on them next.
void advanceNodalVelocities(const ActiveNodes& active, Real dt, GridFields& grid);

/// Kinetic sums of the updated point velocities.
struct KineticTotals {
  Real solid = 0;             ///< sum 1/2 M_S |v_S|^2 (J per m thickness)
  Real liquid = 0;            ///< sum 1/2 M_L |v_L|^2 with the M_L of t^k (J per m)
  int non_finite_points = 0;  ///< points whose updated velocity is not finite
};

/// Sec. 3.3 steps 3-4 in one pass over the points. FLIP: the G2P of the nodal accelerations,
/// v_p += dt sum N a_i for the solid and, at liquid-carrying points, the liquid (Euler-Cromer
/// 7.10, 7.11), blended with a PIC update when `transfer.blend` asks for it (VelocityBlend; the
/// nodal velocities v_i are those of t^k that the drag used, not constrained: a fixed node's zero
/// solid velocity against its points' FLIP velocity would otherwise feed the difference into
/// the liquid's relative velocity every step). APIC: v_p = sum N v~_i (a phase's with a FLIP
/// share when `transfer.blend` sets its rate, VelocityBlend) and C_p = sum v~_i (grad N_i)^T of
/// each phase, v~_i the grid velocities of advanceNodalVelocities (in the
/// velocity slots of GridFields, conditions imposed). Then the P2G of the updated momenta
/// sum N M_S v_S and sum N rho_L V v_L (APIC: with C_p (x_i - x_p) added to v_p) into the
/// (first zeroed) nodal momenta of the active nodes (binned as mapPointsToGrid with
/// `compensation`, whose momenta must be zero on the active nodes). Call
/// computeNodalVelocities next (after folding, when binned).
/// Returns the kinetic energies of the new velocities.
KineticTotals updatePointVelocitiesAndMapMomenta(
    const PointShapes& shapes, const LiquidCarrying& liquid_m, const ActiveNodes& active, Real dt,
    const TransferSettings& transfer, MaterialPoints& points, NodeRecords& records,
    GridFields& grid, const LowParts<GridFields>* compensation = nullptr);

/// G2P of the nodal velocities (Sec. 3.3 step 4): strain increment dt sym(grad v_S) (2.17),
/// spin increment dt skew(grad v_S) (the Jaumann rotation, ObjectiveStressRate.hpp),
/// dt div v_L and the liquid flux divergence dt div(c w), c = rho_L n S_L, w = v_L - v_S, at
/// the liquid-carrying points (4.11-4.12 with the advective-gradient term 4.15-4.16; c from
/// the nodal liquid content), and
/// the displacement increment dt sum N v_S (7.13). A liquid-carrying point alone (every node
/// it touches carries only its own liquid volume, sum N V = its N V, and none is under a
/// hydraulic condition, `conditioned_i`) exchanges no liquid: there is no other point to take
/// or give it, and the grid's relative velocity at its nodes is its own pressure pushing
/// liquid to and fro between itself and empty space (measured: a saturated point resting on a
/// floor gained and lost 1e-4 of its liquid as it vibrated, an unsaturated one drew water
/// out of the air). Its relative flux is none (no content flux, div v_L = div v_S), so its
/// liquid mass stays and its p_L is what its own volume change gives. `rates` is reallocated
/// if needed. With TPIC (`scheme`) the velocity gradients of both phases become the points'
/// affine matrices C_p (TransferScheme.hpp).
void interpolateVelocityGradients(const MaterialPoints& points, const PointShapes& shapes,
                                  const LiquidCarrying& liquid_m, const ActiveNodes& active,
                                  const GridFields& grid, NodeRecords& records, Real dt,
                                  PointRates& rates,
                                  Kokkos::View<const unsigned char*, MemSpace> conditioned_i = {},
                                  TransferScheme scheme = TransferScheme::Flip);

}  // namespace argine

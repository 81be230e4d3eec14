#pragma once
/// @file XpicFilter.hpp
/// The grid half of the XPIC(m) velocity update (TransferScheme::Xpic; Hammerquist and Nairn
/// 2017, Comput. Methods Appl. Mech. Engrg. 318, 724-738).
///
/// With S the P2G of point velocities (v_i = sum_p N_ip m_p v_p / m_i, lumped masses; the
/// liquid weighted by rho_L V, as the nodal velocities of t^k are) and S+ the G2P (v_p =
/// sum_i N_ip v_i), PIC keeps P v_p of the point velocities, P = S+ S, FLIP all of v_p. XPIC(m)
/// keeps the truncated series
///   [I - (I - P)^m] v_p = sum_{k=1..m} (-1)^(k+1) C(m, k) P^k v_p = S+ v*,
///   v* = sum_{k=1..m} (-1)^(k+1) C(m, k) v^(k),  v^(1) = S v_p,  v^(k+1) = S S+ v^(k):
/// a mode of P's eigenvalue lambda keeps 1 - (1 - lambda)^m of itself each step. The grid's
/// blind part (lambda = 0, S v = 0, FLIP's noise) goes at once, as with PIC; a resolved
/// mode (lambda = 1 - eps) loses eps^m instead of PIC's eps. Momentum is kept:
/// sum_p m_p (S+ v)_p = sum_i m_i v_i for any nodal v (partition of unity, lumped masses), so
/// every v^(k) carries the momentum of v_p and the coefficients sum to 1.
///
/// The binomial series is the Neumann series of x = (S S+)^-1 v^(1) (the consistent-mass
/// projection, XPIC's m -> infinity) cut after m terms. With a lower eigenvalue a in (0, 1)
/// the same m - 1 round trips take the Chebyshev polynomial instead: the Chebyshev iteration
/// for that solve on [a, 1], run twice for k = (m - 1) / 2 steps each, then j = m - 2k plain
/// steps, so a mode keeps 1 - (1 - lambda)^j s_k(lambda)^2 of itself,
///   s_k(lambda) = T_k((1 + a - 2 lambda) / (1 - a)) / T_k((1 + a) / (1 - a)),
/// T_k the Chebyshev polynomial: every mode of lambda >= a keeps at least 1 - 1/T_k(...)^2
/// (m = 9, a = 0.05: 90.5 %; the binomial series keeps 37 % at lambda = 0.05), the blind part
/// still goes at once, no mode is amplified (the kept share lies in [0, 1] on [0, 1]) and the
/// rigid mode (lambda = 1) is kept whole, so the momentum is too. The squared s_k is what keeps
/// the share <= 1: a single T_m would overshoot by up to 1/T_m, a growth every step.

#include <functional>

#include "argine/core/Types.hpp"
#include "argine/transfer/CompensatedSum.hpp"
#include "argine/transfer/TwoPhaseTransfer.hpp"

namespace argine {

/// Work space of filterNodalVelocitiesXpic, sized on first use.
struct XpicScratch {
  Kokkos::View<Real * [2 * kDim], MemSpace> filtered_i;  ///< v* of the solid, then the liquid
  /// Chebyshev: the solve's residual, its direction and the round trip's product
  Kokkos::View<Real * [2 * kDim], MemSpace> residual_i, direction_i, product_i;
  Kokkos::View<Real*[kDim], MemSpace> velocity_solid_p, velocity_liquid_p;  ///< the points' own
};

/// Replaces the nodal velocities of t^k (computeNodalVelocities; the velocity fields of
/// `grid` at the active nodes, both phases) by v* of XPIC(m) with `polynomial` (m = 1 leaves
/// them: XPIC(1) is PIC). Each of the m - 1 passes is a PIC round trip of the current
/// iterate: the G2P to the points and the P2G of their momenta (updatePointVelocitiesAndMapMomenta
/// with TPIC, binned with `compensation` as the remap), then `complete_momenta` (the sums over
/// the ranks and the folding of the binned sums; may be empty) and computeNodalVelocities.
/// The points' velocities are as they were after the call; the grid's momenta are not the
/// points' (the remap that follows recomputes them). Call between the nodal solve and the
/// FLIP update with both PIC shares 1.
void filterNodalVelocitiesXpic(const XpicPolynomial& polynomial, const PointShapes& shapes,
                               const LiquidCarrying& liquid_m, const ActiveNodes& active,
                               MaterialPoints& points, NodeRecords& records, GridFields& grid,
                               XpicScratch& scratch, const LowParts<GridFields>* compensation,
                               const std::function<void()>& complete_momenta);

}  // namespace argine

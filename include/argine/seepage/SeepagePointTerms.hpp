#pragma once
/// @file SeepagePointTerms.hpp
/// What one material point contributes to the implicit liquid mass balance (the Richards-type
/// equation of the implicit path, doc/theory.md "The implicit path"):
///
///   d(n S_L rho_L)/dt + div(rho_L w) = 0,   w = -(k / (rho_L0 g_k)) (grad p_L + rho_L g e_y),
///
/// p_L compression positive, gravity g acting in -y, k the hydraulic conductivity of the HCC
/// (defined with g_k = 9.81 m/s^2 and rho_L0, ConductivityCurve.hpp), so k/(rho_L0 g_k) =
/// kappa/mu_L. Hydrostatic p_L = p_0 - rho_L g y gives w = 0. Galerkin with the background
/// mesh's shape functions N_a and the material points as quadrature points (weights = point
/// volumes V_p) gives per node a:
///
///   R_a = sum_p N_a(x_p) n_p V_p [S_L rho_L]_{p^n}^{p^{n+1}} / dt                    (storage)
///       + theta F_a(p^{n+1}) + (1 - theta) F_a(p^n) - Q_a                              (flux)
///   F_a = sum_p V_p m_p grad N_a . (grad p_p + rho_L,p g e_y),  m_p = rho_L,p k_p/(rho_L0 g_k)
///
/// Q_a the boundary inflow (kg/s per metre). The storage is the ACTUAL change of liquid
/// content between the time levels (Celia et al. 1990), so a converged step conserves mass
/// whatever the SWRC slope; the slope only enters the iteration matrix. Each formula here is
/// one function, unit-tested against hand computations (tests/seepage/PointTermsTest.cpp).

#include "argine/core/Types.hpp"
#include "argine/materials/KernelMath.hpp"
#include "argine/physics/LiquidState.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine {

/// Liquid content S_L(p_L) rho_L(p_L) (kg/m^3 of pores): the point's liquid mass is
/// n V S_L rho_L (4.47). The same SWRC and 4.13 as the explicit path.
KOKKOS_INLINE_FUNCTION Real liquidContent(const PointMaterial& material, Real pressure) {
  return saturationAndConductivity(material, pressure).saturation *
         liquidDensity(material.liquid, pressure);
}

/// S_L rho_L at p_new minus at p_old (kg/m^3), without the cancellation of rho_L's large
/// constant part: rho(p1) - rho(p0) = rho(p0) expm1((p1 - p0)/K_L) (4.13), so a saturated
/// compressible change of 1e-7 rho_L keeps its relative precision (mass balance to 1e-10).
///   S1 rho1 - S0 rho0 = S1 (rho1 - rho0) + (S1 - S0) rho0.
/// The same with the saturations S_L(p_new), S_L(p_old) already evaluated (the implicit
/// solver keeps S_L(p_old) for the whole step and S_L(p_new) for the whole iteration).
/// rho_L(p_new) - rho_L(p_old) = rho_old expm1((p_new - p_old)/K_L) (4.13), with rho_old =
/// rho_L(p_old); rho_old plus it is rho_L(p_new) without another exp.
KOKKOS_INLINE_FUNCTION Real liquidDensityChange(const PointMaterial& material, Real p_new,
                                                Real p_old, Real rho_old) {
  return rho_old * Kokkos::Experimental::expm1((p_new - p_old) / material.liquid.bulk_modulus);
}
/// The content change from the saturations, rho_old and the density change.
KOKKOS_INLINE_FUNCTION Real liquidContentChangeOf(Real s_new, Real s_old, Real rho_old,
                                                  Real density_change) {
  return s_new * density_change + (s_new - s_old) * rho_old;
}
/// The same with rho_L(p_old) as well (the implicit solver keeps it for the whole step).
KOKKOS_INLINE_FUNCTION Real liquidContentChangeFrom(const PointMaterial& material, Real p_new,
                                                    Real s_new, Real p_old, Real s_old,
                                                    Real rho_old) {
  return liquidContentChangeOf(s_new, s_old, rho_old,
                               liquidDensityChange(material, p_new, p_old, rho_old));
}
KOKKOS_INLINE_FUNCTION Real liquidContentChangeFrom(const PointMaterial& material, Real p_new,
                                                    Real s_new, Real p_old, Real s_old) {
  return liquidContentChangeFrom(material, p_new, s_new, p_old, s_old,
                                 liquidDensity(material.liquid, p_old));
}

KOKKOS_INLINE_FUNCTION Real liquidContentChange(const PointMaterial& material, Real p_new,
                                                Real p_old) {
  return liquidContentChangeFrom(material, p_new,
                                 saturationAndConductivity(material, p_new).saturation, p_old,
                                 saturationAndConductivity(material, p_old).saturation);
}

/// Whether the Picard matrix needs the minimum-suction regularisation: van Genuchten with
/// lambda < 0.5 has dS_L/ds ~ s^(lambda/(1-lambda)) with exponent < 1 at s -> 0, so its
/// slope (the storage coefficient) is not Lipschitz there and Picard/Newton stall on nodes
/// that just desaturate.
KOKKOS_INLINE_FUNCTION bool needsSuctionRegularisation(const PointMaterial& material) {
  return material.phase == PhaseModel::Unsaturated &&
         material.retention.model == RetentionModel::VanGenuchten &&
         material.retention.lambda < 0.5;
}

/// d(S_L rho_L)/dp_L (kg/m^3/Pa) for the iteration matrix: liquidContentSlope (4.12-4.13) at
/// p_L, with dS_L/ds taken at max(s, s_reg) for 0 < s < s_reg when the curve needs it
/// (s_reg = min_suction_fraction p_ref). Only the matrix uses it: the residual keeps the
/// exact content, so the converged answer does not depend on s_reg.
KOKKOS_INLINE_FUNCTION Real storageSlope(const PointMaterial& material, Real pressure,
                                         Real min_suction_fraction) {
  const LiquidState state = liquidState(material, pressure);
  Real slope_s = state.saturation_suction_derivative;
  const Real suction = suctionOfPressure(pressure);
  if (suction > 0 && needsSuctionRegularisation(material)) {
    const Real s_reg = min_suction_fraction * material.retention.reference_pressure;
    if (suction < s_reg) slope_s = saturationSuctionDerivative(material.retention, s_reg);
  }
  return liquidContentSlope(liquidDensity(material.liquid, pressure), state.saturation, slope_s,
                            material.liquid.bulk_modulus);
}

/// Darcy mass mobility m = rho_L k / (rho_L0 g_k) (s): the mass flux is -m (grad p_L +
/// rho_L g e_y) (kg/m^2/s). k from the HCC at p_L, g_k = 9.81 as in the HCC's k_sat.
/// The same with k already evaluated at p_L.
/// The same with rho_L(p_L) evaluated too.
KOKKOS_INLINE_FUNCTION Real darcyMobilityOf(const PointMaterial& material, Real density,
                                            Real conductivity) {
  return density * conductivity / (material.liquid.density * kStandardGravity);
}
KOKKOS_INLINE_FUNCTION Real darcyMobilityFrom(const PointMaterial& material, Real pressure,
                                              Real conductivity) {
  return darcyMobilityOf(material, liquidDensity(material.liquid, pressure), conductivity);
}

KOKKOS_INLINE_FUNCTION Real darcyMobility(const PointMaterial& material, Real pressure) {
  return darcyMobilityFrom(material, pressure,
                           saturationAndConductivity(material, pressure).conductivity);
}

// ---- Newton (ImplicitSeepageSolver.hpp, doc/theory.md "Newton iteration")
//
// The flux term of a point (N_a, grad N_a at x_p; p_p = sum_b N_b p_b):
//   F_a = V m(p_p) grad N_a . d,   d = grad p + rho_L(p_p) g e_y,                   (N1)
//   m(p) = rho_L(p) k(p) / (rho_L0 g_k)                 (Darcy mobility, 4.13 and the HCC)
// Its exact derivative by the nodal p_b (dp_p/dp_b = N_b, d(grad p)/dp_b = grad N_b):
//   dF_a/dp_b = V m grad N_a . grad N_b                          (Picard's K)         (N2)
//             + V N_b dm/dp (grad N_a . d)                       (non-symmetric)      (N3)
//             + V N_b m g drho_L/dp dN_a/dy                      (non-symmetric)      (N4)
//   dm/dp = m / K_L + rho_L (dk/dp) / (rho_L0 g_k),   drho_L/dp = rho_L / K_L (4.13), (N5)
//   dk/dp = -k_sat dk_r/ds  for s = -p_L > 0,  0 for s <= 0 or a constant HCC.        (N6)
// N3 carries the relative permeability's slope contracted with the point's flux gradient d
// (the liquid mass balance 4.12 with Darcy's law 4.2-4.3: the flux -m d); it makes the
// Jacobian non-symmetric. N4 and the m/K_L of N5 are the liquid compressibility's share
// (relative size p/K_L: tiny, but exact derivatives keep the convergence quadratic).

/// dk/dp_L (m/s/Pa) of the HCC at p_L (N6): -k_sat dk_r/ds (relativeConductivitySuction-
/// Derivative, the materials room's slope) for an unsaturated material at suction s > 0;
/// 0 when saturated (s <= 0, k_r flat at k_r(S_max)) and for a saturated material.
/// Also 0 where the slope is not finite: Mualem's dk_r/dS grows without bound as S -> 1, and
/// at a suction so small that S^(1/lambda*) rounds to 1 the chain rule gives inf x (tiny or
/// 0) = inf or NaN (the exact limit is 0 for the van Genuchten-Mualem pair, lambda = lambda*
/// > 1/2); the point then contributes Picard's matrix, the residual being unchanged.
KOKKOS_INLINE_FUNCTION Real conductivityPressureDerivative(const PointMaterial& material,
                                                           Real pressure) {
  if (material.phase != PhaseModel::Unsaturated) return 0;
  const Real suction = suctionOfPressure(pressure);
  if (suction <= 0) return 0;
  const Real slope =
      -material.conductivity.saturated_conductivity *
      relativeConductivitySuctionDerivative(material.conductivity, material.retention, suction);
  return kmath::fabs(slope) < kmath::infinity() ? slope : 0;  // false for inf and NaN
}

/// dm/dp_L (s/Pa) of the Darcy mobility (N5), with m = darcyMobilityFrom(.., k) already
/// evaluated at p_L.
KOKKOS_INLINE_FUNCTION Real darcyMobilityPressureDerivative(const PointMaterial& material,
                                                            Real pressure, Real mobility) {
  return mobility / material.liquid.bulk_modulus +
         liquidDensity(material.liquid, pressure) *
             conductivityPressureDerivative(material, pressure) /
             (material.liquid.density * kStandardGravity);
}

/// The driving gradient of Darcy's law at the point, d = grad p + rho_L g e_y (4.2-4.3),
/// with grad p = sum_b p_b grad N_b from the nodal pressures `p[b]` of the point's nodes.
KOKKOS_INLINE_FUNCTION void pointDrivingGradient(const PointShape& shape, int nodes, const Real* p,
                                                 Real density_gravity, Real driving[kDim]) {
  driving[0] = 0;
  driving[1] = density_gravity;
  for (int b = 0; b < nodes; ++b)
    for (int d = 0; d < kDim; ++d) driving[d] += p[b] * shape.gradient[b][d];
}

/// Adds the non-symmetric part of the point's flux Jacobian, N3 + N4, to out[a][b]:
///   out[a][b] += N_b (mobility_slope (grad N_a . d) + density_slope dN_a/dy),
/// d = grad p + rho_L g e_y from the nodal pressures p[b] (as addPointFluxVector);
/// mobility_slope = theta V dm/dp, density_slope = theta V m g drho_L/dp.
KOKKOS_INLINE_FUNCTION void addPointFluxJacobianCorrection(
    const PointShape& shape, int nodes, const Real* p, Real density_gravity, Real mobility_slope,
    Real density_slope, Real out[kMaxElementNodes][kMaxElementNodes]) {
  Real driving[kDim];
  pointDrivingGradient(shape, nodes, p, density_gravity, driving);
  for (int a = 0; a < nodes; ++a) {
    Real dot = 0;
    for (int d = 0; d < kDim; ++d) dot += shape.gradient[a][d] * driving[d];
    const Real row = mobility_slope * dot + density_slope * shape.gradient[a][1];
    for (int b = 0; b < nodes; ++b) out[a][b] += row * shape.value[b];
  }
}

/// Adds coefficient N_a N_b to out[a][b] for the point's nodes (consistent storage matrix:
/// coefficient = n V d(S_L rho_L)/dp / dt).
KOKKOS_INLINE_FUNCTION void addPointStorageMatrix(const PointShape& shape, int nodes,
                                                  Real coefficient,
                                                  Real out[kMaxElementNodes][kMaxElementNodes]) {
  for (int a = 0; a < nodes; ++a)
    for (int b = 0; b < nodes; ++b) out[a][b] += coefficient * shape.value[a] * shape.value[b];
}

/// Adds coefficient grad N_a . grad N_b to out[a][b] (conductivity matrix: coefficient =
/// theta V m).
KOKKOS_INLINE_FUNCTION void addPointConductivityMatrix(
    const PointShape& shape, int nodes, Real coefficient,
    Real out[kMaxElementNodes][kMaxElementNodes]) {
  for (int a = 0; a < nodes; ++a)
    for (int b = 0; b < nodes; ++b) {
      Real dot = 0;
      for (int d = 0; d < kDim; ++d) dot += shape.gradient[a][d] * shape.gradient[b][d];
      out[a][b] += coefficient * dot;
    }
}

/// Adds the point's flux term F_a = V m grad N_a . (grad p + rho_L g e_y) to out[a], with
/// grad p = sum_b p_b grad N_b from the nodal pressures `p[b]` of the point's nodes.
KOKKOS_INLINE_FUNCTION void addPointFluxVector(const PointShape& shape, int nodes, const Real* p,
                                               Real volume_mobility, Real density_gravity,
                                               Real* out) {
  Real driving[kDim];
  pointDrivingGradient(shape, nodes, p, density_gravity, driving);
  for (int a = 0; a < nodes; ++a) {
    Real dot = 0;
    for (int d = 0; d < kDim; ++d) dot += shape.gradient[a][d] * driving[d];
    out[a] += volume_mobility * dot;
  }
}

/// p_L at the point from the nodal pressures of its nodes: sum_a N_a p_a.
KOKKOS_INLINE_FUNCTION Real interpolateAtPoint(const PointShape& shape, int nodes, const Real* p) {
  Real value = 0;
  for (int a = 0; a < nodes; ++a) value += shape.value[a] * p[a];
  return value;
}

}  // namespace argine

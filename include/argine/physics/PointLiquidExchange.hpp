#pragma once
/// @file PointLiquidExchange.hpp
/// What the exchanges of liquid between material points share (LiquidHeadStabilisation,
/// IntraElementSeepage): the piezometric pressure that drives them, a point's liquid storage
/// and Darcy conductance, and how an exchanged mass enters the point's mass balance.

#include "argine/core/Lanes.hpp"
#include "argine/core/Types.hpp"
#include "argine/physics/LiquidState.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/PointRates.hpp"

namespace argine {

/// phi = p_L + rho_L0 g y (Pa), gravity g acting in -y: the total head times rho_L0 g
/// (thesis Eq. 4.50); uniform in a hydrostatic state. T = Real, or Lanes for kLanes points.
template <class T>
KOKKOS_INLINE_FUNCTION T piezometricPressure(const PointMaterial& material, T pressure, T y,
                                             Real gravity) {
  return pressure + material.liquid.density * gravity * y;
}

/// dM_L/dp_L = n V rho_L (S_L/K_L - dS_L/ds) (kg/Pa), 4.12 with 4.13, of point p (T = Real)
/// or of points p .. p + kLanes - 1 (Lanes), given dS_L/ds at their p_L.
template <class T>
KOKKOS_INLINE_FUNCTION T pointLiquidStorage(const PointMaterial& material,
                                            const MaterialPoints& points, int p, T ds_ds) {
  return load<T>(points.porosity, p) * load<T>(points.volume, p) *
         liquidContentSlope(load<T>(points.density_liquid, p), load<T>(points.saturation, p), ds_ds,
                            material.liquid.bulk_modulus);
}

/// The same of point p, dS_L/ds from the material's retention curve (0 when saturated).
KOKKOS_INLINE_FUNCTION Real pointLiquidStorage(const PointMaterial& material,
                                               const MaterialPoints& points, int p) {
  const Real pressure = points.pressure_liquid(p);
  const Real ds_ds = material.phase == PhaseModel::Unsaturated
                         ? saturationSuctionDerivativeAtPressure(material.retention, pressure)
                         : 0;
  return pointLiquidStorage(material, points, p, ds_ds);
}

/// Point p's (Real) or points p .. p + kLanes - 1's (Lanes) exchange of `weight` (kg/Pa) towards
/// the piezometric pressure `target` (Pa): weight (target - phi_p) into the mass balance.
template <class T>
KOKKOS_INLINE_FUNCTION void exchangeTowards(const PointMaterial& material,
                                            const MaterialPoints& points, const PointRates& rates,
                                            int p, T weight, T target, Real gravity);

/// The Darcy conductance k / g0 of a point's own cell (kg/(Pa s) per metre of thickness): a
/// square of side a passes (k/g0)(a/a) dphi; g0 = kStandardGravity, the gravity with which a
/// conductivity in m/s is defined (k / (rho_L g0) = kappa / mu_L). T = Real, or Lanes.
template <class T>
KOKKOS_INLINE_FUNCTION T pointDarcyConductance(T conductivity) {
  return conductivity / kStandardGravity;
}

/// Adds `mass_change` (kg, into point p, over the step) to the step's flux divergence of the
/// point's mass balance, before the point update: complete form, M_L^{k+1} = M_L^k - V^k dt
/// div(c w) with V^k = points.volume(p) now (updatePointStates moves V to V^{k+1} only
/// afterwards); simplified, M_L^{k+1} = M_L^k (1 - dt div w). T = Real: point p; Lanes: the
/// points p .. p + kLanes - 1 (of `material`), mass_change of each.
template <class T>
KOKKOS_INLINE_FUNCTION void addPointLiquidMassChange(const PointMaterial& material,
                                                     const MaterialPoints& points,
                                                     const PointRates& rates, int p,
                                                     T mass_change) {
  if (material.mass_balance == MassBalanceForm::Complete) {
    const auto flux = rates.content_flux_divergence_increment_p;
    store(flux, p, load<T>(flux, p) - mass_change / load<T>(points.volume, p));
  } else {
    const auto divergence = rates.liquid_divergence_increment_p;
    store(divergence, p, load<T>(divergence, p) - mass_change / load<T>(points.mass_liquid, p));
  }
}

template <class T>
KOKKOS_INLINE_FUNCTION void exchangeTowards(const PointMaterial& material,
                                            const MaterialPoints& points, const PointRates& rates,
                                            int p, T weight, T target, Real gravity) {
  const T own = piezometricPressure(material, load<T>(points.pressure_liquid, p),
                                    load<T>(points.position, p, 1), gravity);
  addPointLiquidMassChange(material, points, rates, p, weight * (target - own));
}

}  // namespace argine

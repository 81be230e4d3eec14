#pragma once
/// @file PointUpdates.hpp
/// The point-local updates at the end of an explicit step (thesis Sec. 3.3 steps 5-7). Each
/// is a named per-point function; updatePointStates runs them in order for every point in
/// ONE pass over the points (one read and one write of each point field instead of five),
/// and sums the diagnostics on the way.

#include "argine/core/Types.hpp"
#include "argine/materials/KernelMath.hpp"
#include "argine/materials/ObjectiveStressRate.hpp"
#include "argine/materials/SolidModel.hpp"
#include "argine/physics/LiquidState.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/physics/StabilityCheck.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/PointRates.hpp"

namespace argine {

/// What the point updates read and write (Views, copied into the kernel).
struct PointUpdateViews {
  Kokkos::View<const PointMaterial*, MemSpace> materials_m;  ///< parameters by material id
  MaterialPoints points;                                     ///< the point fields
  PointRates rates;                                          ///< this step's increments
  bool hold_liquid_pressure = false;  ///< `Liquid Pressure: held`: p_L, rho_L, S_L kept
};

/// Step 6 (done first, the mass balance needs the new pore volume), solid mass balance
/// (4.9): V <- V (1 + d eps_vol), and n from (1 - n) V = const, so the solid mass
/// (1 - n) rho_S V is kept exactly.
KOKKOS_INLINE_FUNCTION void updatePorosityAndVolume(const PointUpdateViews& v, int p) {
  const Real volumetric = v.rates.strain_increment_p(p, XX) + v.rates.strain_increment_p(p, YY) +
                          v.rates.strain_increment_p(p, ZZ);
  const Real ratio = 1 + volumetric;  // V^{k+1} / V^k
  v.points.volume(p) *= ratio;
  v.points.porosity(p) = 1 - (1 - v.points.porosity(p)) / ratio;
}

/// Step 5, liquid mass balance (4.12 with the advective-gradient term 4.16, or 4.14 without
/// it, per material) in conservative form (LiquidState.hpp): M_L += the relative flux of the
/// step, then p_L such that n S_L(p_L) rho_L(p_L) V = M_L with the new n and V; rho_L from
/// 4.13. Liquid-carrying points only. With a fixed skeleton the strain increments are zero
/// and only the liquid flux changes p_L. With the liquid pressure held, p_L, rho_L and S_L
/// stay and M_L = n S_L rho_L V follows the new pore volume instead (liquid enters or leaves
/// as the skeleton swells or compresses: a drained response).
KOKKOS_INLINE_FUNCTION void updateLiquidPressure(const PointUpdateViews& v, int p) {
  const PointMaterial& material = v.materials_m(v.points.material(p));
  if (!carriesLiquid(material.phase)) return;
  if (v.hold_liquid_pressure) {  // drained: the pore volume fills at the held p_L (4.47)
    v.points.mass_liquid(p) = v.points.porosity(p) * v.points.saturation(p) *
                              v.points.density_liquid(p) * v.points.volume(p);
    return;
  }
  const Real volumetric = v.rates.strain_increment_p(p, XX) + v.rates.strain_increment_p(p, YY) +
                          v.rates.strain_increment_p(p, ZZ);
  // (i) the relative flux moves liquid mass (V is already V^{k+1}: recover V^k).
  const Real volume = v.points.volume(p);
  const Real old_volume = volume / (1 + volumetric);
  const Real mass = liquidMassAfterFlux(material.mass_balance == MassBalanceForm::Complete,
                                        v.points.mass_liquid(p), old_volume,
                                        v.rates.liquid_divergence_increment_p(p) - volumetric,
                                        v.rates.content_flux_divergence_increment_p(p));
  // (ii) the pressure that stores this mass in the new pore volume n V.
  const Real content = mass / (v.points.porosity(p) * volume);
  const Real pressure = v.points.pressure_liquid(p);
  Real guess = pressure;
  if (material.phase == PhaseModel::Unsaturated) {  // the explicit (4.12) predictor
    const Real rho = v.points.density_liquid(p), s = v.points.saturation(p);
    const Real ds_ds = saturationSuctionDerivative(material.retention, suctionOfPressure(pressure));
    guess += (content - s * rho) / liquidContentSlope(rho, s, ds_ds, material.liquid.bulk_modulus);
  }
  const Real next = pressureOfLiquidContent(material, content, guess);
  v.points.pressure_liquid(p) = next;
  // 4.13; saturated, S_L = 1 and the content is the density itself.
  v.points.density_liquid(p) =
      material.phase == PhaseModel::Unsaturated ? liquidDensity(material.liquid, next) : content;
  v.points.mass_liquid(p) = mass;
}

/// Equivalent deviatoric strain sqrt(2/3 e:e) of a plane-strain strain (tensor shear).
KOKKOS_INLINE_FUNCTION Real equivalentDeviatoricStrain(const Real e[kStressComponents]) {
  const Real mean = (e[XX] + e[YY] + e[ZZ]) / 3;
  const Real dxx = e[XX] - mean, dyy = e[YY] - mean, dzz = e[ZZ] - mean;
  return kmath::sqrt(2.0 / 3.0 * (dxx * dxx + dyy * dyy + dzz * dzz + 2 * e[XY] * e[XY]));
}

/// Step 5, constitutive update: the Jaumann rotation of sigma' by the step's spin
/// (ObjectiveStressRate.hpp), then sigma' += D d eps (4.22) or the Mohr-Coulomb return with
/// the point's solid model and current suction (Bishop's chi = S_L enters the total stress
/// in the P2G, 4.5); accumulates the total strain, the equivalent deviatoric strain and the
/// equivalent plastic strain, and sets the plastic state.
KOKKOS_INLINE_FUNCTION void updateEffectiveStress(const PointUpdateViews& v, int p) {
  const PointMaterial& material = v.materials_m(v.points.material(p));
  const Real suction =
      carriesLiquid(material.phase) ? suctionOfPressure(v.points.pressure_liquid(p)) : Real(0);
  Real dstrain[kStressComponents], stress[kStressComponents], strain[kStressComponents];
  for (int c = 0; c < kStressComponents; ++c) {
    dstrain[c] = v.rates.strain_increment_p(p, c);
    stress[c] = v.points.stress_effective(p, c);
    strain[c] = v.points.strain(p, c) + dstrain[c];
  }
  rotateStressBySpin(v.rates.spin_increment_p(p), stress);
  Real plastic_strain = v.points.plastic_strain(p);
  int plastic_state = v.points.plastic_state(p);
  updateEffectiveStress(material.solid, material.solid_constants, suction, dstrain, stress,
                        plastic_strain, plastic_state);
  for (int c = 0; c < kStressComponents; ++c) {
    v.points.stress_effective(p, c) = stress[c];
    v.points.strain(p, c) = strain[c];
  }
  v.points.plastic_strain(p) = plastic_strain;
  v.points.plastic_state(p) = plastic_state;
  v.points.deviatoric_strain(p) = equivalentDeviatoricStrain(strain);
}

/// Step 6, state variables: S_L and k from the SWRC/HCC at the new pressure (unsaturated) or
/// 1 and k_sat (saturated). M_L (4.47) is carried by updateLiquidPressure.
KOKKOS_INLINE_FUNCTION void updateLiquidState(const PointUpdateViews& v, int p) {
  const PointMaterial& material = v.materials_m(v.points.material(p));
  if (material.phase != PhaseModel::Unsaturated) return;  // dry: none; saturated: constant
  const LiquidState state = saturationAndConductivity(material, v.points.pressure_liquid(p));
  v.points.saturation(p) = state.saturation;
  v.points.conductivity(p) = state.conductivity;
}

/// Step 7, Euler-Cromer (7.13): x += dt sum N v_S^{k+1}, u += the same.
KOKKOS_INLINE_FUNCTION void updatePointPosition(const PointUpdateViews& v, int p) {
  for (int d = 0; d < kDim; ++d) {
    v.points.position(p, d) += v.rates.displacement_increment_p(p, d);
    v.points.displacement(p, d) += v.rates.displacement_increment_p(p, d);
  }
}

/// Runs, for every located point and in this order: updatePorosityAndVolume,
/// updateLiquidPressure, updateEffectiveStress, updateLiquidState, updatePointPosition, in
/// one pass; returns the liquid mass and the number of points whose new state is invalid
/// (pointStateIsValid); the kinetic energies are left 0 (the G2P sums them).
PointTotals updatePointStates(const MaterialTable& table, const PointRates& rates,
                              MaterialPoints& points, bool hold_liquid_pressure = false);

}  // namespace argine

#pragma once
/// @file PointUpdates.hpp
/// The point-local updates at the end of an explicit step (thesis Sec. 3.3 steps 5-7). Each
/// is a named per-point function; updatePointStates runs them in order for every point in
/// ONE pass over the points (one read and one write of each point field instead of five),
/// and sums the diagnostics on the way.

#include "argine/core/Lanes.hpp"
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
  /// 1 where air reaches the element (AirPath.hpp), by element: an air-filled crack opens
  /// only there. Empty: anywhere (a single point's updates, with no mesh around it).
  Kokkos::View<const unsigned char*, MemSpace> air_reaches_e;
  /// Step 6 evaluates S_L and k at the new p_L; false where they are known to be those of the
  /// unchanged p_L already (a held stage after its first step): the same values, skipped.
  bool renew_liquid_state = true;
};

/// Whether air reaches point p for an air-filled crack (PointUpdateViews::air_reaches_e).
KOKKOS_INLINE_FUNCTION bool airReaches(const PointUpdateViews& v, int p) {
  return v.air_reaches_e.extent(0) == 0 || v.air_reaches_e(v.points.element(p)) != 0;
}

/// Before step 6: a point that opened from its neighbours (separation > 0, separateFrom-
/// Neighbours) and is now compressed closes that gap first: the step's volumetric strain, up
/// to the gap, is the gap closing, not the point's skeleton compressing, so it is taken out
/// of the step's strain increment (isotropically in the plane: the shear and the deviatoric
/// part pass unchanged) for the volume, the liquid and the stress updates that follow, and
/// the gap shrinks by it. Without it, grains that parted and came back together were
/// compressed as if they had never parted (and an unsaturated point's p_L jumped).
KOKKOS_INLINE_FUNCTION void closeSeparation(const PointUpdateViews& v, int p) {
  const Real gap = v.points.separation(p);
  if (!(gap > 0)) return;
  const Real volumetric = v.rates.strain_increment_p(p, XX) + v.rates.strain_increment_p(p, YY) +
                          v.rates.strain_increment_p(p, ZZ);
  if (!(volumetric < 0)) return;
  const Real closure = -volumetric < gap ? -volumetric : gap;
  v.rates.strain_increment_p(p, XX) += closure / 2;  // plane strain: zz stays 0
  v.rates.strain_increment_p(p, YY) += closure / 2;
  v.points.separation(p) = gap - closure;
}

/// The volume of a point's open air-filled crack (m^3): separation V for a material with
/// `Tension Cracks: air-filled` (keepsOpeningOut), 0 otherwise (the opening of the pore-space
/// model, and a dry point's, holds no liquid).
KOKKOS_INLINE_FUNCTION Real airFilledCrackVolume(const PointUpdateViews& v, int p,
                                                 const PointMaterial& material) {
  if (material.tension_cracks != TensionCracks::AirFilled) return 0;
  const Real gap = v.points.separation(p);
  return gap > 0 ? gap * v.points.volume(p) : Real(0);
}

/// p_L of a point holding the liquid mass `mass` in its pores (pore_volume = n V) and, with
/// an open air-filled crack (crack_volume > 0, airFilledCrackVolume), in the crack too. The
/// crack is open to the air: it takes no water while the pores hold suction (a crack mm wide
/// holds none against it) and holds water only at p_L = 0 (its own head over a point's size
/// neglected):
///  - M_L <= S_L(0) rho_L(0) n V: the pores alone, p_L <= 0 from their content (4.12);
///  - up to rho_L(0) crack_volume more: p_L = 0, the rest stands in the crack;
///  - beyond: the crack is full and the pores hold the rest at p_L > 0.
/// So liquid squeezed out of the pores of a cracked point fills its crack instead of raising
/// p_L, and comes back when the crack closes; M_L is kept. Without a crack: the pores alone.
KOKKOS_INLINE_FUNCTION Real pressureOfPointLiquid(const PointMaterial& material, Real mass,
                                                  Real pore_volume, Real crack_volume, Real guess) {
  if (crack_volume > 0) {
    const Real full_pores =
        saturationOfPressure(material, 0) * material.liquid.density * pore_volume;
    const Real crack_capacity = material.liquid.density * crack_volume;
    if (mass > full_pores && mass <= full_pores + crack_capacity) return 0;
    if (mass > full_pores) mass -= crack_capacity;
  }
  return pressureOfLiquidContent(material, mass / pore_volume, guess);
}

/// Step 6 (done first, the mass balance needs the new pore volume), solid mass balance
/// (4.9): V <- V (1 + d eps_vol), and n from (1 - n) V = const, so the solid mass
/// (1 - n) rho_S V is kept exactly. T = Real: point p; Lanes: points p .. p + kLanes - 1.
template <class T = Real>
KOKKOS_INLINE_FUNCTION void updatePorosityAndVolume(const PointUpdateViews& v, int p) {
  T increment[kStressComponents];
  loadComponents(v.rates.strain_increment_p, p, increment);
  const T volumetric = increment[XX] + increment[YY] + increment[ZZ];
  const T ratio = 1 + volumetric;  // V^{k+1} / V^k
  store(v.points.volume, p, load<T>(v.points.volume, p) * ratio);
  store(v.points.porosity, p, 1 - (1 - load<T>(v.points.porosity, p)) / ratio);
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
    const Real ds_ds = saturationSuctionDerivativeAtPressure(material.retention, pressure);
    guess += (content - s * rho) / liquidContentSlope(rho, s, ds_ds, material.liquid.bulk_modulus);
  }
  const Real next = pressureOfPointLiquid(material, mass, v.points.porosity(p) * volume,
                                          airFilledCrackVolume(v, p, material), guess);
  v.points.pressure_liquid(p) = next;
  // 4.13; saturated, S_L = 1 and the content is the density itself.
  v.points.density_liquid(p) =
      material.phase == PhaseModel::Unsaturated ? liquidDensity(material.liquid, next) : content;
  v.points.mass_liquid(p) = mass;
}

/// Whether updateLiquidPressureLanes can take points of this material all at once: a
/// saturated one (its pressure is the closed-form inverse of 4.13), or an unsaturated one on
/// a linear retention curve (the Newton iterations of pressureOfLiquidContentLanes) whose
/// lanes have no air-filled crack open (that storage is the one-point pressureOfPointLiquid's).
KOKKOS_INLINE_FUNCTION bool takesLanePressureUpdate(const PointUpdateViews& v, int p,
                                                    const PointMaterial& material) {
  if (v.hold_liquid_pressure) return false;
  if (material.phase == PhaseModel::Saturated) return true;
  return material.phase == PhaseModel::Unsaturated &&
         material.retention.model == RetentionModel::Linear &&
         (material.tension_cracks != TensionCracks::AirFilled ||
          !anyLane(load<Lanes>(v.points.separation, p) > 0));
}

/// The liquid mass of the kLanes points p .. p + kLanes - 1 after the step's relative flux
/// and their liquid content M_L / (n V) (updateLiquidPressure's first half, lanes at once).
struct LaneLiquidBalance {
  Lanes mass, content;
};
KOKKOS_INLINE_FUNCTION LaneLiquidBalance laneLiquidBalance(const PointUpdateViews& v, int p,
                                                           const PointMaterial& material) {
  Lanes increment[kStressComponents];
  loadComponents(v.rates.strain_increment_p, p, increment);
  const Lanes volumetric = increment[XX] + increment[YY] + increment[ZZ];
  const Lanes volume = load<Lanes>(v.points.volume, p);
  const Lanes old_volume = volume / (1 + volumetric);
  const Lanes mass = liquidMassAfterFlux(
      material.mass_balance == MassBalanceForm::Complete, load<Lanes>(v.points.mass_liquid, p),
      old_volume, load<Lanes>(v.rates.liquid_divergence_increment_p, p) - volumetric,
      load<Lanes>(v.rates.content_flux_divergence_increment_p, p));
  return {mass, mass / (load<Lanes>(v.points.porosity, p) * volume)};
}

/// updateLiquidPressure's explicit (4.12) predictor of the kLanes points p .. of one
/// unsaturated material on a linear retention curve: the Newton's first iterate.
KOKKOS_INLINE_FUNCTION Lanes lanePressurePredictor(const PointUpdateViews& v, int p,
                                                   const PointMaterial& material, Lanes content) {
  const Lanes pressure = load<Lanes>(v.points.pressure_liquid, p);
  const Lanes rho = load<Lanes>(v.points.density_liquid, p),
              s = load<Lanes>(v.points.saturation, p);
  Lanes unused, ds_ds;
  linearSaturationAndSlopeAtPressure(material.retention, pressure, unused, ds_ds);
  return pressure +
         (content - s * rho) / liquidContentSlope(rho, s, ds_ds, material.liquid.bulk_modulus);
}

/// Stores the unsaturated p_L found for the kLanes points p .., their rho_L (4.13) and M_L.
KOKKOS_INLINE_FUNCTION void storeLaneLiquidPressure(const PointUpdateViews& v, int p,
                                                    const PointMaterial& material, Lanes mass,
                                                    Lanes pressure) {
  store(v.points.pressure_liquid, p, pressure);
  store(v.points.density_liquid, p, liquidDensity(material.liquid, pressure));
  store(v.points.mass_liquid, p, mass);
}

/// updateLiquidPressure of the kLanes points p .. p + kLanes - 1 of one material: the same
/// formulas on all lanes at once where takesLanePressureUpdate (an unsaturated lane whose
/// Newton iterations leave the plain path sends all four to the one-point update); otherwise
/// the one-point update lane by lane. The same bits either way.
KOKKOS_INLINE_FUNCTION void updateLiquidPressureLanes(const PointUpdateViews& v, int p,
                                                      const PointMaterial& material) {
  if (!carriesLiquid(material.phase)) return;
  const auto one_by_one = [&] {
    for (int l = 0; l < kLanes; ++l) updateLiquidPressure(v, p + l);
  };
  if (!takesLanePressureUpdate(v, p, material)) return one_by_one();
  const LaneLiquidBalance balance = laneLiquidBalance(v, p, material);
  if (material.phase == PhaseModel::Saturated) {
    store(v.points.pressure_liquid, p,
          saturatedPressureOfContent(material.liquid, balance.content));
    store(v.points.density_liquid, p, balance.content);  // S_L = 1: the content is the density
    store(v.points.mass_liquid, p, balance.mass);
    return;
  }
  // unsaturated, linear curve: updateLiquidPressure's predictor and Newton, lanes at once
  const Lanes guess = lanePressurePredictor(v, p, material, balance.content);
  Lanes next;
  if (!pressureOfLiquidContentLanes(material, balance.content, guess, next)) return one_by_one();
  storeLaneLiquidPressure(v, p, material, balance.mass, next);
}

/// updateLiquidPressureLanes of the two chunks p .. p + kLanes - 1 and p + kLanes .. p +
/// 2 kLanes - 1 of one material. Unsaturated, both on the lane path: the two chunks' Newton
/// iterations side by side (pressureOfLiquidContentLanes<2>; one chunk's iterations are a
/// single latency chain, ~60 % of this update's time on the levee); otherwise, or where a
/// lane of either leaves the plain Newton path, chunk by chunk. The same bits either way.
KOKKOS_INLINE_FUNCTION void updateLiquidPressureLanePair(const PointUpdateViews& v, int p,
                                                         const PointMaterial& material) {
  const int q = p + kLanes;
  const auto chunk_by_chunk = [&] {
    updateLiquidPressureLanes(v, p, material);
    updateLiquidPressureLanes(v, q, material);
  };
  if (material.phase != PhaseModel::Unsaturated || !takesLanePressureUpdate(v, p, material) ||
      !takesLanePressureUpdate(v, q, material))
    return chunk_by_chunk();
  const LaneLiquidBalance first = laneLiquidBalance(v, p, material),
                          second = laneLiquidBalance(v, q, material);
  const Lanes contents[2] = {first.content, second.content};
  const Lanes guesses[2] = {lanePressurePredictor(v, p, material, first.content),
                            lanePressurePredictor(v, q, material, second.content)};
  Lanes next[2];
  if (!pressureOfLiquidContentLanes<2>(material, contents, guesses, next)) return chunk_by_chunk();
  storeLaneLiquidPressure(v, p, material, first.mass, next[0]);
  storeLaneLiquidPressure(v, q, material, second.mass, next[1]);
}

/// The opening of a return to the apex or the tension cut-off (isSeparating): the part of the
/// step's volumetric strain that the stress did not follow elastically, d eps_vol - (p' after
/// - p' before) / K, K = lambda + 2 G / 3 (p' the mean effective stress, rotation excluded:
/// it keeps the trace). The trial lay where the material carries no more tension: this is the
/// point separating from its neighbours (a crack, grains parting), not a strain of its own
/// skeleton. (At an edge of the cut-off with a Mohr-Coulomb plane the plane's dilatancy, psi
/// > 0, is counted with it.)
KOKKOS_INLINE_FUNCTION Real separationOpening(const SolidConstants& constants,
                                              const Real dstrain[kStressComponents],
                                              Real mean_before, Real mean_after) {
  const Real bulk = constants.lambda + 2 * constants.shear_modulus / 3;
  const Real volumetric = dstrain[XX] + dstrain[YY] + dstrain[ZZ];
  return volumetric - (mean_after - mean_before) / bulk;
}

/// Whether a point of this material and plastic state keeps its opening out of its pores
/// (separateFromNeighbours):
///  - dry: at the apex and at the tension cut-off (grains part, a crack opens);
///  - unsaturated: at the apex, a point pulled apart all round (air fills the opening); at
///    the cut-off only with `Tension Cracks: air-filled`, a point that held suction at the
///    start of the step (`saturation_before` < S_max: the stored S_L, which updateLiquidState
///    renews after the stress) and air that reaches it (`air_reaches`: the surface or an open
///    crack next to it, AirPath.hpp): the crack is then open to the air, and the point's
///    liquid sees it through pressureOfPointLiquid. Without the path a point with occluded
///    air (S_L = 0.9999, 0.8 m deep) opened cracks no air could reach and the slid 0.1 m
///    levee cracked through its depth and came apart (doc/verification.md). With `pore
///    space` (the thesis) the crack stays pore space of the point on its retention curve: the
///    suction the opening makes draws water into it (a scarp's cracks drew 0.013 m^3/m into
///    the 0.05 m grid levee, doc/verification.md). Keeping it out without the crack's own
///    storage broke that run: the lateral squeeze that comes with a crack compressed the
///    nearly saturated pores (p_L up to +75 kPa at the crest in the settle stage, a point at
///    -892 kPa, a non-finite stop);
///  - saturated: never; water fills the opening, its dilation is the liquid's business (4.12).
KOKKOS_INLINE_FUNCTION bool keepsOpeningOut(const PointMaterial& material, int plastic_state,
                                            Real saturation_before, bool air_reaches = true) {
  if (material.phase == PhaseModel::Dry) return isSeparating(plastic_state);
  if (material.phase != PhaseModel::Unsaturated) return false;
  if (plastic_state == kPlasticStateApex) return true;
  return plastic_state == kPlasticStateTension &&
         material.tension_cracks == TensionCracks::AirFilled &&
         saturation_before < material.retention.saturation_max && air_reaches;
}

/// Step 6 corrected at a separating return (keepsOpeningOut): the opening (separationOpening)
/// is space between the points, not porosity, so the point keeps the volume its stress
/// followed: V <- V (1 + d eps_vol - opening) / (1 + d eps_vol), n again from (1 - n) V =
/// const, and the opening joins the point's separation (closeSeparation closes it first when
/// the point is compressed again). Without it an open point's porosity ratchets up (opening is
/// free, closing again costs elastic stress): points at the surface of a psi = 0 collapse
/// reached n = 0.99 and the whole body +17 to +72 % of volume, and their light weight cut the
/// time step tenfold (doc/theory.md). An unsaturated point's content, and so its p_L, stays
/// that of its own pores.
KOKKOS_INLINE_FUNCTION void separateFromNeighbours(const PointUpdateViews& v, int p,
                                                   const PointMaterial& material, int plastic_state,
                                                   Real opening) {
  if (!(opening > 0) ||
      !keepsOpeningOut(material, plastic_state, v.points.saturation(p), airReaches(v, p)))
    return;
  const Real volumetric = v.rates.strain_increment_p(p, XX) + v.rates.strain_increment_p(p, YY) +
                          v.rates.strain_increment_p(p, ZZ);
  const Real ratio = (1 + volumetric - opening) / (1 + volumetric);  // kept / kinematic
  v.points.separation(p) += opening;
  v.points.volume(p) *= ratio;
  v.points.porosity(p) = 1 - (1 - v.points.porosity(p)) / ratio;
  if (material.phase != PhaseModel::Unsaturated) return;
  if (v.hold_liquid_pressure) {  // drained, as updateLiquidPressure: the mass follows n V
    v.points.mass_liquid(p) = v.points.porosity(p) * v.points.saturation(p) *
                              v.points.density_liquid(p) * v.points.volume(p);
    return;
  }
  // the same liquid mass in the smaller pore volume (and an air-filled crack): p_L again (4.12)
  const Real next = pressureOfPointLiquid(
      material, v.points.mass_liquid(p), v.points.porosity(p) * v.points.volume(p),
      airFilledCrackVolume(v, p, material), v.points.pressure_liquid(p));
  v.points.pressure_liquid(p) = next;
  v.points.density_liquid(p) = liquidDensity(material.liquid, next);
}

/// Equivalent deviatoric strain sqrt(2/3 e:e) of a plane-strain strain (tensor shear), of one
/// point (Real) or kLanes points (Lanes).
template <class T>
KOKKOS_INLINE_FUNCTION T equivalentDeviatoricStrain(const T e[kStressComponents]) {
  const T mean = (e[XX] + e[YY] + e[ZZ]) / 3;
  const T dxx = e[XX] - mean, dyy = e[YY] - mean, dzz = e[ZZ] - mean;
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
  const Real mean_before = (stress[XX] + stress[YY] + stress[ZZ]) / 3;
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
  if (isSeparating(plastic_state))
    separateFromNeighbours(v, p, material, plastic_state,
                           separationOpening(material.solid_constants, dstrain, mean_before,
                                             (stress[XX] + stress[YY] + stress[ZZ]) / 3));
}

/// Step 6, state variables: S_L and k from the SWRC/HCC at the new pressure (unsaturated) or
/// 1 and k_sat (saturated). M_L (4.47) is carried by updateLiquidPressure.
KOKKOS_INLINE_FUNCTION void updateLiquidState(const PointUpdateViews& v, int p) {
  if (!v.renew_liquid_state) return;
  const PointMaterial& material = v.materials_m(v.points.material(p));
  if (material.phase != PhaseModel::Unsaturated) return;  // dry: none; saturated: constant
  const LiquidState state = saturationAndConductivity(material, v.points.pressure_liquid(p));
  v.points.saturation(p) = state.saturation;
  v.points.conductivity(p) = state.conductivity;
}

/// Step 7, Euler-Cromer (7.13): x += dt sum N v_S^{k+1}, u += the same. T = Real: point p;
/// Lanes: points p .. p + kLanes - 1.
template <class T = Real>
KOKKOS_INLINE_FUNCTION void updatePointPosition(const PointUpdateViews& v, int p) {
  T increment[kDim], position[kDim], displacement[kDim];
  loadComponents(v.rates.displacement_increment_p, p, increment);
  loadComponents(v.points.position, p, position);
  loadComponents(v.points.displacement, p, displacement);
  for (int d = 0; d < kDim; ++d) {
    position[d] = position[d] + increment[d];
    displacement[d] = displacement[d] + increment[d];
  }
  storeComponents(v.points.position, p, position);
  storeComponents(v.points.displacement, p, displacement);
}

/// Whether updateEffectiveStressLanes covers the material's solid model (those whose update
/// has no parameter that varies by point).
KOKKOS_INLINE_FUNCTION bool hasLaneStressUpdate(const PointMaterial& material) {
  return material.solid.model == SolidModel::LinearElastic ||
         material.solid.model == SolidModel::MohrCoulomb;
}

/// updateEffectiveStress of the kLanes points p .. p + kLanes - 1 of one material with
/// hasLaneStressUpdate, all at once with the same formulas (rotation, elastic trial, and for
/// Mohr-Coulomb its principal stresses and admissibility test). A lane whose Mohr-Coulomb
/// trial lies outside the surface is left to the one-point updateEffectiveStress, which does
/// the return (a branchy, rarer path). So each lane gets the one-point update's bits.
KOKKOS_INLINE_FUNCTION void updateEffectiveStressLanes(const PointUpdateViews& v, int p,
                                                       const PointMaterial& material) {
  Lanes dstrain[kStressComponents], stress[kStressComponents], strain[kStressComponents];
  loadComponents(v.rates.strain_increment_p, p, dstrain);
  loadComponents(v.points.stress_effective, p, stress);
  loadComponents(v.points.strain, p, strain);
  for (int c = 0; c < kStressComponents; ++c) strain[c] = strain[c] + dstrain[c];
  rotateStressBySpin(load<Lanes>(v.rates.spin_increment_p, p), stress);
  const SolidConstants& constants = material.solid_constants;
  Lanes dstress[kStressComponents];
  elasticStressIncrement(constants.lambda, 2 * constants.shear_modulus, dstrain, dstress);
  for (int c = 0; c < kStressComponents; ++c) stress[c] = stress[c] + dstress[c];  // the trial
  LaneMask outside = {};
  if (material.solid.model == SolidModel::MohrCoulomb) {
    Lanes sigma[3];
    sortedPrincipalStresses(inPlanePrincipal(stress[XX], stress[YY], stress[XY]), stress[ZZ],
                            sigma);
    outside = checkMohrCoulombTrial(constants.strength, constants.factors, sigma).outside;
  }
  const Lanes deviatoric = equivalentDeviatoricStrain(strain);
  if (!anyLane(outside)) {  // the common case: elastic in every lane
    storeComponents(v.points.stress_effective, p, stress);
    storeComponents(v.points.strain, p, strain);
    store(v.points.deviatoric_strain, p, deviatoric);
    for (int l = 0; l < kLanes; ++l) v.points.plastic_state(p + l) = kPlasticStateElastic;
    return;
  }
  for (int l = 0; l < kLanes; ++l) {
    if (outside[l]) {
      updateEffectiveStress(v, p + l);  // from the stored state: it has not been written
      continue;
    }
    for (int c = 0; c < kStressComponents; ++c) {
      v.points.stress_effective(p + l, c) = stress[c][l];
      v.points.strain(p + l, c) = strain[c][l];
    }
    v.points.deviatoric_strain(p + l) = deviatoric[l];
    v.points.plastic_state(p + l) = kPlasticStateElastic;
  }
}

/// Runs, for every located point and in this order: closeSeparation, updatePorosityAndVolume,
/// updateLiquidPressure, updateEffectiveStress, updateLiquidState, updatePointPosition, in
/// one pass; returns the liquid mass and the number of points whose new state is invalid
/// (pointStateIsValid); the kinetic energies are left 0 (the G2P sums them). Without
/// `renew_liquid_state` updateLiquidState is skipped (PointUpdateViews).
PointTotals updatePointStates(const MaterialTable& table, const PointRates& rates,
                              MaterialPoints& points, bool hold_liquid_pressure = false,
                              Kokkos::View<const unsigned char*, MemSpace> air_reaches_e = {},
                              bool renew_liquid_state = true);

}  // namespace argine

#pragma once
/// @file SolidModel.hpp
/// The effective-stress update of the solid skeleton (thesis Eq. 4.22 with h' = 0 and
/// Bishop's chi = S_L, so suction acts through the strength parameters only), chosen by a
/// switch on SolidSpec::model (no virtual calls in kernels), and the suction-dependent
/// strength parameters of Eqs. 4.23-4.26.
///
/// All three models are implemented: LinearElastic (LinearElastic.hpp), MohrCoulomb and
/// SuctionMohrCoulomb (MohrCoulomb.hpp; the latter with c and phi of Eqs. 4.23-4.26 at the
/// point's current suction). The objective (Jaumann) rotation of the stress is applied by
/// the caller before this update (ObjectiveStressRate.hpp, physics/PointUpdates.hpp).

#include "argine/core/Types.hpp"
#include "argine/materials/KernelMath.hpp"
#include "argine/materials/LinearElastic.hpp"
#include "argine/materials/MaterialParameters.hpp"
#include "argine/materials/MohrCoulomb.hpp"

namespace argine {

/// plastic_state values (points/MaterialPoints.hpp: 0 elastic, 1 plastic, 2 apex, 3 tension
/// cut-off).
inline constexpr int kPlasticStateElastic = kMohrCoulombElastic;
inline constexpr int kPlasticStatePlastic = kMohrCoulombSurface;  ///< Mohr-Coulomb plane, edge
inline constexpr int kPlasticStateApex = kMohrCoulombApex;
inline constexpr int kPlasticStateTension = kMohrCoulombTension;  ///< cut-off: a tensile crack
/// Whether a point of this plastic state is separating from its neighbours: a return to the
/// apex or to the tension cut-off, where the material carries no more tension.
KOKKOS_INLINE_FUNCTION constexpr bool isSeparating(int plastic_state) {
  return plastic_state == kPlasticStateApex || plastic_state == kPlasticStateTension;
}
/// A model without a stress update (none at present; kept for models added later).
inline constexpr int kPlasticStateUnsupported = -1;

/// Whether updateEffectiveStress() implements `model`.
KOKKOS_INLINE_FUNCTION constexpr bool isImplemented(SolidModel model) {
  switch (model) {
    case SolidModel::LinearElastic:
    case SolidModel::MohrCoulomb:
    case SolidModel::SuctionMohrCoulomb:
      return true;
  }
  return false;
}

/// Cohesion c = c' + dc_max (1 - exp(-B s / p_atm)) (Pa), Eqs. 4.23 and 4.25; s <= 0
/// (saturated) gives c'.
KOKKOS_INLINE_FUNCTION Real suctionDependentCohesion(const SolidSpec& spec, Real suction) {
  if (suction <= 0) return spec.cohesion;
  return spec.cohesion +
         spec.cohesion_increase_max *
             (1 - kmath::exp(-spec.cohesion_suction_rate * suction / spec.atmospheric_pressure));
}

/// Friction angle phi = phi' + A s / p_atm (rad), Eqs. 4.24 and 4.26; s <= 0 gives phi'.
KOKKOS_INLINE_FUNCTION Real suctionDependentFriction(const SolidSpec& spec, Real suction) {
  if (suction <= 0) return spec.friction_angle;
  return spec.friction_angle + spec.friction_suction_rate * suction / spec.atmospheric_pressure;
}

/// The strength `strength` divided by the strength-reduction factor F (Dawson, Roth and
/// Drescher 1999; Griffiths and Lane 1999): c/F, tan phi_F = tan phi / F, the cut-off
/// sigma_t/F, and psi_F = min(psi, phi_F) so that the flow never dilates more than the
/// reduced friction allows. Applied to c(s) and phi(s), it reduces the suction terms with
/// them: the Bishop stress's S_L s adds S_L s tan phi_F to the shear strength. F = 1 returns
/// `strength` unchanged, to the bit.
KOKKOS_INLINE_FUNCTION MohrCoulombStrength reducedStrength(MohrCoulombStrength strength, Real f) {
  if (f == 1) return strength;
  strength.cohesion /= f;
  strength.friction_angle = kmath::atan(kmath::tan(strength.friction_angle) / f);
  if (strength.dilatancy_angle > strength.friction_angle)
    strength.dilatancy_angle = strength.friction_angle;
  strength.tensile_strength /= f;
  return strength;
}

/// The Mohr-Coulomb strength of `spec` at suction s (Pa): c', phi' for MohrCoulomb, c(s) and
/// phi(s) of Eqs. 4.23-4.26 for SuctionMohrCoulomb; psi and the cut-off as given; all of it
/// reduced by spec.strength_reduction (reducedStrength).
KOKKOS_INLINE_FUNCTION MohrCoulombStrength mohrCoulombStrength(const SolidSpec& spec,
                                                               Real suction) {
  MohrCoulombStrength strength;
  const bool suction_dependent = spec.model == SolidModel::SuctionMohrCoulomb;
  strength.cohesion = suction_dependent ? suctionDependentCohesion(spec, suction) : spec.cohesion;
  strength.friction_angle =
      suction_dependent ? suctionDependentFriction(spec, suction) : spec.friction_angle;
  strength.dilatancy_angle = spec.dilatancy_angle;
  strength.tensile_strength = spec.tensile_strength;
  strength.tension_cutoff = spec.tension_cutoff;
  return reducedStrength(strength, spec.strength_reduction);
}

/// What a material's stress update derives from its SolidSpec alone, derived once per
/// material (physics/MaterialTable) instead of at every point, by the same expressions (so
/// the same values to the bit): lambda and G, and for MohrCoulomb, whose strength does not
/// depend on suction, the strength and its return-mapping factors. SuctionMohrCoulomb with
/// A = 0 (Friction Suction Rate A, Eq. 4.24: phi = phi' at every suction, as the thesis'
/// Table 5.4) keeps its angles at every suction, so the factors' k and m (two sines, most of
/// such a point's cost) are those at s = 0; only the cohesion, and with it sigma_c and the
/// apex, is taken at the point's suction.
struct SolidConstants {
  Real lambda = 0;               ///< Lame's lambda (Pa)
  Real shear_modulus = 0;        ///< G (Pa)
  MohrCoulombStrength strength;  ///< MohrCoulomb (and constantSuctionAngles): at s = 0
  MohrCoulombFactors factors;    ///< the same: mohrCoulombFactors(strength)
};

/// Whether a SuctionMohrCoulomb spec keeps its friction and dilatancy angles at every
/// suction (A = 0): phi(s) = phi' + 0 s / p_atm = phi', to the bit.
KOKKOS_INLINE_FUNCTION bool constantSuctionAngles(const SolidSpec& spec) {
  return spec.model == SolidModel::SuctionMohrCoulomb && spec.friction_suction_rate == 0;
}

KOKKOS_INLINE_FUNCTION SolidConstants solidConstants(const SolidSpec& spec) {
  SolidConstants constants;
  constants.lambda = lameLambda(spec);
  constants.shear_modulus = shearModulus(spec);
  if (spec.model == SolidModel::MohrCoulomb || constantSuctionAngles(spec)) {
    constants.strength = mohrCoulombStrength(spec, 0);
    constants.factors = mohrCoulombFactors(constants.strength);
  }
  return constants;
}

/// Update the Bishop effective stress (Pa, tension positive; xx, yy, zz, xy) of one point
/// by the strain increment dstrain (tensor shear in [3], see LinearElastic.hpp). `suction`
/// (Pa, s = -p_L) feeds the suction-dependent model; `constants` = solidConstants(spec).
/// Sets plastic_state (0 elastic, 1 plastic on a plane/edge, 2 apex, 3 cut-off) and adds the
/// equivalent plastic strain of the increment to plastic_strain. Returns false (NaN stress,
/// kPlasticStateUnsupported) only for a model without an update.
KOKKOS_INLINE_FUNCTION bool updateEffectiveStress(const SolidSpec& spec,
                                                  const SolidConstants& constants, Real suction,
                                                  const Real dstrain[kStressComponents],
                                                  Real stress[kStressComponents],
                                                  Real& plastic_strain, int& plastic_state) {
  switch (spec.model) {
    case SolidModel::LinearElastic: {
      Real dstress[kStressComponents];
      elasticStressIncrement(constants.lambda, 2 * constants.shear_modulus, dstrain, dstress);
      for (int i = 0; i < kStressComponents; ++i) stress[i] += dstress[i];
      plastic_state = kPlasticStateElastic;
      return true;
    }
    case SolidModel::MohrCoulomb:
      plastic_state =
          mohrCoulombStressUpdate(constants.lambda, constants.shear_modulus, constants.strength,
                                  constants.factors, dstrain, stress, plastic_strain);
      return true;
    case SolidModel::SuctionMohrCoulomb: {
      const MohrCoulombStrength strength = mohrCoulombStrength(spec, suction);
      const MohrCoulombFactors factors =
          constantSuctionAngles(spec)
              ? mohrCoulombFactors(strength, constants.factors.k, constants.factors.m)
              : mohrCoulombFactors(strength);
      plastic_state = mohrCoulombStressUpdate(constants.lambda, constants.shear_modulus, strength,
                                              factors, dstrain, stress, plastic_strain);
      return true;
    }
  }
  for (int i = 0; i < kStressComponents; ++i) stress[i] = kmath::quietNaN();
  plastic_state = kPlasticStateUnsupported;
  return false;
}

/// The same, deriving the constants from `spec`.
KOKKOS_INLINE_FUNCTION bool updateEffectiveStress(const SolidSpec& spec, Real suction,
                                                  const Real dstrain[kStressComponents],
                                                  Real stress[kStressComponents],
                                                  Real& plastic_strain, int& plastic_state) {
  return updateEffectiveStress(spec, solidConstants(spec), suction, dstrain, stress, plastic_strain,
                               plastic_state);
}

}  // namespace argine

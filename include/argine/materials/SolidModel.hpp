#pragma once
/// @file SolidModel.hpp
/// The effective-stress update of the solid skeleton (thesis Eq. 4.22 with h' = 0 and
/// Bishop's chi = S_L, so suction acts through the strength parameters only), chosen by a
/// switch on SolidSpec::model (no virtual calls in kernels), and the suction-dependent
/// strength parameters of Eqs. 4.23-4.26.
///
/// Status: LinearElastic is implemented. MohrCoulomb and SuctionMohrCoulomb are not yet
/// (later issue). They must not silently behave elastically, so:
///  - the input layer calls isImplemented(model) and rejects a deck that needs a missing
///    model before the run (InputError naming "Materials/<name>/Solid/Model");
///  - if a kernel still reaches updateEffectiveStress() with such a model, the function
///    returns false, sets plastic_state = kPlasticStateUnsupported and fills the stress
///    with NaN, so the run's non-finite check stops with the point's id.

#include "argine/core/Types.hpp"
#include "argine/materials/KernelMath.hpp"
#include "argine/materials/LinearElastic.hpp"
#include "argine/materials/MaterialParameters.hpp"

namespace argine {

/// plastic_state values (points/MaterialPoints.hpp: 0 elastic, 1 plastic, 2 apex).
inline constexpr int kPlasticStateElastic = 0;
inline constexpr int kPlasticStatePlastic = 1;
inline constexpr int kPlasticStateApex = 2;
/// The point's model has no stress update yet (see file comment).
inline constexpr int kPlasticStateUnsupported = -1;

/// Whether updateEffectiveStress() implements `model`.
KOKKOS_INLINE_FUNCTION constexpr bool isImplemented(SolidModel model) {
  switch (model) {
    case SolidModel::LinearElastic:
      return true;
    case SolidModel::MohrCoulomb:
    case SolidModel::SuctionMohrCoulomb:
      return false;
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

/// Update the Bishop effective stress (Pa, tension positive; xx, yy, zz, xy) of one point
/// by the strain increment dstrain (tensor shear in [3], see LinearElastic.hpp). `suction`
/// (Pa, s = -p_L) feeds the suction-dependent models. Returns false, with NaN stress and
/// plastic_state = kPlasticStateUnsupported, for a model that is not implemented.
KOKKOS_INLINE_FUNCTION bool updateEffectiveStress(const SolidSpec& spec, Real suction,
                                                  const Real dstrain[kStressComponents],
                                                  Real stress[kStressComponents],
                                                  Real& plastic_strain, int& plastic_state) {
  (void)suction;         // used by the Mohr-Coulomb models (later issue)
  (void)plastic_strain;  // unchanged by elasticity
  switch (spec.model) {
    case SolidModel::LinearElastic: {
      Real dstress[kStressComponents];
      elasticStressIncrement(spec, dstrain, dstress);
      for (int i = 0; i < kStressComponents; ++i) stress[i] += dstress[i];
      plastic_state = kPlasticStateElastic;
      return true;
    }
    case SolidModel::MohrCoulomb:
    case SolidModel::SuctionMohrCoulomb:
      break;
  }
  for (int i = 0; i < kStressComponents; ++i) stress[i] = kmath::quietNaN();
  plastic_state = kPlasticStateUnsupported;
  return false;
}

}  // namespace argine

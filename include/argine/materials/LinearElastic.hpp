#pragma once
/// @file LinearElastic.hpp
/// Isotropic linear elasticity in plane strain (thesis Eq. 7.4 uses its 1D form).
///
/// Component order of the 4-vectors: xx, yy, zz, xy (points/MaterialPoints.hpp
/// StressComponent). Strain index 3 is the TENSOR shear component eps_xy = gamma_xy / 2,
/// stress index 3 is sigma_xy; so every component obeys d sigma_ij = lambda tr(d eps)
/// delta_ij + 2 G d eps_ij. Tension positive. eps_zz is 0 in plane strain but is taken
/// into account if given.

#include "argine/core/Types.hpp"
#include "argine/materials/MaterialParameters.hpp"

namespace argine {

/// Shear modulus G = E / (2 (1 + nu)) (Pa).
KOKKOS_INLINE_FUNCTION Real shearModulus(const SolidSpec& spec) {
  return spec.youngs_modulus / (2 * (1 + spec.poisson_ratio));
}

/// Bulk modulus K = E / (3 (1 - 2 nu)) (Pa).
KOKKOS_INLINE_FUNCTION Real bulkModulus(const SolidSpec& spec) {
  return spec.youngs_modulus / (3 * (1 - 2 * spec.poisson_ratio));
}

/// Lame's first parameter lambda = E nu / ((1 + nu)(1 - 2 nu)) (Pa).
KOKKOS_INLINE_FUNCTION Real lameLambda(const SolidSpec& spec) {
  const Real nu = spec.poisson_ratio;
  return spec.youngs_modulus * nu / ((1 + nu) * (1 - 2 * nu));
}

/// Constrained (oedometric) modulus E_c = E (1 - nu) / ((1 + nu)(1 - 2 nu)) = lambda + 2G
/// (Pa): the E_c / E'_c of the time-step criteria (Eqs. 4.62-4.67).
KOKKOS_INLINE_FUNCTION Real constrainedModulus(const SolidSpec& spec) {
  const Real nu = spec.poisson_ratio;
  return spec.youngs_modulus * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
}

/// Effective-stress increment of a strain increment: dstress = D dstrain (Pa), with the
/// tensor shear strain in dstrain[3] (see file comment); lambda and 2G given (Pa), e.g.
/// derived once per material (SolidConstants, SolidModel.hpp) instead of at every point.
/// T = Real for one point, Lanes for kLanes points (core/Lanes.hpp).
template <class T>
KOKKOS_INLINE_FUNCTION void elasticStressIncrement(Real lambda, Real two_g,
                                                   const T dstrain[kStressComponents],
                                                   T dstress[kStressComponents]) {
  const T volumetric = dstrain[0] + dstrain[1] + dstrain[2];
  dstress[0] = lambda * volumetric + two_g * dstrain[0];
  dstress[1] = lambda * volumetric + two_g * dstrain[1];
  dstress[2] = lambda * volumetric + two_g * dstrain[2];
  dstress[3] = two_g * dstrain[3];
}

/// The same with lambda and 2G of `spec`.
KOKKOS_INLINE_FUNCTION void elasticStressIncrement(const SolidSpec& spec,
                                                   const Real dstrain[kStressComponents],
                                                   Real dstress[kStressComponents]) {
  elasticStressIncrement(lameLambda(spec), 2 * shearModulus(spec), dstrain, dstress);
}

}  // namespace argine

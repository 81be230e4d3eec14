#pragma once
/// @file ConductivityCurve.hpp
/// Hydraulic conductivity curves (HCC, thesis Sec. 2.5): k = k_sat k_r, with the relative
/// conductivity k_r from the degree of saturation or the suction.
///
/// Which saturation: the thesis writes Hillel (Eq. 4.30) and Mualem (Eq. 4.31) with the
/// degree of saturation S_L, and argine follows it by default; with
/// ConductivitySpec::use_effective_saturation they take S_e = (S_L - S_min)/(S_max - S_min)
/// instead (the usual Mualem-van Genuchten form, k_r = 0 at S_min).
///   constant (Eq. 4.29): k_r = 1
///   Hillel   (Eq. 4.30): k_r = S^r
///   Mualem   (Eq. 4.31): k_r = sqrt(S) [1 - (1 - S^(1/lambda*))^lambda*]^2
///   Gardner exponential: k_r = exp(-alpha s)   (alpha of the HCC, not of the SWRC)
/// Suction s = -p_L (Pa); s <= 0 (saturated) gives k_r = k_r(S_max), i.e. 1 when S_max = 1.

#include "argine/core/Types.hpp"
#include "argine/materials/KernelMath.hpp"
#include "argine/materials/MaterialParameters.hpp"
#include "argine/materials/RetentionCurve.hpp"

namespace argine {

/// k_sat = kappa rho_L g / mu_L (m/s) from the intrinsic permeability kappa (m^2), liquid
/// density (kg/m^3), viscosity (Pa s) and gravity (m/s^2; 9.81 by convention, also when a
/// stage switches gravity off, because k is a material property).
KOKKOS_INLINE_FUNCTION Real saturatedConductivityFromPermeability(Real intrinsic_permeability,
                                                                  Real liquid_density,
                                                                  Real viscosity,
                                                                  Real gravity = kStandardGravity) {
  return intrinsic_permeability * liquid_density * gravity / viscosity;
}

/// The saturation measure S the HCC uses: S_L, or S_e when use_effective_saturation.
KOKKOS_INLINE_FUNCTION Real conductivitySaturation(const ConductivitySpec& spec,
                                                   const RetentionSpec& retention,
                                                   Real saturation) {
  const Real s =
      spec.use_effective_saturation ? effectiveSaturation(retention, saturation) : saturation;
  return kmath::fmin(kmath::fmax(s, Real(0)), Real(1));
}

/// k_r from the saturation measure S in [0, 1] (Hillel and Mualem only; the others do
/// not depend on S and return 1).
KOKKOS_INLINE_FUNCTION Real relativeConductivityOfSaturation(const ConductivitySpec& spec, Real s) {
  switch (spec.model) {
    case ConductivityModel::Hillel:  // Eq. 4.30
      return kmath::powKnown(s, spec.hillel_exponent);
    case ConductivityModel::Mualem: {  // Eq. 4.31
      if (s <= 0) return 0;
      const Real lam = spec.mualem_lambda;
      const Real w = 1 - kmath::powKnown(1 - kmath::powKnown(s, 1 / lam), lam);
      return kmath::sqrt(s) * w * w;
    }
    case ConductivityModel::Constant:
    case ConductivityModel::Gardner:
      return 1;
  }
  return 1;
}

/// dk_r/dS for Hillel and Mualem (0 for the others). The Mualem derivative grows without
/// bound as S -> 1 (the factor (1 - S^(1/lambda*))^(lambda*-1)).
KOKKOS_INLINE_FUNCTION Real relativeConductivitySaturationDerivative(const ConductivitySpec& spec,
                                                                     Real s) {
  switch (spec.model) {
    case ConductivityModel::Hillel:
      return spec.hillel_exponent * kmath::powKnown(s, spec.hillel_exponent - 1);
    case ConductivityModel::Mualem: {
      if (s <= 0 || s >= 1) return 0;
      const Real lam = spec.mualem_lambda;
      const Real u = kmath::powKnown(s, 1 / lam);
      const Real w = 1 - kmath::powKnown(1 - u, lam);
      // d/dS [S^(1/2) w^2] = w^2 / (2 sqrt(S)) + 2 sqrt(S) w dw/dS,
      // dw/dS = (1 - u)^(lam - 1) S^(1/lam - 1).
      const Real dw = kmath::powKnown(1 - u, lam - 1) * u / s;
      return w * w / (2 * kmath::sqrt(s)) + 2 * kmath::sqrt(s) * w * dw;
    }
    case ConductivityModel::Constant:
    case ConductivityModel::Gardner:
      return 0;
  }
  return 0;
}

/// relativeConductivity (below) when the caller has S_L = saturation(retention, suction)
/// already: the SWRC (two pow for van Genuchten) is not evaluated again.
KOKKOS_INLINE_FUNCTION Real relativeConductivityAt(const ConductivitySpec& spec,
                                                   const RetentionSpec& retention, Real suction,
                                                   Real saturation_of_suction) {
  switch (spec.model) {
    case ConductivityModel::Constant:  // Eq. 4.29 with const = 1
      return 1;
    case ConductivityModel::Gardner:
      return suction <= 0 ? 1 : kmath::exp(-spec.gardner_alpha * suction);
    case ConductivityModel::Hillel:
    case ConductivityModel::Mualem:
      return relativeConductivityOfSaturation(
          spec, conductivitySaturation(spec, retention, saturation_of_suction));
  }
  return 1;
}

/// Relative conductivity k_r(s) (-), in [0, 1]. For s <= 0 it is the value at S_L = S_max
/// (1 when S_max = 1 or with S_e), so k_r is continuous at s = 0.
KOKKOS_INLINE_FUNCTION Real relativeConductivity(const ConductivitySpec& spec,
                                                 const RetentionSpec& retention, Real suction) {
  const bool needs_saturation =
      spec.model == ConductivityModel::Hillel || spec.model == ConductivityModel::Mualem;
  return relativeConductivityAt(spec, retention, suction,
                                needs_saturation ? saturation(retention, suction) : Real(1));
}

/// dk_r/ds (1/Pa), <= 0; 0 for s <= 0. Chain rule through the SWRC for Hillel and Mualem.
KOKKOS_INLINE_FUNCTION Real relativeConductivitySuctionDerivative(const ConductivitySpec& spec,
                                                                  const RetentionSpec& retention,
                                                                  Real suction) {
  if (suction <= 0) return 0;
  switch (spec.model) {
    case ConductivityModel::Constant:
      return 0;
    case ConductivityModel::Gardner:
      return -spec.gardner_alpha * kmath::exp(-spec.gardner_alpha * suction);
    case ConductivityModel::Hillel:
    case ConductivityModel::Mualem: {
      const Real s_l = saturation(retention, suction);
      const Real raw = spec.use_effective_saturation ? effectiveSaturation(retention, s_l) : s_l;
      if (raw <= 0 || raw >= 1) return 0;  // clipped: k_r is flat there
      Real ds_ds = saturationSuctionDerivative(retention, suction);
      if (spec.use_effective_saturation) {
        const Real range = retention.saturation_max - retention.saturation_min;
        ds_ds = range > 0 ? ds_ds / range : 0;
      }
      return relativeConductivitySaturationDerivative(spec, raw) * ds_ds;
    }
  }
  return 0;
}

/// Hydraulic conductivity k = k_sat k_r(s) (m/s). k_sat is ConductivitySpec::
/// saturated_conductivity, which the input layer fills (from kappa with
/// saturatedConductivityFromPermeability when the deck gives the permeability).
KOKKOS_INLINE_FUNCTION Real conductivity(const ConductivitySpec& spec,
                                         const RetentionSpec& retention, Real suction) {
  return spec.saturated_conductivity * relativeConductivity(spec, retention, suction);
}

/// The same with S_L = saturation(retention, suction) given (relativeConductivityAt).
KOKKOS_INLINE_FUNCTION Real conductivityAt(const ConductivitySpec& spec,
                                           const RetentionSpec& retention, Real suction,
                                           Real saturation_of_suction) {
  return spec.saturated_conductivity *
         relativeConductivityAt(spec, retention, suction, saturation_of_suction);
}

}  // namespace argine

#pragma once
/// @file RetentionCurve.hpp
/// Soil-water retention curves (SWRC, thesis Sec. 2.5): degree of saturation S_L as a
/// function of suction, its derivative and its inverse.
///
/// Sign convention: argine passes SUCTION s = -p_L >= 0 (Pa); the thesis writes these
/// curves in its tension-positive liquid pressure, which is the same number. s <= 0 means
/// saturated: every curve returns S_L = S_max and dS_L/ds = 0 there, so S_L is continuous
/// at s = 0. The derivative is continuous at s = 0 for van Genuchten (lambda in (0,1));
/// it jumps from 0 to -a_v (linear) or -(S_max - S_min) alpha (Gardner) when the first
/// suction appears, which is the shape of those curves.
///
/// Effective saturation S_e = (S_L - S_min) / (S_max - S_min) (thesis Eq. 4.28 form):
///   linear (Eq. 5.6 / 4.27): S_L = S_max - a_v s, clipped below at S_min
///   van Genuchten (Eq. 4.28): S_e = [1 + (s / p_ref)^(1/(1-lambda))]^(-lambda)
///   Gardner exponential:       S_e = exp(-alpha s)
///
/// Occluded air (an option, RetentionSpec::occluded_air_pressure p_a > 0): below S_max = 1
/// the air left in the pores at zero suction is occluded, and at p_L > 0 it compresses by
/// Boyle's law at constant mass, its absolute pressure p_a + p_L:
///   S_L(p_L) = 1 - (1 - S_max) p_a / (p_a + p_L),   dS_L/dp_L = (1 - S_max) p_a / (p_a + p_L)^2,
/// continuous with S_max at p_L = 0. It turns the liquid's storage at p_L > 0 from
/// n S_L / K_L (water's, 1e-8 1/Pa) into about n (1 - S_max) / p_a (2e-6 1/Pa with 20 % air),
/// as for any air-water mixture (Fredlund & Rahardjo, Soil Mechanics for Unsaturated Soils,
/// 1993; dissolution of the air in the water neglected). The
/// *AtPressure functions take p_L (compression positive) and give it; the suction functions
/// above keep S_max at s <= 0.

#include "argine/core/Types.hpp"
#include "argine/materials/KernelMath.hpp"
#include "argine/materials/MaterialParameters.hpp"

namespace argine {

/// S_e = (S_L - S_min) / (S_max - S_min) (-); 1 when S_max == S_min.
KOKKOS_INLINE_FUNCTION Real effectiveSaturation(const RetentionSpec& spec, Real saturation) {
  const Real range = spec.saturation_max - spec.saturation_min;
  if (range <= 0) return 1;
  return (saturation - spec.saturation_min) / range;
}

namespace detail {
/// Van Genuchten's x = s/p_ref, m = 1/(1-lambda), x^m and (1 + x^m)^(-lambda): the two pows
/// that S_L and dS_L/ds share.
struct VanGenuchtenTerms {
  Real m, x, xm, power;
};
KOKKOS_INLINE_FUNCTION VanGenuchtenTerms vanGenuchtenTerms(const RetentionSpec& spec,
                                                           Real suction) {
  VanGenuchtenTerms t;
  t.m = 1 / (1 - spec.lambda);
  t.x = suction / spec.reference_pressure;
  t.xm = kmath::powKnown(t.x, t.m);
  t.power = kmath::powKnown(1 + t.xm, -spec.lambda);
  return t;
}
/// Eq. 4.28: S_L = S_min + (S_max - S_min) (1 + x^m)^(-lambda).
KOKKOS_INLINE_FUNCTION Real vanGenuchtenSaturation(const RetentionSpec& spec,
                                                   const VanGenuchtenTerms& t) {
  const Real range = spec.saturation_max - spec.saturation_min;
  return spec.saturation_min + range * t.power;
}
/// dS_e/ds = -lambda m x^(m-1) (1 + x^m)^(-lambda-1) / p_ref, times S_max - S_min, with
/// (1 + x^m)^(-lambda-1) = (1 + x^m)^(-lambda) / (1 + x^m) (no third pow).
KOKKOS_INLINE_FUNCTION Real vanGenuchtenSlope(const RetentionSpec& spec,
                                              const VanGenuchtenTerms& t) {
  const Real range = spec.saturation_max - spec.saturation_min;
  return -range * spec.lambda * t.m * (t.xm / t.x) * (t.power / (1 + t.xm)) /
         spec.reference_pressure;
}
}  // namespace detail

/// The linear curve (Eq. 5.6 with S_max in place of 1, clipped at S_min) at suction s > 0:
/// S_L = max(S_max - a_v s, S_min), and its slope dS_L/ds = -a_v above S_min, 0 on the clipped
/// part. T = Real, or Lanes for kLanes points (the Real form's bits in each lane).
template <class T>
KOKKOS_INLINE_FUNCTION T linearSaturation(const RetentionSpec& spec, T suction) {
  return kmath::fmax(spec.saturation_max - spec.linear_slope * suction,
                     splat<T>(spec.saturation_min));
}
template <class T>
KOKKOS_INLINE_FUNCTION T linearSaturationSlope(const RetentionSpec& spec, T suction) {
  return select(spec.saturation_max - spec.linear_slope * suction > spec.saturation_min,
                splat<T>(-spec.linear_slope), splat<T>(0));
}

/// Degree of saturation S_L(s) (-), suction s in Pa (s <= 0: S_max).
KOKKOS_INLINE_FUNCTION Real saturation(const RetentionSpec& spec, Real suction) {
  if (suction <= 0) return spec.saturation_max;
  const Real range = spec.saturation_max - spec.saturation_min;
  switch (spec.model) {
    case RetentionModel::Linear:
      return linearSaturation(spec, suction);
    case RetentionModel::VanGenuchten:  // Eq. 4.28
      return detail::vanGenuchtenSaturation(spec, detail::vanGenuchtenTerms(spec, suction));
    case RetentionModel::Gardner:
      return spec.saturation_min + range * kmath::exp(-spec.gardner_alpha * suction);
  }
  return spec.saturation_max;
}

/// dS_L/ds (1/Pa), <= 0 (saturation falls as suction grows); 0 for s <= 0 and on the
/// clipped (S_L = S_min) part of the linear curve.
KOKKOS_INLINE_FUNCTION Real saturationSuctionDerivative(const RetentionSpec& spec, Real suction) {
  if (suction <= 0) return 0;
  const Real range = spec.saturation_max - spec.saturation_min;
  switch (spec.model) {
    case RetentionModel::Linear:
      return linearSaturationSlope(spec, suction);
    case RetentionModel::VanGenuchten:
      return detail::vanGenuchtenSlope(spec, detail::vanGenuchtenTerms(spec, suction));
    case RetentionModel::Gardner:
      return -range * spec.gardner_alpha * kmath::exp(-spec.gardner_alpha * suction);
  }
  return 0;
}

/// S_L(s) and dS_L/ds(s) together, each to the bit as saturation() and
/// saturationSuctionDerivative() give it; van Genuchten's two pows are taken once (the
/// Newton iteration of the liquid pressure needs both at every iterate).
struct SaturationAndSlope {
  Real saturation;
  Real slope;  ///< dS_L/ds (1/Pa), <= 0
};
KOKKOS_INLINE_FUNCTION SaturationAndSlope saturationAndSlope(const RetentionSpec& spec,
                                                             Real suction) {
  if (suction > 0 && spec.model == RetentionModel::VanGenuchten) {
    const detail::VanGenuchtenTerms t = detail::vanGenuchtenTerms(spec, suction);
    return {detail::vanGenuchtenSaturation(spec, t), detail::vanGenuchtenSlope(spec, t)};
  }
  return {saturation(spec, suction), saturationSuctionDerivative(spec, suction)};
}

/// S_L at p_L > 0 with occluded air (file comment); S_max when the air is rigid (p_a = 0).
/// T = Real, or Lanes (each lane the Real form's bits).
template <class T>
KOKKOS_INLINE_FUNCTION T occludedAirSaturation(const RetentionSpec& spec, T pressure) {
  const Real air = spec.occluded_air_pressure;
  if (!(air > 0)) return splat<T>(spec.saturation_max);
  return 1 - (1 - spec.saturation_max) * air / (air + pressure);
}

/// dS_L/ds = -dS_L/dp_L (1/Pa), <= 0, at p_L > 0 with occluded air (0 when rigid).
template <class T>
KOKKOS_INLINE_FUNCTION T occludedAirSuctionDerivative(const RetentionSpec& spec, T pressure) {
  const Real air = spec.occluded_air_pressure;
  if (!(air > 0)) return splat<T>(0);
  const T absolute = air + pressure;
  return -(1 - spec.saturation_max) * air / (absolute * absolute);
}

/// S_L at the liquid pressure p_L (Pa, compression positive): the curve at the suction
/// s = -p_L, and the occluded air's S_L at p_L > 0.
KOKKOS_INLINE_FUNCTION Real saturationAtPressure(const RetentionSpec& spec, Real pressure) {
  return pressure > 0 ? occludedAirSaturation(spec, pressure) : saturation(spec, -pressure);
}

/// dS_L/ds (1/Pa) at the liquid pressure p_L: -dS_L/dp_L, the slope the storage of 4.12
/// takes (liquidContentSlope).
KOKKOS_INLINE_FUNCTION Real saturationSuctionDerivativeAtPressure(const RetentionSpec& spec,
                                                                  Real pressure) {
  return pressure > 0 ? occludedAirSuctionDerivative(spec, pressure)
                      : saturationSuctionDerivative(spec, -pressure);
}

/// saturationAndSlope at the liquid pressure p_L.
KOKKOS_INLINE_FUNCTION SaturationAndSlope saturationAndSlopeAtPressure(const RetentionSpec& spec,
                                                                       Real pressure) {
  if (pressure > 0)
    return {occludedAirSaturation(spec, pressure), occludedAirSuctionDerivative(spec, pressure)};
  return saturationAndSlope(spec, -pressure);
}

/// S_L and dS_L/ds at the liquid pressures of kLanes points on a linear curve
/// (saturationAndSlopeAtPressure's bits in each lane; the caller checks the model).
KOKKOS_INLINE_FUNCTION void linearSaturationAndSlopeAtPressure(const RetentionSpec& spec,
                                                               Lanes pressure, Lanes& saturation,
                                                               Lanes& slope) {
  const LaneMask wet = pressure > 0, suction_free = -pressure <= 0;
  saturation = select(
      wet, occludedAirSaturation(spec, pressure),
      select(suction_free, splat<Lanes>(spec.saturation_max), linearSaturation(spec, -pressure)));
  slope = select(wet, occludedAirSuctionDerivative(spec, pressure),
                 select(suction_free, splat<Lanes>(0), linearSaturationSlope(spec, -pressure)));
}

/// Inverse of saturation(): the suction s >= 0 (Pa) at which S_L = `saturation`, used to
/// initialise points from a prescribed saturation. S_L >= S_max gives 0. For S_L <= S_min
/// the curve has no unique inverse: the linear curve returns the suction where it reaches
/// S_min, (S_max - S_min)/a_v; van Genuchten and Gardner return +infinity (S_min is their
/// asymptote), as does a linear curve with a_v = 0.
KOKKOS_INLINE_FUNCTION Real suctionFromSaturation(const RetentionSpec& spec, Real saturation) {
  if (saturation >= spec.saturation_max) return 0;
  const Real s_e = effectiveSaturation(spec, saturation);
  switch (spec.model) {
    case RetentionModel::Linear: {
      if (spec.linear_slope <= 0) return kmath::infinity();
      const Real clipped = kmath::fmax(saturation, spec.saturation_min);
      return (spec.saturation_max - clipped) / spec.linear_slope;
    }
    case RetentionModel::VanGenuchten:
      // S_e^(-1/lambda) - 1 = (s/p_ref)^(1/(1-lambda))
      if (s_e <= 0) return kmath::infinity();
      return spec.reference_pressure *
             kmath::powKnown(kmath::powKnown(s_e, -1 / spec.lambda) - 1, 1 - spec.lambda);
    case RetentionModel::Gardner:
      if (s_e <= 0 || spec.gardner_alpha <= 0) return kmath::infinity();
      return -kmath::log(s_e) / spec.gardner_alpha;
  }
  return 0;
}

}  // namespace argine

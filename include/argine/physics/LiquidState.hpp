#pragma once
/// @file LiquidState.hpp
/// The liquid state of a material point as functions of its pressure (one source of truth
/// for each formula), and the liquid mass balance in the form argine integrates.
///
/// Signs: argine's p_L is compression positive; the thesis writes tension-positive
/// pressures (its p_L = -p_L here, its suction = p_L there = s here). Suction s = max(-p_L, 0).
///
/// Mass balance (4.12) in argine's signs. With d rho_L / d p_L = rho_L / K_L (4.13) and
/// dS_L/dp_L = -dS_L/ds:
///   n rho_L (S_L/K_L - dS_L/ds) Dp_L/Dt
///       = -grad(rho_L n S_L).(v_L - v_S) - rho_L n S_L div(v_L - v_S) - rho_L S_L div v_S,
/// the first right-hand term being the advective-gradient term of 4.15-4.16, dropped by the
/// simplified form (4.14). Saturated and undrained (v_L = v_S) it gives dp_L = -(K_L/n) d
/// eps_vol, the thesis' Eq. 2.19.
///
/// argine integrates it in its conservative form. With 4.9, (1-n) V is constant, and 4.12 is
/// exactly  D(n S_L rho_L V)/Dt = -V div(rho_L n S_L (v_L - v_S)):  the point's liquid mass
/// M_L changes only by the relative flux. So each step (i) advances M_L by that flux, and
/// (ii) finds the p_L at which n S_L(p_L) rho_L(p_L) V = M_L with the new n and V. Both
/// forms agree as dt -> 0, but the explicit pressure form mixes t^k storage with t^{k+1}
/// volumes and lets the liquid mass of a closed column drift by O(dt) (measured 5e-9
/// relative in 0.3 s of an undrained test); the conservative form changes the total only by
/// the point quadrature of the flux divergence: round-off on a fixed skeleton, ~1e-7 after
/// a column has settled and moved its points off their symmetric seeded positions.

#include "argine/core/Types.hpp"
#include "argine/materials/ConductivityCurve.hpp"
#include "argine/materials/KernelMath.hpp"
#include "argine/materials/RetentionCurve.hpp"
#include "argine/physics/MaterialTable.hpp"

namespace argine {

/// Suction s = max(-p_L, 0) (Pa), p_L compression positive.
KOKKOS_INLINE_FUNCTION Real suctionOfPressure(Real pressure) {
  return pressure < 0 ? -pressure : 0;
}

/// rho_L(p_L) = rho_L0 exp(p_L / K_L) (kg/m^3): Eq. 4.13 integrated from rho_L0 at p_L = 0
/// (the exponent is small for any soil's pressure: kmath::expNearZero, no library call), of
/// one point (Real) or kLanes points (Lanes); not a template, so that an integer pressure
/// converts to Real.
namespace detail {
template <class T>
KOKKOS_INLINE_FUNCTION T liquidDensity(const LiquidSpec& liquid, T pressure) {
  return liquid.density * kmath::expNearZero(pressure / liquid.bulk_modulus);
}
}  // namespace detail
KOKKOS_INLINE_FUNCTION Real liquidDensity(const LiquidSpec& liquid, Real pressure) {
  return detail::liquidDensity(liquid, pressure);
}
KOKKOS_INLINE_FUNCTION Lanes liquidDensity(const LiquidSpec& liquid, Lanes pressure) {
  return detail::liquidDensity(liquid, pressure);
}

/// Degree of saturation, its suction derivative and the conductivity at one pressure.
struct LiquidState {
  Real saturation = 1;                     ///< S_L (-)
  Real saturation_suction_derivative = 0;  ///< dS_L/ds (1/Pa), <= 0
  Real conductivity = 0;                   ///< k (m/s)
};

/// S_L of a liquid-carrying material at p_L alone (1 unless unsaturated): the SWRC of
/// saturationAndConductivity without the HCC.
KOKKOS_INLINE_FUNCTION Real saturationOfPressure(const PointMaterial& material, Real pressure) {
  if (material.phase != PhaseModel::Unsaturated) return 1;
  return saturationAtPressure(material.retention, pressure);
}

/// S_L and k of a liquid-carrying material at p_L, what a point stores (the derivative is
/// left 0: it costs two more pow calls per unsaturated point, and the point update does not
/// need it). A saturated material skips the retention curve (S_L = 1, k = k_sat); an
/// unsaturated one evaluates the SWRC and the HCC (thesis Sec. 2.5) at the suction.
KOKKOS_INLINE_FUNCTION LiquidState saturationAndConductivity(const PointMaterial& material,
                                                             Real pressure) {
  LiquidState state;
  if (material.phase != PhaseModel::Unsaturated) {
    state.conductivity = material.conductivity.saturated_conductivity;
    return state;
  }
  const Real suction = suctionOfPressure(pressure);
  state.saturation = saturationOfPressure(material, pressure);
  // k at S_L of the suction: S_max at p_L >= 0, where occluded air compressing does not
  // reconnect the water's paths (k continuous at s = 0 either way)
  state.conductivity =
      conductivityAt(material.conductivity, material.retention, suction,
                     pressure > 0 ? material.retention.saturation_max : state.saturation);
  return state;
}

/// S_L, dS_L/ds and k of a liquid-carrying material at p_L: saturationAndConductivity and,
/// for an unsaturated material, the SWRC slope (0 when saturated).
KOKKOS_INLINE_FUNCTION LiquidState liquidState(const PointMaterial& material, Real pressure) {
  LiquidState state = saturationAndConductivity(material, pressure);
  if (material.phase == PhaseModel::Unsaturated)
    state.saturation_suction_derivative =
        saturationSuctionDerivativeAtPressure(material.retention, pressure);
  return state;
}

/// d(S_L rho_L)/dp_L = rho_L (S_L/K_L - dS_L/ds) (kg/m^3/Pa): the storage of 4.12 per unit
/// porosity (4.13 for rho_L, the SWRC for S_L, dS_L/dp_L = -dS_L/ds).
/// T = Real, or Lanes for kLanes points.
template <class T>
KOKKOS_INLINE_FUNCTION T liquidContentSlope(T density, T saturation,
                                            T saturation_suction_derivative, Real bulk_modulus) {
  return density * (saturation / bulk_modulus - saturation_suction_derivative);
}

/// Liquid mass after one step of the relative flux (4.11-4.12 in conservative form):
///   complete (4.12):   M_L^{k+1} = M_L^k - V dt div(c w),  div(c w) = c div w + grad c . w
///   simplified (4.14): M_L^{k+1} = M_L^k - V dt c_p div w = M_L^k (1 - dt div w)
/// with c = rho_L n S_L and w = v_L - v_S. The complete form takes c and w interpolated from
/// the nodes (the nodal mapping of rho_L n S_L of 4.16), so the sum over points of the flux
/// divergence is the boundary flux up to quadrature; the simplified form uses the point's own
/// c_p = M_L / V. Increments over dt: relative_divergence = dt div w, flux_divergence = dt
/// div(c w).
/// T = Real for one point, Lanes for kLanes points (core/Lanes.hpp).
template <class T>
KOKKOS_INLINE_FUNCTION T liquidMassAfterFlux(bool complete, T mass, T volume, T relative_divergence,
                                             T flux_divergence) {
  return complete ? mass - volume * flux_divergence : mass * (1 - relative_divergence);
}

/// The saturated liquid pressure p_L = K_L ln(content / rho_L0) (Pa), the inverse of 4.13, of
/// a liquid content M_L / (n V) (kg/m^3); NaN for a non-positive content. T = Real, or Lanes
/// for kLanes points.
template <class T>
KOKKOS_INLINE_FUNCTION T saturatedPressureOfContent(const LiquidSpec& liquid, T content) {
  if constexpr (std::is_same_v<T, Real>) {
    if (!(content > 0)) return kmath::quietNaN();
    return liquid.bulk_modulus * kmath::logNearOne(content / liquid.density);
  } else {
    return select(content > 0, liquid.bulk_modulus * kmath::logNearOne(content / liquid.density),
                  splat<T>(kmath::quietNaN()));
  }
}

/// The liquid pressure p_L (Pa) at which S_L(p_L) rho_L(p_L) equals the liquid content
/// `content` = M_L / (n V) (kg/m^3). Saturated (S_L = 1): p_L = K_L ln(content / rho_L0),
/// the inverse of 4.13. Unsaturated: Newton iterations from `guess` on the increasing
/// function S_L rho_L, whose derivative is rho_L (S_L/K_L - dS_L/ds) (the storage of 4.12);
/// a step out of the bracket bisects it, and before there is one (a guess where S_L = 0 and
/// the function is flat) the pressure walks towards the root in doubling steps.
/// A non-positive content gives NaN (the run's non-finite check then stops it).
KOKKOS_INLINE_FUNCTION Real pressureOfLiquidContent(const PointMaterial& material, Real content,
                                                    Real guess) {
  if (material.phase != PhaseModel::Unsaturated)
    return saturatedPressureOfContent(material.liquid, content);
  const Real bulk = material.liquid.bulk_modulus;
  if (!(content > 0)) return kmath::quietNaN();
  // Safeguarded Newton: S_L rho_L - content is increasing in p_L, so every iterate brackets
  // the root from one side; a Newton step leaving the bracket (the SWRC has a kink at s = 0)
  // is replaced by bisection.
  Real pressure = guess;
  Real low = -kmath::infinity(), high = kmath::infinity();
  constexpr int kMaxIterations = 60;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    const SaturationAndSlope swrc = saturationAndSlopeAtPressure(material.retention, pressure);
    const Real s = swrc.saturation;
    const Real rho = liquidDensity(material.liquid, pressure);
    const Real residual = s * rho - content;
    // the root itself (a zero step would fail the strict bracket test and bisect away from it)
    if (residual == 0) break;
    if (residual > 0)
      high = pressure;
    else
      low = pressure;
    const Real slope = liquidContentSlope(rho, s, swrc.slope, bulk);
    Real next = pressure - residual / slope;
    const bool bracketed = low > -kmath::infinity() && high < kmath::infinity();
    if (!(next > low && next < high)) {
      if (bracketed) {
        next = 0.5 * (low + high);
      } else if (!kmath::isFinite(next) || next < low || next > high) {
        // a flat stretch (S_L = S_min = 0: no slope) gave a non-finite step: walk towards
        // the root, doubling, until it is bracketed (a step too small to move stays: done)
        const Real step = kmath::fmax(kmath::fabs(pressure), 1e-3 * bulk);
        next = residual > 0 ? pressure - step : pressure + step;
      }
    }
    const Real change = kmath::fabs(next - pressure);
    pressure = next;
    if (change <= 1e-14 * bulk) break;
  }
  return pressure;
}

/// pressureOfLiquidContent of kLanes points of one unsaturated material with a linear
/// retention curve, all lanes at once: the same iterates in each lane (so the one-point
/// function's bits) as long as every step is a plain Newton step inside its lane's bracket;
/// a lane that has converged keeps its pressure while the others go on. Returns false,
/// `pressure` untouched, where some lane needs more (a content that is not positive, a
/// step out of the bracket at the kink s = 0 or on the flat S_L = S_min, more than
/// kLaneIterations iterations): the caller then takes the one-point function lane by lane.
/// kGroups Lanes values of the same material side by side: each iteration is one chain of
/// dependent operations (the polynomial exp, then a division), so two groups iterated
/// together fill the pipeline that one leaves idle; every lane's iterates are still its own.
template <int kGroups>
KOKKOS_INLINE_FUNCTION bool pressureOfLiquidContentLanes(const PointMaterial& material,
                                                         const Lanes (&content)[kGroups],
                                                         const Lanes (&guess)[kGroups],
                                                         Lanes (&pressure)[kGroups]) {
  constexpr int kLaneIterations = 8;
  for (int g = 0; g < kGroups; ++g)
    if (anyLane(~(content[g] > 0))) return false;
  const Real bulk = material.liquid.bulk_modulus;
  Lanes current[kGroups], low[kGroups], high[kGroups];
  LaneMask done[kGroups];
  for (int g = 0; g < kGroups; ++g) {
    current[g] = guess[g];
    low[g] = splat<Lanes>(-kmath::infinity());
    high[g] = splat<Lanes>(kmath::infinity());
    done[g] = LaneMask{};  // all lanes still iterating
  }
  for (int iteration = 0; iteration < kLaneIterations; ++iteration) {
    bool all_done = true;
    for (int g = 0; g < kGroups; ++g) {
      Lanes s, swrc_slope;
      linearSaturationAndSlopeAtPressure(material.retention, current[g], s, swrc_slope);
      const Lanes rho = liquidDensity(material.liquid, current[g]);
      const Lanes residual = s * rho - content[g];
      // at the root: kept, as the one-point loop stops there
      done[g] = either(done[g], residual == 0);
      const LaneMask above = residual > 0;
      high[g] = select(above, current[g], high[g]);
      low[g] = select(above, low[g], current[g]);
      const Lanes next = current[g] - residual / liquidContentSlope(rho, s, swrc_slope, bulk);
      if (anyLane(~done[g] & ~both(next > low[g], next < high[g]))) return false;
      const LaneMask converged = kmath::fabs(next - current[g]) <= 1e-14 * bulk;
      current[g] = select(done[g], current[g], next);
      done[g] = either(done[g], converged);
      all_done = all_done && !anyLane(~done[g]);
    }
    if (all_done) {
      for (int g = 0; g < kGroups; ++g) pressure[g] = current[g];
      return true;
    }
  }
  return false;
}
KOKKOS_INLINE_FUNCTION bool pressureOfLiquidContentLanes(const PointMaterial& material,
                                                         Lanes content, Lanes guess,
                                                         Lanes& pressure) {
  const Lanes contents[1] = {content}, guesses[1] = {guess};
  Lanes pressures[1];
  if (!pressureOfLiquidContentLanes<1>(material, contents, guesses, pressures)) return false;
  pressure = pressures[0];
  return true;
}

}  // namespace argine

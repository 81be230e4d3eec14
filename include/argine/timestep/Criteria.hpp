#pragma once
/// @file Criteria.hpp
/// Critical time-step criteria of the explicit two-phase MPM at one material point
/// (thesis Ch. 4 Sec. 7, Table 4.4, Appendix Eqs. 7.22-7.40). Each returns the critical
/// step (s); +infinity means "this criterion sets no limit here". The step controller takes
/// the minimum over points and selected criteria times a safety factor.
///
/// Conventions:
///  - L_i = element_size (the thesis uses the minimum element altitude).
///  - Suction derivative: argine's dS_L/ds <= 0; the criteria need the retention storage
///    |dS_L/ds| >= 0 (the thesis writes it as "dS_L/ds" in Eqs. 4.63 and 7.8), so the sign of
///    the input is ignored.
///  - Effective liquid stiffness (Eq. 7.8 times L_i^2): K_e = S_L / (|dS_L/ds| + S_L/K_L);
///    K_e = K_L when saturated. S_L = 0 gives K_e = 0.
///  - Drag: the thesis writes mu_L / k_L with k_L the (relative) intrinsic permeability;
///    argine uses the current hydraulic conductivity k = kappa rho_L g / mu_L (m/s), so
///    mu_L / kappa = rho_L g / k with the physical rho_L. q_L = S_L n mu_L/kappa (Eq. 7.7).
///  - Mass scaling f multiplies every density where it acts as inertia (rho_S, rho_L, and
///    so rho_sat, rho_m): wave criteria grow like sqrt(f). It does NOT touch the drag
///    coefficient (rho_L g / k, a viscous property) nor the parabolic criteria
///    (consolidation, infiltration), which have no inertia.
///  - Implicit drag (`Liquid Drag: implicit`, MomentumBalance.hpp): the drag no longer
///    bounds the step, so liquidDrag is 0 and the momentum criteria reduce to their
///    undamped wave limits (xi = 0, a = 0); the parabolic criteria keep k: the pore pressure
///    still diffuses explicitly through the mass balance.

#include "argine/core/Types.hpp"
#include "argine/materials/KernelMath.hpp"
#include "argine/timestep/CriterionKind.hpp"

namespace argine {

/// Everything the criteria need at one material point (SI units).
struct CriterionInput {
  Real element_size = 0;                   ///< L_i (m)
  Real porosity = 0;                       ///< n (-), 0 < n < 1
  Real saturation = 1;                     ///< S_L (-)
  Real saturation_suction_derivative = 0;  ///< dS_L/ds (1/Pa); sign ignored, see above
  Real solid_density = 0;                  ///< rho_S, grain density (kg/m^3)
  Real liquid_density = 1000;              ///< rho_L (kg/m^3)
  Real liquid_bulk_modulus = 2.2e9;        ///< K_L (Pa)
  Real constrained_modulus = 0;            ///< E'_c = E(1-nu)/((1+nu)(1-2nu)) (Pa)
  Real hydraulic_conductivity = 0;         ///< k = k_sat k_r(S_L) (m/s)
  Real gravity = kStandardGravity;         ///< g used in k = kappa rho_L g / mu_L (m/s^2)
  Real mass_scaling = 1;                   ///< f >= 1, multiplies the densities
  bool implicit_drag = false;              ///< the drag solved implicitly: no drag terms
};

/// Every criterion, in enum order (for name lookup and loops).
inline constexpr CriterionKind kAllCriteria[] = {CriterionKind::CflDry,
                                                 CriterionKind::CflUndrained,
                                                 CriterionKind::Consolidation,
                                                 CriterionKind::Infiltration,
                                                 CriterionKind::UnsaturatedLiquid,
                                                 CriterionKind::UnsaturatedMixture,
                                                 CriterionKind::UnsaturatedCoupled,
                                                 CriterionKind::Mieremet,
                                                 CriterionKind::MieremetLiquidDrag};

/// Name for logs and decks.
inline constexpr const char* criterionName(CriterionKind kind) {
  switch (kind) {
    case CriterionKind::CflDry:
      return "CFL dry";
    case CriterionKind::CflUndrained:
      return "CFL undrained";
    case CriterionKind::Consolidation:
      return "consolidation";
    case CriterionKind::Infiltration:
      return "infiltration";
    case CriterionKind::UnsaturatedLiquid:
      return "liquid";
    case CriterionKind::UnsaturatedMixture:
      return "mixture";
    case CriterionKind::UnsaturatedCoupled:
      return "coupled";
    case CriterionKind::Mieremet:
      return "Mieremet";
    case CriterionKind::MieremetLiquidDrag:
      return "Mieremet liquid drag";
  }
  return "unknown";
}

// ---- shared terms ------------------------------------------------------------------------

/// K_e = S_L / (|dS_L/ds| + S_L / K_L) (Pa), Eq. 7.8 without the 1/L_i^2.
KOKKOS_INLINE_FUNCTION Real effectiveLiquidStiffness(const CriterionInput& in) {
  if (in.saturation <= 0) return 0;
  return in.saturation /
         (kmath::fabs(in.saturation_suction_derivative) + in.saturation / in.liquid_bulk_modulus);
}

/// mu_L / kappa = rho_L g / k (Pa s / m^2), with the physical (unscaled) rho_L.
KOKKOS_INLINE_FUNCTION Real dragCoefficient(const CriterionInput& in) {
  if (in.hydraulic_conductivity <= 0) return kmath::infinity();
  return in.liquid_density * in.gravity / in.hydraulic_conductivity;
}

/// q_L = S_L n mu_L / kappa (Pa s / m^2), Eq. 7.7; 0 without liquid (even if k = 0).
KOKKOS_INLINE_FUNCTION Real liquidDrag(const CriterionInput& in) {
  if (in.implicit_drag) return 0;
  const Real liquid_fraction = in.saturation * in.porosity;
  if (!(liquid_fraction > 0)) return 0;
  return liquid_fraction * dragCoefficient(in);
}

/// Eq. 4.65: dt = (2/omega) [-xi + sqrt(xi^2 + 1)], evaluated as
/// 2 / (omega [xi + sqrt(xi^2 + 1)]) (same value, no cancellation when xi is large).
KOKKOS_INLINE_FUNCTION Real yerroStep(Real omega, Real xi) {
  if (!(omega > 0)) return kmath::infinity();
  if (xi == kmath::infinity()) return 0;
  return 2 / (omega * (xi + kmath::sqrt(xi * xi + 1)));
}

// ---- the criteria --------------------------------------------------------------------------

/// Eq. 4.62 with Eq. 4.64, dry: dt = L_i / sqrt(E'_c / rho_dry), rho_dry = (1-n) rho_S f.
KOKKOS_INLINE_FUNCTION Real criticalStepCflDry(const CriterionInput& in) {
  if (!(in.constrained_modulus > 0)) return kmath::infinity();
  const Real rho_dry = (1 - in.porosity) * in.solid_density * in.mass_scaling;
  return in.element_size * kmath::sqrt(rho_dry / in.constrained_modulus);
}

/// Eq. 4.62 with Eq. 4.64, undrained (saturated reference, as in the thesis):
/// dt = L_i / sqrt((E'_c + K_L/n) / rho_sat), rho_sat = [(1-n) rho_S + n rho_L] f.
/// (The thesis prints "E'_c + n/K_L"; K_L/n is the dimensionally right undrained term.)
KOKKOS_INLINE_FUNCTION Real criticalStepCflUndrained(const CriterionInput& in) {
  const Real n = in.porosity;
  const Real rho_sat = ((1 - n) * in.solid_density + n * in.liquid_density) * in.mass_scaling;
  const Real modulus = in.constrained_modulus + in.liquid_bulk_modulus / n;
  return in.element_size * kmath::sqrt(rho_sat / modulus);
}

/// Eq. 4.61, dt = L_i^2 / (2c), with c from Eq. 4.63 written with the hydraulic
/// conductivity: c = k / (rho_L g [1/E'_c + S n/K_L + n |dS_L/ds|]).
KOKKOS_INLINE_FUNCTION Real parabolicStep(const CriterionInput& in, Real saturation,
                                          Real storage_derivative) {
  const Real n = in.porosity;
  Real compressibility = saturation * n / in.liquid_bulk_modulus + n * storage_derivative;
  if (in.constrained_modulus > 0) compressibility += 1 / in.constrained_modulus;
  const Real c = in.hydraulic_conductivity / (in.liquid_density * in.gravity * compressibility);
  if (!(c > 0)) return kmath::infinity();
  return in.element_size * in.element_size / (2 * c);
}

/// Consolidation, Eq. 4.61 with the saturated consolidation coefficient (Eq. 4.63 at
/// S_L = 1, dS_L/ds = 0): c_v = k / (rho_L g [1/E'_c + n/K_L]). Ignores S_L; f-independent.
KOKKOS_INLINE_FUNCTION Real criticalStepConsolidation(const CriterionInput& in) {
  return parabolicStep(in, 1, 0);
}

/// Infiltration, Eq. 4.61 with the full Eq. 4.63 (S_L and retention storage). f-independent.
KOKKOS_INLINE_FUNCTION Real criticalStepInfiltration(const CriterionInput& in) {
  return parabolicStep(in, in.saturation, kmath::fabs(in.saturation_suction_derivative));
}

/// Liquid momentum balance, Eqs. 7.30-7.32 (Table 4.4 "Liquid", unsaturated):
/// omega_L = sqrt(K_e / rho_L) / L_i, xi_L = q_L / (2 omega_L rho_L), q_L = S_L n mu/kappa.
KOKKOS_INLINE_FUNCTION Real criticalStepUnsaturatedLiquid(const CriterionInput& in) {
  const Real rho_l = in.liquid_density * in.mass_scaling;
  const Real omega = kmath::sqrt(effectiveLiquidStiffness(in) / rho_l) / in.element_size;
  const Real q = liquidDrag(in);
  return yerroStep(omega, q / (2 * omega * rho_l));
}

/// Mixture momentum balance, Eqs. 7.37-7.40 (Table 4.4 "Mixture", unsaturated):
/// omega_M^2 = [E'_c/(1-n) + (1/n - S_L) K_e] / (rho_S L_i^2),
/// xi_M = n S_L q_L / (2 (1-n) rho_S omega_M).
KOKKOS_INLINE_FUNCTION Real criticalStepUnsaturatedMixture(const CriterionInput& in) {
  const Real n = in.porosity;
  const Real s = in.saturation;
  const Real rho_s = in.solid_density * in.mass_scaling;
  const Real stiffness =
      in.constrained_modulus / (1 - n) + (1 / n - s) * effectiveLiquidStiffness(in);
  const Real omega = kmath::sqrt(stiffness / rho_s) / in.element_size;
  const Real q = liquidDrag(in);
  return yerroStep(omega, n * s * q / (2 * (1 - n) * rho_s * omega));
}

/// Coupled liquid + mixture momentum balances, Eqs. 7.22-7.25 (Table 4.4 "Coupled"):
/// omega_C^2 = {K_e [1/rho_L + (1/n - S_L)/rho_S] + E'_c / (rho_S (1-n))} / L_i^2,
/// xi_C = q_L [S_L n / ((1-n) rho_S) + 1/rho_L] / (2 omega_C).
KOKKOS_INLINE_FUNCTION Real criticalStepUnsaturatedCoupled(const CriterionInput& in) {
  const Real n = in.porosity;
  const Real s = in.saturation;
  const Real rho_s = in.solid_density * in.mass_scaling;
  const Real rho_l = in.liquid_density * in.mass_scaling;
  const Real k_e = effectiveLiquidStiffness(in);
  const Real omega2 =
      k_e * (1 / rho_l + (1 / n - s) / rho_s) + in.constrained_modulus / (rho_s * (1 - n));
  const Real omega = kmath::sqrt(omega2) / in.element_size;
  const Real q = liquidDrag(in);
  return yerroStep(omega, q * (s * n / ((1 - n) * rho_s) + 1 / rho_l) / (2 * omega));
}

/// Eq. 4.67 with the drag term `a` (1/s) given and b, d of the unsaturated adaptation of
/// Sec. 7.2 (K_L -> K_e, rho_sat -> rho_m; identical to Table 4.5's saturated b, d at S_L = 1):
///   rho_m = (1-n) rho_S + S_L n rho_L
///   b = 4 [n rho_m K_e + (1-2n) rho_L K_e + n rho_L E'_c] / (n (1-n) rho_S rho_L L_i^2)
///   d = 16 E'_c K_e / ((1-n) rho_S rho_L L_i^4)
///   dt = (-2a + sqrt(4a^2 + 8B)) / B,  B = b + sqrt(b^2 - 4d),
/// evaluated as dt = 8 / (2a + sqrt(4a^2 + 8B)) (same value, finite as B -> 0).
/// Densities carry f, so b, d become b/f, d/f^2 (the callers' a becomes a/f). Where the
/// adaptation has b^2 < 4d (very dry states, thesis Sec. 7.3) the inner root is taken as 0.
KOKKOS_INLINE_FUNCTION Real mieremetStep(const CriterionInput& in, Real a) {
  const Real n = in.porosity;
  const Real s = in.saturation;
  const Real dx2 = in.element_size * in.element_size;
  const Real rho_s = in.solid_density * in.mass_scaling;
  const Real rho_l = in.liquid_density * in.mass_scaling;
  const Real rho_m = (1 - n) * rho_s + s * n * rho_l;
  const Real k_e = effectiveLiquidStiffness(in);
  const Real e_c = in.constrained_modulus;
  const Real b = 4 * (n * rho_m * k_e + (1 - 2 * n) * rho_l * k_e + n * rho_l * e_c) /
                 (n * (1 - n) * rho_s * rho_l * dx2);
  const Real d = 16 * e_c * k_e / ((1 - n) * rho_s * rho_l * dx2 * dx2);
  const Real big_b = kmath::fmax(b + kmath::sqrt(kmath::fmax(b * b - 4 * d, Real(0))), Real(0));
  if (a == kmath::infinity()) return 0;
  const Real denominator = 2 * a + kmath::sqrt(4 * a * a + 8 * big_b);
  if (!(denominator > 0)) return kmath::infinity();
  return 8 / denominator;
}

/// q_L rho_m / ((1-n) rho_S rho_L) (1/s): Mieremet's drag term a with the drag q_L (Eq. 7.7);
/// at S_L = 1 Table 4.5's a = n rho_sat (mu/kappa) / ((1-n) rho_S rho_L). 0 without liquid.
KOKKOS_INLINE_FUNCTION Real mieremetDragTerm(const CriterionInput& in) {
  const Real n = in.porosity;
  const Real rho_s = in.solid_density * in.mass_scaling;
  const Real rho_l = in.liquid_density * in.mass_scaling;
  const Real rho_m = (1 - n) * rho_s + in.saturation * n * rho_l;
  return liquidDrag(in) * rho_m / ((1 - n) * rho_s * rho_l);
}

/// Mieremet, Eq. 4.67 with the terms of Anura3D / Table 4.5, in the unsaturated adaptation
/// of Sec. 7.2 (identical to the saturated criterion at S_L = 1, dS_L/ds = 0):
///   a = S_L^2 n rho_m (mu/kappa) / ((1-n) rho_S rho_L)  (= n rho_sat g / ((1-n) rho_S k)),
/// i.e. S_L times mieremetDragTerm, with b, d of mieremetStep.
KOKKOS_INLINE_FUNCTION Real criticalStepMieremet(const CriterionInput& in) {
  // S_L^2 n mu/kappa = S_L q_L; written so that S_L = 0 gives a = 0 even when k = 0.
  const Real a = in.saturation > 0 ? in.saturation * mieremetDragTerm(in) : Real(0);
  return mieremetStep(in, a);
}

/// Mieremet with the unsaturated liquid drag: Eq. 4.67, b and d as criticalStepMieremet, but
/// the damping term carries the drag q_L = S_L n mu/kappa of Eq. 7.7 once, as the Yerro-type
/// unsaturated criteria of Table 4.4 do (xi_L, xi_C ~ S_L n mu/kappa), instead of S_L^2 q:
///   a = S_L n rho_m (mu/kappa) / ((1-n) rho_S rho_L) = mieremetDragTerm.
/// Identical to criticalStepMieremet at S_L = 1. With strong drag dt -> 2/a grows like
/// 1/(S_L rho_m) as the soil desaturates, not 1/(S_L^2 rho_m): the V5 study
/// (doc/stability.md) measures 1/(S_L rho_m) in argine at kappa = 7e-12 m^2, where the
/// S_L^2 form allows up to 2.6x the empirical critical step.
KOKKOS_INLINE_FUNCTION Real criticalStepMieremetLiquidDrag(const CriterionInput& in) {
  return mieremetStep(in, mieremetDragTerm(in));
}

/// Whether criterion `kind` reads the retention storage |dS_L/ds| (through K_e or the
/// infiltration's diffusivity): the CFL criteria and consolidation do not, so a stage that
/// uses only those needs no SWRC slope at the points (two pow calls a point for van
/// Genuchten, TimeStepControl).
inline constexpr bool readsSaturationSlope(CriterionKind kind) {
  return kind != CriterionKind::CflDry && kind != CriterionKind::CflUndrained &&
         kind != CriterionKind::Consolidation;
}

/// The critical step of one criterion (s).
KOKKOS_INLINE_FUNCTION Real criticalStep(CriterionKind kind, const CriterionInput& in) {
  switch (kind) {
    case CriterionKind::CflDry:
      return criticalStepCflDry(in);
    case CriterionKind::CflUndrained:
      return criticalStepCflUndrained(in);
    case CriterionKind::Consolidation:
      return criticalStepConsolidation(in);
    case CriterionKind::Infiltration:
      return criticalStepInfiltration(in);
    case CriterionKind::UnsaturatedLiquid:
      return criticalStepUnsaturatedLiquid(in);
    case CriterionKind::UnsaturatedMixture:
      return criticalStepUnsaturatedMixture(in);
    case CriterionKind::UnsaturatedCoupled:
      return criticalStepUnsaturatedCoupled(in);
    case CriterionKind::Mieremet:
      return criticalStepMieremet(in);
    case CriterionKind::MieremetLiquidDrag:
      return criticalStepMieremetLiquidDrag(in);
  }
  return kmath::infinity();
}

}  // namespace argine

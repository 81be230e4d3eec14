#pragma once
/// @file K0Formulas.hpp
/// The point formulas of the K0 procedure (thesis Ch. 4 Sec. 5.1, Figs. 4.6-4.7), one
/// function each. Signs: stresses tension positive, p_L compression positive.
///
///   hydrostatic p_L:      p_L = rho_L g (y_ph - y), above the phreatic surface p_L < 0
///                         (suction), capped at -s_max when a maximum suction is given
///                         (Fig. 4.7 (a)); linear without a cap (Fig. 4.7 (b))
///   unit weight:          gamma = (1 - n) rho_S g + n S_L rho_L g (dry: (1 - n) rho_S g)
///   total vertical:       sigma_yy(y) = -( int_y^{y_ground} gamma dz + rho_L g max(0, y_ph -
///   y_ground) ) Bishop (4.5):         sigma'_yy = sigma_yy + S_L p_L   (chi = S_L) horizontal:
///   sigma'_xx = sigma'_zz = K0 sigma'_yy, sigma'_xy = 0

#include "argine/core/Types.hpp"
#include "argine/materials/KernelMath.hpp"
#include "argine/physics/BishopStress.hpp"

namespace argine {

/// Hydrostatic liquid pressure (Pa) at height y (m) under a phreatic surface at y_ph (m),
/// liquid density rho_L (kg/m3), gravity g (m/s2); suction beyond `max_suction` (Pa) is cut
/// to it (pass a negative max_suction for no cap).
KOKKOS_INLINE_FUNCTION Real hydrostaticPressure(Real liquid_density, Real gravity, Real phreatic_y,
                                                Real y, Real max_suction) {
  const Real pressure = liquid_density * gravity * (phreatic_y - y);
  if (max_suction >= 0 && pressure < -max_suction) return -max_suction;
  return pressure;
}

/// Unit weight of a soil layer (N/m3): (1 - n) rho_S g + n S_L rho_L g; a dry layer passes
/// saturation 0 (its pores hold no liquid).
KOKKOS_INLINE_FUNCTION Real unitWeight(Real porosity, Real solid_density, Real saturation,
                                       Real liquid_density, Real gravity) {
  return ((1 - porosity) * solid_density + porosity * saturation * liquid_density) * gravity;
}

/// Bishop's effective vertical stress (4.5, chi = S_L): sigma' = sigma + S_L p_L (Pa).
KOKKOS_INLINE_FUNCTION Real bishopEffectiveStress(Real total_stress, Real saturation,
                                                  Real pressure) {
  return total_stress + bishopPorePressure(saturation, pressure);
}

}  // namespace argine

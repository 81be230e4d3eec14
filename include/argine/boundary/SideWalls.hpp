#pragma once
/// @file SideWalls.hpp
/// The formulas of the side walls of a quasi-2D channel (deck `side walls`), the only place
/// they are written; physics/SideWallFriction applies them on the grid.
///
/// A plane-strain section stands for a channel of width W between two rigid walls at rest
/// (z = -W/2 and z = W/2), as in laboratory flume and column-collapse experiments. Averaged
/// over the width, the walls' shear tractions are a body force in the plane of the section
/// (per unit volume):
///   |f_w| = 2 tau_w / W,   tau_w = mu sigma'_n,   sigma'_n = max(-sigma'_zz, 0),
/// with sigma'_zz the out-of-plane effective stress of plane strain (tension positive, so
/// compression presses the soil on the walls; a soil-wall interface carries shear by its
/// effective normal stress, the pore liquid slides freely), and the force opposing the solid
/// velocity. Coulomb's law makes it set-valued at rest: the walls take up to |f_w| V, no more
/// than what stops the soil (frictionSlowedVelocity), never reversing it. This is the
/// width-averaged wall friction of depth-averaged and quasi-2D granular-flow models (e.g.
/// Jop, Forterre & Pouliquen 2005, J. Fluid Mech. 541, 167-192, their side-wall term
/// mu_w p / W with a hydrostatic p; here p is the soil's own sigma'_zz).

#include "argine/core/Types.hpp"

namespace argine {

/// Channel width and wall coefficient of a stage's `side walls` condition.
struct SideWallParameters {
  Real width = 0;     ///< W (m), > 0
  Real friction = 0;  ///< Coulomb mu of the soil on the walls (-), >= 0
};

/// The walls' resistance per unit volume (N/m^3) of soil with out-of-plane effective
/// stress `sigma_zz` (Pa, tension positive): 2 mu max(-sigma_zz, 0) / width, for a Coulomb
/// coefficient `mu` >= 0 and a channel `width` > 0 (m).
KOKKOS_INLINE_FUNCTION Real sideWallResistance(Real sigma_zz, Real mu, Real width) {
  return sigma_zz < 0 ? 2 * mu * (-sigma_zz) / width : Real(0);
}

/// The velocity `v` after a friction impulse that can take `speed_loss` (>= 0, m/s) off its
/// magnitude, against the motion: v (1 - speed_loss / |v|), or zero (stick) when the impulse
/// is enough to stop it. Returns whether the result is at rest.
KOKKOS_INLINE_FUNCTION bool frictionSlowedVelocity(const Real v[kDim], Real speed_loss,
                                                   Real out[kDim]) {
  const Real speed = Kokkos::Experimental::sqrt(v[0] * v[0] + v[1] * v[1]);
  if (!(speed > speed_loss)) {  // stick (also speed 0: nothing to slow)
    out[0] = out[1] = 0;
    return true;
  }
  const Real scale = (speed - speed_loss) / speed;
  out[0] = v[0] * scale;
  out[1] = v[1] * scale;
  return false;
}

}  // namespace argine

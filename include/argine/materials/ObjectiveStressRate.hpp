#pragma once
/// @file ObjectiveStressRate.hpp
/// The rotation of the stress by the material spin over one step, so that the stress rate
/// the constitutive models see is objective (Jaumann rate): a rigidly rotating body keeps
/// its stress invariants and its stress turns with it.
///
/// The Jaumann rate is sigma_dot = sigma^J + W sigma - sigma W, W = skew(L) the spin
/// (L = grad v). Over a step with spin increment dW = dt W = [[0, w], [-w, 0]] in the plane,
/// w = dt (dv_x/dy - dv_y/dx) / 2, the first-order update sigma += dW sigma - sigma dW is
/// replaced by its exactly orthogonal (Hughes-Winget) form sigma <- Q sigma Q^T,
/// Q = (I - dW/2)^-1 (I + dW/2), which agrees to first order in w but keeps the invariants
/// exactly for any number of steps. In 2D, Q is the rotation matrix [[c, s], [-s, c]] with
///   c = (1 - w^2/4) / (1 + w^2/4),  s = w / (1 + w^2/4).
/// sigma_zz (out of plane) does not rotate.

#include "argine/core/Types.hpp"

namespace argine {

/// The spin increment w = dt (L_xy - L_yx) / 2 = dt (dv_x/dy - dv_y/dx) / 2 (rad) of a
/// velocity gradient L_jk = dv_j/dx_k. A counter-clockwise rigid rotation at rate omega
/// (v = omega (-y, x)) gives w = -omega dt.
KOKKOS_INLINE_FUNCTION Real spinIncrement(Real dt, Real dvx_dy, Real dvy_dx) {
  return Real(0.5) * dt * (dvx_dy - dvy_dx);
}

/// sigma <- Q sigma Q^T for the spin increment w (file comment); components xx, yy, zz, xy.
/// To first order: d sigma_xx = 2 w sigma_xy, d sigma_yy = -2 w sigma_xy,
/// d sigma_xy = w (sigma_yy - sigma_xx).
KOKKOS_INLINE_FUNCTION void rotateStressBySpin(Real w, Real stress[kStressComponents]) {
  if (w == 0) return;
  const Real q = 1 + w * w / 4;
  const Real c = (1 - w * w / 4) / q, s = w / q;
  const Real xx = stress[0], yy = stress[1], zz = stress[2], xy = stress[3];
  // Q sigma Q^T with Q = [[c, s], [-s, c]]. All four components are written together (zz
  // unchanged): a caller that reads the stress back as one vector then finds it in one
  // store, not three scalar stores around an older value (a store-forwarding stall).
  const Real rotated[kStressComponents] = {c * c * xx + 2 * c * s * xy + s * s * yy,
                                           s * s * xx - 2 * c * s * xy + c * c * yy, zz,
                                           c * s * (yy - xx) + (c * c - s * s) * xy};
  for (int i = 0; i < kStressComponents; ++i) stress[i] = rotated[i];
}

}  // namespace argine

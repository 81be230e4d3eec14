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

#include <type_traits>

#include "argine/core/Lanes.hpp"
#include "argine/core/Types.hpp"

namespace argine {

/// The spin increment w = dt (L_xy - L_yx) / 2 = dt (dv_x/dy - dv_y/dx) / 2 (rad) of a
/// velocity gradient L_jk = dv_j/dx_k. A counter-clockwise rigid rotation at rate omega
/// (v = omega (-y, x)) gives w = -omega dt.
/// T = Real for one point, Lanes for kLanes points (core/Lanes.hpp).
template <class T>
KOKKOS_INLINE_FUNCTION T spinIncrement(Real dt, T dvx_dy, T dvy_dx) {
  return Real(0.5) * dt * (dvx_dy - dvy_dx);
}

/// sigma <- Q sigma Q^T for the spin increment w (file comment); components xx, yy, zz, xy.
/// To first order: d sigma_xx = 2 w sigma_xy, d sigma_yy = -2 w sigma_xy,
/// d sigma_xy = w (sigma_yy - sigma_xx). w = 0 leaves the stress as it is (bit for bit).
/// T = Real for one point, Lanes for kLanes points (core/Lanes.hpp).
template <class T>
KOKKOS_INLINE_FUNCTION void rotateStressBySpin(T w, T stress[kStressComponents]) {
  if constexpr (std::is_same_v<T, Real>)
    if (w == 0) return;
  const T q = 1 + w * w / 4;
  const T c = (1 - w * w / 4) / q, s = w / q;
  const T xx = stress[0], yy = stress[1], zz = stress[2], xy = stress[3];
  // Q sigma Q^T with Q = [[c, s], [-s, c]]. All four components are written together (zz
  // unchanged): a caller that reads the stress back as one vector then finds it in one
  // store, not three scalar stores around an older value (a store-forwarding stall).
  const T rotated[kStressComponents] = {c * c * xx + 2 * c * s * xy + s * s * yy,
                                        s * s * xx - 2 * c * s * xy + c * c * yy, zz,
                                        c * s * (yy - xx) + (c * c - s * s) * xy};
  if constexpr (std::is_same_v<T, Real>) {
    for (int i = 0; i < kStressComponents; ++i) stress[i] = rotated[i];
  } else {
    const auto still = w == 0;
    for (int i = 0; i < kStressComponents; ++i) stress[i] = select(still, stress[i], rotated[i]);
  }
}

}  // namespace argine

#pragma once
/// @file CoulombContact.hpp
/// The formulas of a rigid frictional wall at one grid node, shared by the acceleration and
/// the velocity kernels (physics/WallContact.hpp, FrictionalContact::constrainVelocities) and
/// the tests: the one place where Coulomb's law is written.
///
/// The wall is at rest. n is the outward unit normal of the soil, pointing INTO the wall, so
/// v . n > 0 means the node moves into the wall. After Bardenhagen, Brackbill & Sulsky (2000),
/// "The material-point method for granular materials", CMAME 187, 529-541 (their contact
/// correction of the nodal velocity against the centre-of-mass velocity, which is zero for a
/// fixed rigid wall, with the friction coefficient capped at |v_t| / v_n):
///   v_n = v . n;  v_t = v - v_n n
///   v_n <= 0:            v' = v                      (free: the wall cannot pull)
///   |v_t| <= mu v_n:     v' = 0                      (stick)
///   otherwise:           v' = v_t (1 - mu v_n / |v_t|)  (slip: the normal part removed, the
///                                                     tangential one reduced by mu v_n)
/// With the impulse M v_n that stops the node's normal motion in one step, the reduction is
/// the impulse of a friction force mu N, N = M v_n / dt (Coulomb: |F_t| <= mu N).

#include "argine/core/Types.hpp"

namespace argine {

/// The velocity after contact with a rigid wall of outward unit normal `n` (into the wall)
/// and Coulomb coefficient `mu` >= 0, for a trial velocity `v` (see the file comment).
KOKKOS_INLINE_FUNCTION void coulombWallVelocity(const Real v[kDim], const Real n[kDim], Real mu,
                                                Real out[kDim]) {
  const Real vn = v[0] * n[0] + v[1] * n[1];
  if (!(vn > 0)) {  // moving away from or along the wall: no contact force
    out[0] = v[0];
    out[1] = v[1];
    return;
  }
  const Real t[kDim] = {v[0] - vn * n[0], v[1] - vn * n[1]};
  const Real vt = Kokkos::Experimental::sqrt(t[0] * t[0] + t[1] * t[1]);
  const Real slip = vt - mu * vn;  // tangential speed left after the friction impulse
  if (!(slip > 0)) {               // stick (also vt = 0: nothing to slide)
    out[0] = out[1] = 0;
    return;
  }
  const Real scale = slip / vt;
  out[0] = t[0] * scale;
  out[1] = t[1] * scale;
}

/// The coefficient that turns the solid's normal speed into the friction reduction of its
/// tangential speed when the wall stops the normal motion of `mass_solid` and
/// `mass_stopped_liquid` together (an impermeable wall, the liquid locked to the solid
/// normal to it): the friction is mu times that TOTAL normal force, f (M_S + M_L) v_n / dt,
/// and acts on the solid's momentum f M_S v_t alone (the pore liquid carries no shear), so
/// the solid sees mu (M_S + M_L) / M_S (the mass scaling f cancels). Without stopped liquid it
/// is mu. doc/theory.md Sec. 5.6 (total against effective normal force).
KOKKOS_INLINE_FUNCTION Real solidFrictionCoefficient(Real mu, Real mass_solid,
                                                     Real mass_stopped_liquid) {
  return mu * (mass_solid + mass_stopped_liquid) / mass_solid;
}

/// Sets the component of `v` along the unit normal `n` to that of `target` (the tangential
/// part of `v` is kept): the liquid's relative velocity normal to an impermeable wall is
/// zero, (v_L - v_S) . n = 0. The same on accelerations.
KOKKOS_INLINE_FUNCTION void matchNormalComponent(const Real target[kDim], const Real n[kDim],
                                                 Real v[kDim]) {
  const Real difference = (target[0] - v[0]) * n[0] + (target[1] - v[1]) * n[1];
  v[0] += difference * n[0];
  v[1] += difference * n[1];
}

}  // namespace argine

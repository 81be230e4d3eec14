#pragma once
/// @file LocalDamping.hpp
/// Local damping of the explicit nodal solves (doc/theory.md Sec. 3.5, doc/stability.md
/// "A dissipative local damping"): the one formula every equation of MomentumBalance.hpp
/// uses (liquid, mixture, mixture with the liquid moving with the solid, the locked
/// directions of constrainAccelerations and the implicit-drag liquid equation).
///
/// Per node, equation and component, with F the undamped unbalanced force, m the (scaled)
/// mass the force is divided by, v the velocity at t^k and dt the step, the equation solves
/// m a = F + D. Two forms of D (deck `Local Damping Form`):
///  - StartOfStep (Anura3D's form of the damping the thesis describes in words, Ch. 3
///    Sec. 2.2, no numbered equation):
///      D = -alpha |F| sign(v).
///    Not dissipative in the sign-alternating mode of an explicit instability: there F
///    opposes v^k at every node, D adds alpha |F|, as if m were divided by 1 + alpha.
///  - Dissipative: with the undamped end velocity v* = v + dt F/m and the step's mean
///    velocity vbar = (v + v*)/2 = v + dt F/(2m),
///      D = -sign(vbar) min(alpha |F|, m |vbar| / dt).
///    D opposes the velocity the central-difference step does work with, and never takes
///    vbar + dt D/m (= v^{k+1} - dt F/(2m)) past zero. For a linear system with lumped masses
///    stepped as argine steps it (v^{k+1} = v^k + dt a, u^{k+1} = u^k + dt v^{k+1}), the quadratic
///    invariant of the undamped scheme, H = sum_i m_i (v_i - dt F_i / (2 m_i))^2 + u^T (K - dt^2/4
///    K M^-1 K) u (u at t^k, v at t^{k+1}), falls or stays at every step: the damped step is stable
///    wherever the undamped one is. It equals the start-of-step form when sign(vbar) =
///    sign(v) and alpha |F| dt / m <= |vbar|; |v| > (1/2 + alpha) dt |F| / m suffices (a
///    node moving steadily).
///    From rest (v = 0) it damps (by at most half the step's velocity change) where the
///    start-of-step form does not.
/// Both return the damped force F + D; the caller divides by m as before, so the
/// start-of-step form gives the same bits as before the form existed.

#include "argine/core/Types.hpp"

namespace argine {

/// Deck `Local Damping Form` (per stage).
enum class LocalDampingForm {
  StartOfStep,  ///< -alpha |F| sign(v^k) (default)
  Dissipative,  ///< -sign(vbar) min(alpha |F|, m |vbar| / dt), vbar = v^k + dt F / (2m)
};

/// The start-of-step local damping force of one component: -alpha |force| sign(velocity).
KOKKOS_INLINE_FUNCTION Real localDampingForce(Real alpha, Real force, Real velocity) {
  const Real magnitude = force < 0 ? -force : force;
  return velocity > 0 ? -alpha * magnitude : (velocity < 0 ? alpha * magnitude : 0);
}

/// The damped force F + D of one component (see the file comment): `force` F undamped,
/// `velocity` v at t^k, `mass` m > 0 the mass F is divided by (scaled), `dt` >= 0 the step
/// (read by the dissipative form only; at dt = 0 it is the start-of-step form).
KOKKOS_INLINE_FUNCTION Real dampedForce(LocalDampingForm form, Real alpha, Real force,
                                        Real velocity, Real mass, Real dt) {
  if (form == LocalDampingForm::StartOfStep)
    return force + localDampingForce(alpha, force, velocity);
  const Real mean = velocity + Real(0.5) * dt * force / mass;
  const Real wanted = alpha * (force < 0 ? -force : force);
  const Real cap_times_dt = mass * (mean < 0 ? -mean : mean);  // m |vbar|
  // min(alpha |F|, m |vbar| / dt) without dividing by dt (dt -> 0: the start-of-step form)
  const Real magnitude = wanted * dt <= cap_times_dt ? wanted : cap_times_dt / dt;
  return mean > 0 ? force - magnitude : (mean < 0 ? force + magnitude : force);
}

}  // namespace argine

#pragma once
/// @file MomentumBalance.hpp
/// The nodal solves of the explicit step (thesis Sec. 3.3 steps 1-2), on the active nodes:
///   liquid  (4.36): M~_L a_L = f_L^ext - f_L^int - Q_L (v_L - v_S)
///   mixture (4.37): M_S a_S = f^ext - f^int - M_L a_L
/// with lumped masses (4.38-4.40) multiplied by the mass-scaling factor, and local damping
/// (LocalDamping.hpp): each phase's unbalanced force F gets D, component by component, v the
/// phase's nodal velocity at t^k: -alpha |F| sign(v) (Anura3D style, the default) or the
/// dissipative form (`Local Damping Form: dissipative`). Nodes without liquid mass skip the
/// liquid equation (a_L = 0). In fixed-skeleton mode a_S = 0 and only the liquid moves. With the
/// liquid pressure held, the liquid moves with the solid: one mixture equation per node.
///
/// Implicit drag (`Liquid Drag: implicit`, doc/theory.md Sec. 3.1): the drag acts on the
/// relative velocity at t^{k+1}, r + dt (a_L - a_S), r = v_L - v_S at t^k. With a_S from
/// the mixture equation, a_S = (F_m - M_L a_L) / M_S (F_m = f^ext - f^int of the mixture),
/// the liquid equation becomes one linear equation per node and direction:
///   a_L = [F_L - Q r + Q dt F_m / M_S] / [M~_L + Q dt (1 + M_L / M_S)],
/// and a_S = (F_m - M_L a_L) / M_S as before (masses times the scaling, Q not: it is
/// viscous). Without solid mass, on a fixed skeleton or in a solid-fixed direction a_S = 0
/// and a_L = (F_L - Q r) / (M~_L + Q dt). The relative velocity then decays as backward
/// Euler, r^{k+1} = r^k / (1 + dt Q (1 + M_L/M_S) / M~_L) without forces: stable for any
/// Q dt, so the drag no longer bounds the step. At Q dt -> 0 it is the explicit solve; at
/// Q dt -> infinity both phases take F_m / (M_S + M_L) (undrained).

#include "argine/core/Types.hpp"
#include "argine/physics/LocalDamping.hpp"

namespace argine {

class ActiveNodes;
class NodalConstraints;
struct GridFields;

/// Stage settings the nodal solve reads.
struct MomentumSettings {
  Real local_damping = 0;       ///< alpha in [0, 1)
  Real mass_scaling = 1;        ///< factor >= 1 on the nodal masses (inertia only)
  bool fixed_skeleton = false;  ///< hold the solid at rest (seepage only)
  /// Held liquid pressure (StageSpec::hold_liquid_pressure): the liquid moves with the solid
  /// at every node, a_L = a_S = damped (f^ext - f^int) / (M_S + M_L); no liquid equation.
  bool liquid_with_solid = false;
  /// The drag at the new velocities (StageSpec::implicit_drag; see the file comment).
  bool implicit_drag = false;
  /// The form of the local damping (LocalDamping.hpp; StageSpec::local_damping_form).
  LocalDampingForm local_damping_form = LocalDampingForm::StartOfStep;
  /// StageSpec::fixity_keeps_relative_velocity (NodalConstraints::constrainVelocities).
  bool fixity_keeps_relative_velocity = false;
};

/// Step 1: liquid accelerations a_L on the active nodes (4.36); dt (s) is the step, read
/// with the implicit drag and the dissipative damping.
void solveLiquidMomentum(const ActiveNodes& active, const MomentumSettings& settings, Real dt,
                         GridFields& grid);

/// Step 2: solid accelerations a_S on the active nodes (4.37), using a_L of step 1; dt (s)
/// read by the dissipative damping only.
void solveMixtureMomentum(const ActiveNodes& active, const MomentumSettings& settings, Real dt,
                          GridFields& grid);

/// Essential conditions on the accelerations of the constrained nodes. Where the liquid is
/// locked to the solid in direction d (impermeable), both phases share one acceleration
/// from the mixture equation alone: (M_S + M_L) a_d = f^ext_d - f^int_d (damped with the
/// solid velocity), which replaces steps 1-2 in that direction. Then solid-fixed directions
/// get a_S,d = 0 and, if also locked, a_L,d = 0; with the implicit drag a solid-fixed,
/// unlocked direction re-solves a_L,d against a_S,d = 0. In fixed-skeleton mode every
/// direction is solid-fixed.
void constrainAccelerations(const NodalConstraints& constraints, const MomentumSettings& settings,
                            Real dt, GridFields& grid);

/// With the liquid pressure held (MomentumSettings::liquid_with_solid) the liquid moves with
/// the solid: v_L,i = v_S,i at the active nodes, after the velocity conditions. The remap
/// weights the phases by their own masses, and a solid fixity zeroes v_S,d but keeps the
/// mapped v_L,d, so without it the grid's liquid velocity drifts from the solid's. FLIP
/// points never read it (they take a_L = a_S), but APIC and TPIC points take v_L from it:
/// in a held TPIC stage on the 0.0625 m experimental slope the toe's points carried a liquid
/// velocity of 1 m/s at a solid one of 1 mm/s, 9 J/m of kinetic energy that no damping
/// reaches and that kept the stage from relaxing. The boundary fluxes of a held stage, which
/// read v_L - v_S at the nodes, are zero with it, as a held p_L means.
void moveLiquidWithSolid(const ActiveNodes& active, GridFields& grid);

/// The implicit-drag liquid acceleration of one direction (see the file comment): the
/// unbalanced liquid force F_L - Q r + Q dt F_m / M_S over M~_L + Q dt (1 + M_L/M_S), each
/// mass already scaled; `coupled` false (a_S = 0) drops the M_S terms. Local damping acts
/// on that numerator with the liquid velocity, as on the explicit force, the denominator
/// the mass (dampedForce).
KOKKOS_INLINE_FUNCTION Real implicitDragLiquidAcceleration(
    Real liquid_force, Real mixture_force, Real drag, Real relative_velocity, Real liquid_velocity,
    Real dt, Real intrinsic_liquid_mass, Real liquid_mass, Real solid_mass, bool coupled,
    Real alpha, LocalDampingForm form) {
  Real numerator = liquid_force - drag * relative_velocity;
  Real denominator = intrinsic_liquid_mass + drag * dt;
  if (coupled) {
    numerator += drag * dt * mixture_force / solid_mass;
    denominator += drag * dt * liquid_mass / solid_mass;
  }
  return dampedForce(form, alpha, numerator, liquid_velocity, denominator, dt) / denominator;
}

}  // namespace argine

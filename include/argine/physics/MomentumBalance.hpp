#pragma once
/// @file MomentumBalance.hpp
/// The nodal solves of the explicit step (thesis Sec. 3.3 steps 1-2), on the active nodes:
///   liquid  (4.36): M~_L a_L = f_L^ext - f_L^int - Q_L (v_L - v_S)
///   mixture (4.37): M_S a_S = f^ext - f^int - M_L a_L
/// with lumped masses (4.38-4.40) multiplied by the mass-scaling factor, and local damping
/// (Anura3D style): each phase's unbalanced force F gets -alpha |F| sign(v), component by
/// component, v the phase's nodal velocity at t^k. Nodes without liquid mass skip the liquid
/// equation (a_L = 0). In fixed-skeleton mode a_S = 0 and only the liquid moves. With the
/// liquid pressure held, the liquid moves with the solid: one mixture equation per node.

#include "argine/core/Types.hpp"

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
};

/// The local damping force of one component: -alpha |force| sign(velocity).
KOKKOS_INLINE_FUNCTION Real localDampingForce(Real alpha, Real force, Real velocity) {
  const Real magnitude = force < 0 ? -force : force;
  return velocity > 0 ? -alpha * magnitude : (velocity < 0 ? alpha * magnitude : 0);
}

/// Step 1: liquid accelerations a_L on the active nodes (4.36).
void solveLiquidMomentum(const ActiveNodes& active, const MomentumSettings& settings,
                         GridFields& grid);

/// Step 2: solid accelerations a_S on the active nodes (4.37), using a_L of step 1.
void solveMixtureMomentum(const ActiveNodes& active, const MomentumSettings& settings,
                          GridFields& grid);

/// Essential conditions on the accelerations of the constrained nodes. Where the liquid is
/// locked to the solid in direction d (impermeable), both phases share one acceleration
/// from the mixture equation alone: (M_S + M_L) a_d = f^ext_d - f^int_d (damped with the
/// solid velocity), which replaces steps 1-2 in that direction. Then solid-fixed directions
/// get a_S,d = 0 and, if also locked, a_L,d = 0. In fixed-skeleton mode every direction is
/// solid-fixed.
void constrainAccelerations(const NodalConstraints& constraints, const MomentumSettings& settings,
                            GridFields& grid);

}  // namespace argine

#pragma once
/// @file WallContact.hpp
/// Rigid frictional walls on the accelerations of the explicit step (deck `frictional wall`,
/// doc/theory.md Sec. 5.6), after the momentum solves (4.36, 4.37) and the fixities
/// (constrainAccelerations), at the contact nodes only. Per node, with n the wall's outward
/// unit normal (into the wall):
///  1. impermeable wall, node with liquid: the two phases share one normal acceleration, the
///     momentum-weighted mean (M_S a_S + M_L a_L) . n / (M_S + M_L): the lock's reaction is
///     internal, so the mixture's normal momentum is that of the two equations (with no
///     local damping exactly the mixture equation's, as for an axis lock);
///  2. trial solid velocity v* = v_S + dt a_S; Coulomb's projection v' (CoulombContact.hpp)
///     with the coefficient the solid sees (solidFrictionCoefficient: the normal force is
///     the total one when the wall also stops the liquid); a_S = (v' - v_S) / dt; whether
///     v' = 0 (stick, held corner) goes to FrictionalContact::atRest() for the velocity form;
///  3. solid-fixed components: a_S,d = 0 (the fixity wins);
///  4. the liquid: no relative acceleration normal to an impermeable wall; axis locks of
///     impermeable conditions at the node (wallLiquidComponents).
/// Running it again on its own result changes nothing (v* . n <= 0 then), so the solver
/// re-applies it after the hydraulic corrections. In fixed-skeleton mode only step 4 runs;
/// with the liquid pressure held the liquid takes the solid's acceleration.

#include "argine/core/Types.hpp"

namespace argine {

class FrictionalContact;
struct GridFields;
struct MomentumSettings;

/// Applies the walls of `contact` to the nodal accelerations of `grid` for a step `dt` (> 0).
void constrainWallContactAccelerations(const FrictionalContact& contact,
                                       const MomentumSettings& settings, Real dt, GridFields& grid);

}  // namespace argine

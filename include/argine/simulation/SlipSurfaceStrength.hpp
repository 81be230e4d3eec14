#pragma once
/// @file SlipSurfaceStrength.hpp
/// The shear strength a limit-equilibrium analysis (P13) takes on a slip surface through a
/// material at liquid pressure p_L and saturation S_L, with the gas at zero pressure, so the
/// matric suction is s = max(-p_L, 0) (Pa). The suction's share is returned as an apparent
/// cohesion (BaseStrength::suction_strength), the pore pressure itself enters the methods as
/// max(p_L, 0):
///   solid model: c = c(s), phi = phi(s) of the material (Eqs. 4.23-4.26; c', phi' for plain
///                Mohr-Coulomb) and chi s tan(phi) with Bishop's chi = S_L (Eq. 4.5): the
///                strength the MPM's own effective stress gives;
///   vanapalli:   c', phi' and s Theta tan(phi'), Theta = (S_L - S_min) / (S_max - S_min)
///                (Vanapalli et al. 1996, thesis Eq. 5.1);
///   fredlund:    c', phi' and s tan(phi_b) (Fredlund et al. 1978, thesis Eq. 5.2);
///   none:        c', phi' (suction ignored, the conventional conservative choice).
/// A linear-elastic material has no strength limit: it gets a cohesion of kElasticCohesion,
/// so a slip surface through it is never critical.

#include "argine/input/Deck.hpp"
#include "argine/slopestability/SlopeSection.hpp"

namespace argine {

/// Cohesion (Pa) standing for "does not yield" (linear-elastic materials).
inline constexpr Real kElasticCohesion = 1e12;

/// The strength of `material` at p_L, S_L under `mode` (see the file comment); phi_b (rad) is
/// used by the fredlund form only.
BaseStrength slipSurfaceStrength(const MaterialSpec& material, SuctionStrength mode, Real phi_b,
                                 Real liquid_pressure, Real saturation);

}  // namespace argine

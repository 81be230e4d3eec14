#pragma once
/// @file Spencer.hpp
/// Spencer's method (Spencer 1967; as set out in Duncan & Wright 2005, Sec. 7.4, and
/// Fredlund & Krahn 1977): force and moment equilibrium of the whole mass with the interslice
/// forces of all slices at one inclination theta, for any slice table (circle or polyline).
///
/// Per slice (mass sliding towards -x, alpha the base inclination, l = b / cos(alpha)), the
/// net interslice force Q along (cos theta, sin theta) follows from the equilibrium normal
/// and parallel to the base with the Mohr-Coulomb strength mobilised by F:
///   Q = [W sin(alpha) - (c l + (W cos(alpha) - u l) tan(phi')) / F] / m,
///   m = cos(alpha - theta) (1 + tan(alpha - theta) tan(phi') / F),
/// c = c' + suction_strength, u = max(u, 0). The mass is in equilibrium when
///   force:  sum Q = 0,
///   moment: sum Q [(x - x0) sin(theta) - (y - y0) cos(theta)] = 0,
/// Q acting at the base midpoint (x, y) (its line of action through the point where W, N and
/// S of the slice meet; Spencer 1967). The moment is taken about a fixed point (x0, y0): the
/// circle's centre when the caller gives it, otherwise the default point of
/// spencerMomentPoint. Where sum Q = 0 the moment does not depend on (x0, y0), so the
/// converged (F, theta) does not either (tested).
///
/// Solution: for a given theta, F_f(theta) solves the force equation and F_m(theta) the
/// moment equation, each by bracketing on F > F_0(theta) (all m > 0) and the Illinois
/// variant of regula falsi; then theta solves F_m(theta) = F_f(theta), bracketed by stepping
/// out from theta = 0 (the F_m / F_f intersection of Spencer 1967, Fig. 4). At theta = 0
/// F_f is Janbu's simplified method (uncorrected) and, about the centre of a circle, F_m is
/// Bishop's simplified method (both tested).

#include <vector>

#include "argine/core/Types.hpp"
#include "argine/slopestability/Bishop.hpp"
#include "argine/slopestability/Slice.hpp"

namespace argine {

/// Settings of the Spencer solution.
struct SpencerOptions {
  Real tolerance = 1e-10;  ///< on F and theta (relative to F; rad)
  int max_iterations = 200;
  /// Smallest admissible m = cos(alpha - theta)(1 + tan(alpha - theta) tan(phi') / F) at the
  /// solution: the m_alpha guard of Bishop's method (Whitman & Bailey 1967) with alpha - theta
  /// in place of alpha.
  Real min_m_alpha = 0.2;
  Real max_theta = 1.4;  ///< search theta in [-max_theta, max_theta] (rad)
  /// The moment point (m): used when use_moment_point, else spencerMomentPoint(slices).
  bool use_moment_point = false;
  Real moment_x = 0, moment_y = 0;
};

/// Spencer's F with the interslice inclination.
struct SpencerFactor {
  FactorOfSafety factor;  ///< value, admissible, converged, iterations (outer), min m, driving
  Real theta = 0;         ///< interslice force inclination (rad) in the section's frame
  Real moment_x = 0, moment_y = 0;  ///< the moment point used (m)
  Real min_effective_normal = 0;    ///< smallest N' = N - u l (N per m); < 0: tension
};

/// The default moment point: midway between the outer slice edges, above the highest ground
/// point of the mass by half the mass's width. Any fixed point gives the same converged F.
void spencerMomentPoint(const std::vector<Slice>& slices, Real& x0, Real& y0);

/// F that satisfies force equilibrium at inclination theta (sum Q = 0); at theta = 0 Janbu's
/// simplified F (uncorrected).
FactorOfSafety spencerForceFactor(const std::vector<Slice>& slices, Real theta);

/// Janbu's simplified method (Janbu 1954/1973; force equilibrium, interslice shear neglected),
/// uncorrected (no f_0): spencerForceFactor at theta = 0, i.e.
///   F = sum[(c b + (W - u b) tan phi') / (cos(alpha) m_alpha)] / sum[W tan(alpha)].
/// For non-circular cross-checks; known to be low against rigorous methods (Duncan & Wright
/// 2005, Sec. 6.7).
FactorOfSafety janbuSimplified(const std::vector<Slice>& slices);

/// F that satisfies moment equilibrium about (x0, y0) at inclination theta.
FactorOfSafety spencerMomentFactor(const std::vector<Slice>& slices, Real theta, Real x0, Real y0,
                                   const std::vector<HorizontalForce>& end_forces = {});

/// Spencer's factor of safety (see the file comment).
/// `end_forces`: horizontal forces on the ends of the mass (SlipMass::end_forces, water
/// standing against them), each on the slice at its abscissa.
SpencerFactor spencer(const std::vector<Slice>& slices, const SpencerOptions& options = {},
                      const std::vector<HorizontalForce>& end_forces = {});

}  // namespace argine

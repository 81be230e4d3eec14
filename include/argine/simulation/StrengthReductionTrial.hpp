#pragma once
/// @file StrengthReductionTrial.hpp
/// The displacement criterion of a strength-reduction trial (P13 item 3): does the mobilised
/// mass accelerate? The MOBILISED MASS is the points whose displacement over the trial is at
/// least half the largest (the body that slides, not the elastic settlement around it); its
/// mean displacement rate over the trial's third quarter is compared with that over its last
/// quarter. The first half is left out: cutting the strength releases the stress above the
/// reduced surface at once, and the burst of motion that follows says nothing about whether
/// the mass can stand. Under local damping a mass on which the reduced strength cannot
/// balance gravity keeps an unbalanced force and moves faster in the last quarter; a mass
/// that finds equilibrium slows down. A mean displacement below a minimum (creep of a mass at
/// rest) never counts as failure, nor does a trial that came to rest (the caller's test).
///
/// CONTINUING displacement: the mobilised mass still moves at least that minimum over the
/// last quarter. Under local damping a mass that cannot stand slides at a terminal rate that
/// grows with F rather than faster and faster (the dry slope on 0.25 m with psi = phi': at rest
/// with a few um/s at F = 1.08, a steady 1.4 mm/s at 1.10; verification/strength_reduction), so
/// "accelerating" is not monotonic in F there, while "still moving" is.

#include <vector>

#include "argine/core/Types.hpp"

namespace argine {

struct DisplacementTrend {
  int mobilised_points = 0;
  Real largest = 0;           ///< largest displacement over the trial (m)
  Real mean = 0;              ///< mean displacement of the mobilised mass over the trial (m)
  Real earlier_rate = 0;      ///< its mean displacement rate over [t_a, t_b] (m/s)
  Real later_rate = 0;        ///< over [t_b, t_c] (m/s)
  bool accelerating = false;  ///< later_rate > earlier_rate and mean >= minimum_displacement
  bool continuing = false;    ///< later_rate (t_c - t_b) >= minimum_displacement
};

/// `start`, `a`, `b`, `c`: the points' displacement vectors (x, y per point, the same points
/// in the same order) at the trial's start and at the times t_a < t_b < t_c from it (s); the
/// mobilised mass is taken from start -> c. Throws std::invalid_argument for arrays of
/// different sizes or times out of order.
DisplacementTrend displacementTrend(const std::vector<Real>& start, const std::vector<Real>& a,
                                    const std::vector<Real>& b, const std::vector<Real>& c,
                                    Real t_a, Real t_b, Real t_c, Real minimum_displacement);

}  // namespace argine

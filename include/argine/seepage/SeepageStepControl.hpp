#pragma once
/// @file SeepageStepControl.hpp
/// The adaptive step of the implicit seepage path: the next step from what the last accepted
/// one did. Until P10 the step grew only after 4 or fewer Picard iterations, which the
/// default tolerances rarely allow (about 5 per step), so it stayed at `Initial Step`
/// whatever `Maximum Step` said. Now it grows whenever the accuracy allows, and iterations
/// only hold it back when they are many:
///  - time error: backward Euler's local error in p_L is about (dt^2 / 2) |d2p/dt2|; with
///    d2p/dt2 estimated from the change of the nodal rate dp/dt between the last two steps,
///      e = dt^2 / (dt + dt_prev) max_i |dp_i / dt - dp_prev_i / dt_prev|   (Pa),
///    the factor is 0.9 sqrt(`Step Error` / e) (first order: e ~ dt^2);
///  - saturation change: `Maximum Saturation Change` / max |dS_L| (as before);
///  - iterations: 10 or more shrink the step to 0.6 of it, half of `Picard Iterations` or
///    more keep it from growing;
/// the smallest factor, clamped to [0.3, 2], and the step to [`Minimum Step`, `Maximum Step`].

#include <vector>

#include "argine/core/Types.hpp"

namespace argine {

struct ImplicitSeepageSpec;

/// Backward Euler's local time error estimate e (Pa) of a step of length dt with nodal
/// increments `increment` after a step of length dt_prev with increments `previous` (same
/// nodes): dt^2 / (dt + dt_prev) max_i |increment_i / dt - previous_i / dt_prev|.
Real seepageTimeError(Real dt, const std::vector<Real>& increment, Real dt_prev,
                      const std::vector<Real>& previous);

/// What the last accepted step did.
struct SeepageStepOutcome {
  Real dt = 0;                     ///< its length (s)
  int iterations = 0;              ///< Picard (or Newton) iterations
  Real max_saturation_change = 0;  ///< largest |dS_L| of a point
  Real time_error = -1;            ///< seepageTimeError; < 0: no estimate (no previous step)
};

/// The next step (s) after `outcome` (see the file comment).
Real nextSeepageStep(const SeepageStepOutcome& outcome, const ImplicitSeepageSpec& settings);

}  // namespace argine

/// @file SeepageStepControl.cpp
/// The implicit seepage path's adaptive step (SeepageStepControl.hpp).
#include "argine/seepage/SeepageStepControl.hpp"

#include <algorithm>
#include <cmath>

#include "argine/input/Deck.hpp"

namespace argine {

Real seepageTimeError(Real dt, const std::vector<Real>& increment, Real dt_prev,
                      const std::vector<Real>& previous) {
  Real largest = 0;
  for (std::size_t i = 0; i < increment.size() && i < previous.size(); ++i)
    largest = std::max(largest, std::fabs(increment[i] / dt - previous[i] / dt_prev));
  return dt * dt / (dt + dt_prev) * largest;
}

Real nextSeepageStep(const SeepageStepOutcome& outcome, const ImplicitSeepageSpec& settings) {
  Real factor = 2;
  if (outcome.time_error > 0)
    factor = std::min(factor, 0.9 * std::sqrt(settings.step_error / outcome.time_error));
  if (outcome.max_saturation_change > 0)
    factor = std::min(factor, settings.max_saturation_change / outcome.max_saturation_change);
  if (outcome.iterations >= 10)
    factor = std::min<Real>(factor, 0.6);
  else if (2 * outcome.iterations >= settings.max_picard_iterations)
    factor = std::min<Real>(factor, 1);
  factor = std::clamp<Real>(factor, 0.3, 2.0);
  return std::clamp(outcome.dt * factor, settings.min_step, settings.max_step);
}

}  // namespace argine

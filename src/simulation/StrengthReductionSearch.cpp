#include "argine/simulation/StrengthReductionSearch.hpp"

#include <algorithm>

namespace argine {

StrengthReductionSearch::StrengthReductionSearch(const StrengthReductionSpec& spec)
    : spec_(spec), next_(spec.initial_factor), step_(spec.factor_step) {}

StrengthReductionBracket StrengthReductionSearch::bracket(
    StrengthReductionCriterion criterion) const {
  StrengthReductionBracket b;
  for (const StrengthReductionTrial& t : trials_) {
    if (t.failed(criterion))
      b.failing = std::min(b.failing, t.factor);
    else
      b.holding = std::max(b.holding, t.factor);
  }
  b.ordered = !(b.holding > b.failing);
  return b;
}

void StrengthReductionSearch::record(const StrengthReductionTrial& trial) {
  trials_.push_back(trial);
  const StrengthReductionBracket b = result();
  if (b.closed()) {  // bisection (on an unordered bracket: between the last two found)
    if (!b.ordered || b.halfWidth() <= spec_.tolerance * (1 + 1e-12)) {
      done_ = true;
      return;
    }
    next_ = b.factor();
    return;
  }
  if (b.failing == std::numeric_limits<Real>::infinity()) {  // all held: up
    if (trial.factor >= spec_.maximum_factor) {
      done_ = true;
      return;
    }
    next_ = std::min(spec_.maximum_factor, trial.factor + step_);
  } else {  // all failed: down
    if (trial.factor <= spec_.minimum_factor) {
      done_ = true;
      return;
    }
    next_ = std::max(spec_.minimum_factor, trial.factor - step_);
  }
  step_ *= 2;
}

}  // namespace argine

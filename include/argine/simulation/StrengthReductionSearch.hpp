#pragma once
/// @file StrengthReductionSearch.hpp
/// The factors a strength-reduction stage tries (P13 item 3; Dawson, Roth and Drescher 1999
/// bracket the factor of safety in the same way): F of the first trial given; while every
/// trial has held, F grows by a step that doubles after each trial (while every trial has
/// failed, it falls the same way); once one holds and one fails, bisection between the
/// highest holding and the lowest failing F until they are at most 2 x tolerance apart.
/// FS_SRM is their mean, +- tolerance. The search also ends at the maximum factor (the
/// slope holds there: FS_SRM > maximum) and at the minimum one (it fails there).
///
/// Each trial is judged by three criteria (StrengthReductionTrial.hpp); the search follows the
/// deck's Failure Criterion, and bracket() gives each criterion's own bracket from the same
/// trials, so all are reported.

#include <limits>
#include <vector>

#include "argine/input/Deck.hpp"

namespace argine {

/// What one trial found.
struct StrengthReductionTrial {
  Real factor = 1;            ///< F (-)
  bool converged = false;     ///< relaxed within the trial (not failed by non-convergence)
  bool accelerating = false;  ///< failed by accelerating displacement
  bool continuing = false;    ///< failed by continuing displacement
  bool failed(StrengthReductionCriterion criterion) const {
    switch (criterion) {
      case StrengthReductionCriterion::NonConvergence:
        return !converged;
      case StrengthReductionCriterion::AcceleratingDisplacement:
        return accelerating;
      case StrengthReductionCriterion::ContinuingDisplacement:
        return continuing;
      case StrengthReductionCriterion::Either:
        break;
    }
    return !converged || accelerating;
  }
};

/// The highest F that held and the lowest that failed, by one criterion. `holding` is 0 when
/// none held, `failing` infinity when none failed. `ordered` is false when some trial held
/// above one that failed (the criterion is not monotonic in F on these trials).
struct StrengthReductionBracket {
  Real holding = 0;
  Real failing = std::numeric_limits<Real>::infinity();
  bool ordered = true;
  bool closed() const { return holding > 0 && failing < std::numeric_limits<Real>::infinity(); }
  Real factor() const { return 0.5 * (holding + failing); }  ///< FS_SRM (closed brackets)
  Real halfWidth() const { return 0.5 * (failing - holding); }
};

class StrengthReductionSearch {
 public:
  explicit StrengthReductionSearch(const StrengthReductionSpec& spec);

  bool done() const { return done_; }
  /// F of the next trial (valid while !done()).
  Real next() const { return next_; }
  /// Records the trial at next() and chooses the next F (or ends the search).
  void record(const StrengthReductionTrial& trial);

  const std::vector<StrengthReductionTrial>& trials() const { return trials_; }
  /// The bracket by `criterion` over all trials so far.
  StrengthReductionBracket bracket(StrengthReductionCriterion criterion) const;
  /// The bracket of the criterion the search follows.
  StrengthReductionBracket result() const { return bracket(spec_.criterion); }

 private:
  StrengthReductionSpec spec_;
  std::vector<StrengthReductionTrial> trials_;
  Real next_ = 1;
  Real step_ = 0;
  bool done_ = false;
};

}  // namespace argine

#pragma once
/// @file StepFallReport.hpp
/// Says when a stage's critical time step falls: each time it drops below half of the lowest
/// the stage has reported (its first step's, then each report's), one log line with the
/// criterion, the point and where it is. A step that falls inside a stage means the run costs
/// more than its start promised, and the point that governs it is usually the one to look at
/// (a loosened or stray point: the 0.0625 m experimental slope's drained stage fell from
/// 6.8e-5 to 2.1e-5 s at a toe point whose porosity had ratcheted to 0.988). New lows only, by
/// halves: a step that flickers logs nothing, one that falls a thousandfold logs ten lines.

#include <string>

#include "argine/core/Types.hpp"
#include "argine/physics/TimeStepControl.hpp"

namespace argine {

/// "governed by '<criterion>' at point <id> (x, y) m": the text of an automatic choice's
/// governing criterion and point, for the stage's first-step line and the fall lines alike.
std::string governingText(const TimeStepChoice& choice);

class StepFallReport {
 public:
  /// A stage starts (or continues from a checkpoint) with this step choice: the reference.
  void begin(const TimeStepChoice& first) {
    lowest_ = first.automatic ? first.critical_step : Real(0);
  }

  /// The line to log when `choice` is below half of the lowest so far (it becomes the new
  /// lowest), else "". Fixed steps never fall. `time` (s) and `step` (count since the run
  /// started) say when.
  std::string note(const std::string& stage, Real time, long long step,
                   const TimeStepChoice& choice);

 private:
  Real lowest_ = 0;  ///< the lowest critical step reported in the stage (s); 0: none
};

}  // namespace argine

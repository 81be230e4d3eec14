#include "argine/simulation/StepFallReport.hpp"

#include <cstdio>

#include "argine/timestep/Criteria.hpp"

namespace argine {

std::string StepFallReport::note(const std::string& stage, Real time, long long step,
                                 const TimeStepChoice& choice) {
  if (!choice.automatic || !(lowest_ > 0) || !(choice.critical_step < lowest_ / 2)) return "";
  char line[384];
  std::snprintf(line, sizeof line,
                "stage '%s': the critical time step fell to %.4g s (%.3g x %.4g s) at t = %.6g s, "
                "step %lld, governed by '%s' at point %d (%.4g, %.4g) m",
                stage.c_str(), choice.critical_step, choice.critical_step / lowest_, lowest_, time,
                step, criterionName(choice.governing), choice.point_id, choice.position[0],
                choice.position[1]);
  lowest_ = choice.critical_step;
  return line;
}

}  // namespace argine

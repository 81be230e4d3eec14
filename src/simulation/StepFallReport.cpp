#include "argine/simulation/StepFallReport.hpp"

#include <cstdio>

#include "argine/timestep/Criteria.hpp"

namespace argine {

std::string governingText(const TimeStepChoice& choice) {
  char text[160];
  std::snprintf(text, sizeof text, "governed by '%s' at point %d (%.4g, %.4g) m",
                criterionName(choice.governing), choice.point_id, choice.position[0],
                choice.position[1]);
  return text;
}

std::string StepFallReport::note(const std::string& stage, Real time, long long step,
                                 const TimeStepChoice& choice) {
  if (!choice.automatic || !(lowest_ > 0) || !(choice.critical_step < lowest_ / 2)) return "";
  char line[256];
  std::snprintf(line, sizeof line,
                "stage '%s': the critical time step fell to %.4g s (%.3g x %.4g s) at t = %.6g s, "
                "step %lld, ",
                stage.c_str(), choice.critical_step, choice.critical_step / lowest_, lowest_, time,
                step);
  lowest_ = choice.critical_step;
  return line + governingText(choice);
}

}  // namespace argine

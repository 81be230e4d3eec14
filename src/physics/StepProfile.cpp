#include "argine/physics/StepProfile.hpp"

#include <cstdio>

namespace argine {

const char* StepProfile::name(StepPhase phase) {
  switch (phase) {
    case StepPhase::TimeStep:
      return "time-step criteria";
    case StepPhase::P2G:
      return "P2G";
    case StepPhase::NodalSolve:
      return "nodal solve";
    case StepPhase::G2PVelocity:
      return "G2P velocities + momentum remap";
    case StepPhase::G2PStrain:
      return "G2P strain increments";
    case StepPhase::Constitutive:
      return "constitutive (point states)";
    case StepPhase::Relocation:
      return "relocation + shape functions";
    case StepPhase::Sort:
      return "sort by element";
    case StepPhase::Stability:
      return "stability check";
  }
  return "?";
}

double StepProfile::total() const {
  double sum = 0;
  for (const double s : seconds) sum += s;
  return sum;
}

double StepProfile::share(StepPhase phase) const {
  const double all = total();
  return all > 0 ? of(phase) / all : 0;
}

double StepProfile::pointUpdatesPerSecond() const {
  const double all = total();
  return all > 0 ? static_cast<double>(point_updates) / all : 0;
}

std::string StepProfile::describe(const std::string& indent) const {
  std::string text;
  char line[160];
  for (int k = 0; k < kStepPhases; ++k) {
    const auto phase = static_cast<StepPhase>(k);
    if (!(of(phase) > 0)) continue;
    std::snprintf(line, sizeof(line), "%s%-32s %5.1f %%  %9.4f s\n", indent.c_str(), name(phase),
                  100 * share(phase), of(phase));
    text += line;
  }
  std::snprintf(line, sizeof(line),
                "%s%ld steps, %ld point updates, %ld sorts: %.3g point updates/s in %.4f s\n",
                indent.c_str(), steps, point_updates, sorts, pointUpdatesPerSecond(), total());
  text += line;
  return text;
}

}  // namespace argine

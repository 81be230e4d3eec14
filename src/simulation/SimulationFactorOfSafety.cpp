// The factor of safety at every output and the hand-over it may trigger (P13 item 4).
#include <cmath>
#include <cstdio>

#include <mpi.h>

#include "argine/simulation/Checkpoint.hpp"
#include "argine/simulation/Simulation.hpp"

namespace argine {

void Simulation::openFactorOfSafetyLog() {
  if (!deck_.factor_of_safety.enabled || !writes()) return;
  const std::vector<std::uint64_t> resume =
      resume_ ? resume_->factor_of_safety_bytes : std::vector<std::uint64_t>{};
  factor_of_safety_ = std::make_unique<FactorOfSafetyMonitor>(
      deck_.factor_of_safety, options_.output_directory, deck_.output.name, resume);
}

void Simulation::evaluateFactorOfSafety(const MaterialPoints& points) {
  if (!deck_.factor_of_safety.enabled) return;
  const StageSpec& stage = deck_.stages.at(std::min(stage_index_, deck_.stages.size() - 1));
  Real factor = 0;
  if (factor_of_safety_)
    factor = factor_of_safety_->evaluate(solver_->time(), points, deck_.materials, stage.gravity);
  if (distributed()) MPI_Bcast(&factor, 1, MPI_DOUBLE, 0, MPI_COMM_WORLD);
  last_factor_of_safety_ = factor;
  if (std::isfinite(factor) && (stage_lowest_factor_ <= 0 || factor < stage_lowest_factor_)) {
    stage_lowest_factor_ = factor;
    stage_lowest_factor_time_ = solver_->time();
  }
}

bool Simulation::handsOverOnFactorOfSafety(const StageSpec& stage) {
  const Real threshold = stage.hand_over_below_factor_of_safety;
  if (!(threshold > 0) || !std::isfinite(last_factor_of_safety_) ||
      !(last_factor_of_safety_ < threshold))
    return false;
  char line[320];
  std::snprintf(line, sizeof line,
                "stage '%s': factor of safety %.4g < %.4g at t = %.6g s: the stage ends and the "
                "next one starts from this state",
                stage.name.c_str(), last_factor_of_safety_, threshold, solver_->time());
  log(line);
  return true;
}

void Simulation::logLowestFactorOfSafety(const StageSpec& stage) {
  if (!deck_.factor_of_safety.enabled) return;
  if (stage_lowest_factor_ > 0) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "stage '%s': lowest factor of safety %.4g at t = %.6g s (Bishop, critical "
                  "circle; %s_factor_of_safety.csv)",
                  stage.name.c_str(), stage_lowest_factor_, stage_lowest_factor_time_,
                  deck_.output.name.c_str());
    log(line);
  }
  stage_lowest_factor_ = 0;
}

}  // namespace argine

// Simulation's part of the physical guards (issue P8; the guards themselves are in
// RunGuards.cpp): what the run knows after each explicit step, handed to RunGuards; warnings
// go to stderr (also with --quiet; on several ranks from rank 0 only, the diagnostics being
// the same on every rank) and to the stage log.
#include <cstdio>

#include "argine/boundary/HydraulicConditions.hpp"
#include "argine/physics/ExplicitTwoPhaseSolver.hpp"
#include "argine/simulation/RunGuards.hpp"
#include "argine/simulation/Simulation.hpp"

namespace argine {

void Simulation::beginStageGuards(const StageSpec& stage) {
  (void)stage;
  if (!guards_) guards_ = std::make_unique<RunGuards>(deck_.guards);
  const Real density = solver_->referenceLiquidDensity();
  const Real mass = liquidMassNow();
  guards_->beginStage(mass / density, flux_all_nodes_cumulative_, initial_liquid_mass_ / density);
}

void Simulation::checkGuards(const StageSpec& stage) {
  const StepDiagnostics& d = solver_->diagnostics();
  const GuardPlace place{solver_->time(), d.step, stage.name};
  auto warn = [&](const std::string& line) {
    if (line.empty()) return;
    if (writes()) std::fprintf(stderr, "argine: warning: %s\n", line.c_str());
    stage_log_.push_back("warning: " + line);
  };
  if (d.lost_points > guards_->removedPoints()) {
    const std::string line = guards_->handleLeavingPoints(points_, place);  // RunError if stop
    if (!line.empty()) log(line);
  }
  // The net inflow through the nodes is known where the stage has hydraulic conditions. A
  // stage with the liquid pressure held exchanges liquid with the pore volume by design.
  if (boundary_flux_ && !solver_->hydraulicConditions().conditions().empty() &&
      !stage.hold_liquid_pressure)
    warn(guards_->checkMassBalance(d.liquid_mass / solver_->referenceLiquidDensity(),
                                   flux_all_nodes_cumulative_, place));
  warn(guards_->checkKineticEnergy(d.kinetic_energy_solid + d.kinetic_energy_liquid,
                                   solver_->stageEnergyScale(), place));
}

}  // namespace argine

// Checkpoint/restart of the explicit solver (simulation/Checkpoint.hpp): what it carries
// from step to step, and how it continues from a checkpoint bit for bit.
#include <stdexcept>

#include "argine/physics/ExplicitTwoPhaseSolver.hpp"
#include "argine/points/MaterialPoints.hpp"

namespace argine {

ExplicitTwoPhaseSolver::ResumeState ExplicitTwoPhaseSolver::resumeState() const {
  ResumeState state;
  state.time = time_;
  state.diagnostics = diagnostics_;
  state.stage_energies = stage_energies_;
  state.load_bound = load_bound_;
  state.inflow_energy = inflow_energy_;
  state.stage_started = stage_started_;
  // A step prepared at the end of the last one (several ranks) is not taken yet: the state
  // before it, which a resumed run prepares again.
  state.time_step = prepared_time_step_ ? state_before_candidate_ : time_step_.state();
  return state;
}

void ExplicitTwoPhaseSolver::resume(const ResumeState& state) {
  if (state.stage_started && !stage_started_)
    throw std::logic_error("ExplicitTwoPhaseSolver::resume of a stage before beginStage");
  time_ = state.time;
  diagnostics_ = state.diagnostics;
  prepared_time_step_ = false;  // chosen again by the next chooseTimeStep()
  if (state.stage_started) {
    stage_energies_ = state.stage_energies;
    load_bound_ = state.load_bound;
    inflow_energy_ = state.inflow_energy;
    time_step_.restore(state.time_step);
  }
  // The uninterrupted run relocated the points from these positions at the end of the last
  // step (or re-relocated them after sorting): doing it again gives the same elements, local
  // coordinates and shape functions bit for bit. Before its first step (e.g. after implicit
  // stages, which do not move the points) it holds the shapes the constructor evaluated from
  // the seeded elements and local coordinates, which relocation would reproduce only to
  // round-off: evaluate those again.
  if (state.diagnostics.step == 0)
    evaluatePointShapes(mesh_, points_, shapes_);
  else
    relocateAndEvaluateShapes(mesh_, locator_, element_maps_, points_, shapes_);
  nodes_next_.rebuild(mesh_, points_, &shapes_, alwaysActiveNodes());  // several ranks: + shared
  nodes_next_changed_ = true;
  free_boundary_stale_ = true;  // detected again from the points' elements
}

}  // namespace argine

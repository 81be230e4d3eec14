// Checkpoints and restart of a run (issue P8, doc/checkpoints.md): what the Simulation
// writes, and how `argine run DECK --restart FILE` picks the run up so that it continues bit
// for bit and its files end up as those of an uninterrupted run, on one MPI rank or on as
// many as the checkpointed run had (each rank gets back its own points in their order).
#include <mpi.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <type_traits>
#include <vector>

#include "argine/checkpoint/CheckpointFile.hpp"
#include "argine/core/Error.hpp"
#include "argine/input/DeckWords.hpp"
#include "argine/output/CsvWriter.hpp"
#include "argine/output/ResultsWriter.hpp"
#include "argine/parallel/PointMigration.hpp"
#include "argine/parallel/RankDecomposition.hpp"
#include "argine/physics/ExplicitTwoPhaseSolver.hpp"
#include "argine/probes/ProbeWriter.hpp"
#include "argine/simulation/Checkpoint.hpp"
#include "argine/simulation/MaterialChanges.hpp"
#include "argine/simulation/RelaxationMonitor.hpp"
#include "argine/simulation/RestMonitor.hpp"
#include "argine/simulation/Simulation.hpp"

namespace argine {

namespace {
long long faultStopStep();
double steadySeconds() {
  using Clock = std::chrono::steady_clock;
  return std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
}
}  // namespace

void Simulation::readRestartCheckpoint() {
  const bool restart = !options_.restart.empty();
  if (!restart && !deck_.output.checkpoint.enabled()) return;
  deck_hash_ = deck_.path.empty() ? 0 : fileHash(deck_.path);
  if (!restart) return;
  const std::string& path = options_.restart;
  auto state = std::make_unique<CheckpointState>();
  // Every rank reads the whole file: the points of all ranks (as many as the deck seeds).
  state->points.allocate(static_cast<int>(totalPoints()));
  readCheckpoint(path, deck_hash_, *state);
  if (state->mesh_nodes != mesh_.numNodes() || state->mesh_elements != mesh_.numElements())
    throw InputError(
        path, "checkpoint of a mesh of " + std::to_string(state->mesh_nodes) + " nodes and " +
                  std::to_string(state->mesh_elements) + " elements; the deck's mesh has " +
                  std::to_string(mesh_.numNodes()) + " and " + std::to_string(mesh_.numElements()));
  const auto stages = static_cast<std::int64_t>(deck_.stages.size());
  if (state->stage_index < 0 || state->stage_index >= stages)
    throw InputError(path, "corrupt checkpoint: stage index " + std::to_string(state->stage_index) +
                               " of " + std::to_string(stages) + " stages");
  if (state->mid_stage && deck_.stages[state->stage_index].solver == SolverKind::ImplicitSeepage)
    throw InputError(path, "corrupt checkpoint: inside an implicit seepage stage");
  resume_ = std::move(state);
}

void Simulation::restoreFromCheckpoint() {
  if (!resume_) return;
  CheckpointState& s = *resume_;
  const std::string& path = options_.restart;
  if (s.flux_last_step.size() != flux_names_.size() ||
      s.flux_cumulative.size() != flux_names_.size())
    throw InputError(path, "checkpoint of " + std::to_string(s.flux_cumulative.size()) +
                               " hydraulic conditions; the deck has " +
                               std::to_string(flux_names_.size()));
  // The materials as the checkpointed run had them: the changes of every stage begun.
  const std::size_t begun = static_cast<std::size_t>(s.stage_index) + (s.mid_stage ? 1 : 0);
  bool changed = false;
  for (std::size_t k = 0; k < begun; ++k) {
    const StageSpec& stage = deck_.stages[k];
    if (stage.material_changes.empty()) continue;
    applyMaterialChanges(stage.name, stage.material_changes, deck_.materials);
    changed = true;
  }
  if (changed) solver_->setMaterials(deck_.materials);
  // Inside a stage: its settings, boundary conditions and time-step control from the deck;
  // what beginStage does to the points is overwritten by the checkpoint's points next.
  // The stage's time tables count from its start: begin it at that time, as the run did.
  if (s.mid_stage) {
    solver_->setTime(s.stage_start);
    solver_->beginStage(deck_.stages[s.stage_index]);
  }
  // This rank's points; the solver refers to points_, so it sees them.
  const int rank = distributed() ? ranks_->rank() : 0;
  const int ranks = distributed() ? ranks_->size() : 1;
  const bool same_ranks = s.rank_point_counts.size() == static_cast<std::size_t>(ranks);
  ExplicitTwoPhaseSolver::ResumeState solver_state = s.solver;
  if (same_ranks) {  // each rank its own points in the order it held them (of its sums)
    std::int64_t first = 0;
    for (int r = 0; r < rank; ++r) first += s.rank_point_counts[r];
    points_ = distributed() ? pointRange(s.points, static_cast<int>(first),
                                         static_cast<int>(s.rank_point_counts[rank]))
                            : s.points;
    if (rank > 0) solver_state = s.other_rank_solvers[rank - 1];
  } else {
    // Another number of ranks: each keeps the points of its elements (the deck's partition
    // for this many ranks). The run goes on, but not bit for bit: the shared nodes' partial
    // sums are added in another order. The step controller's cached choice names a point
    // of another rank's numbering: it is evaluated again.
    points_ = s.points;
    if (distributed()) keepOwnedPoints(*ranks_, points_);
    solver_state.time_step.stale = true;
  }
  solver_state.stage_started = s.mid_stage;
  solver_->resume(solver_state);

  summary_.steps = s.steps;
  summary_.point_updates = s.point_updates;
  next_probe_time_ = s.next_probe_time;
  initial_output_written_ = s.initial_output_written;
  initial_time_step_ = s.initial_time_step;
  initial_liquid_mass_ = s.initial_liquid_mass;
  flux_last_step_ = s.flux_last_step;
  flux_cumulative_ = s.flux_cumulative;
  flux_all_nodes_cumulative_ = s.flux_all_nodes_cumulative;
  flux_interior_nodes_cumulative_ = s.flux_interior_nodes_cumulative;
  stage_log_ = s.stage_log;
  stage_start_ = s.stage_start;
  next_output_ = s.next_output;
  resume_pending_ = s.mid_stage;
  const long long every = deck_.output.checkpoint.every_steps;
  checkpoint_step_mark_ = every > 0 ? s.steps / every : 0;

  char line[512];
  std::snprintf(line, sizeof line, "restarted from %s: %s stage '%s' at t = %.9g s, step %lld",
                path.c_str(), s.mid_stage ? "inside" : "at the start of",
                deck_.stages[s.stage_index].name.c_str(), solver_->time(),
                static_cast<long long>(s.steps));
  log(line);
  if (!same_ranks)
    log("warning: the checkpoint was made on " + std::to_string(s.rank_point_counts.size()) +
        " MPI rank(s), this run has " + std::to_string(ranks) +
        ": it continues, but not bit for bit (sums at rank borders are added in another "
        "order)");
}

bool Simulation::resumeStage(RelaxationMonitor* relaxation, RestMonitor* rest) {
  if (!resume_pending_) return false;
  resume_pending_ = false;
  if (relaxation && resume_->has_relaxation) relaxation->restore(resume_->relaxation);
  if (rest) rest->startWindow(resume_->rest_window_start);  // (P12)
  return true;
}

// Fault injection for the crash and restart tests (doc/checkpoints.md): with
// ARGINE_FAULT_STOP_AT_STEP=N in the environment the process stops itself (SIGSTOP) after
// explicit step N, its output and its checkpoint if one was due, so that a test kills it with
// SIGKILL at a known point. Read once; absent or unparsable: never.
namespace {
long long faultStopStep() {
  static const long long step = [] {
    const char* text = std::getenv("ARGINE_FAULT_STOP_AT_STEP");
    char* end = nullptr;
    const long long value = text ? std::strtoll(text, &end, 10) : -1;
    return text && end != text && *end == '\0' ? value : -1;
  }();
  return step;
}
}  // namespace

void Simulation::checkpointIfDue(bool mid_stage) {
  writeCheckpointIfDue(mid_stage);
  if (mid_stage && summary_.steps == faultStopStep()) std::raise(SIGSTOP);
}

void Simulation::writeCheckpointIfDue(bool mid_stage) {
  const CheckpointSpec& spec = deck_.output.checkpoint;
  if (!spec.enabled()) return;
  // At a stage boundary the checkpoint says "before the next stage": none after the last.
  if (!mid_stage && stage_index_ + 1 >= deck_.stages.size()) return;
  // Steps: whenever the step count passes a multiple of Every Steps (the same steps in a
  // restarted run as in the uninterrupted one).
  const bool steps_due =
      spec.every_steps > 0 && summary_.steps / spec.every_steps > checkpoint_step_mark_;
  bool wall_due =
      spec.wall_interval > 0 && steadySeconds() - last_checkpoint_wall_ >= spec.wall_interval;
  if (distributed() && spec.wall_interval > 0) {  // rank 0's clock decides for all ranks
    int due = wall_due ? 1 : 0;
    MPI_Bcast(&due, 1, MPI_INT, 0, MPI_COMM_WORLD);
    wall_due = due != 0;
  }
  if (steps_due || wall_due) writeCheckpointNow(mid_stage);
}

void Simulation::writeCheckpointNow(bool mid_stage) {
  const double begin = steadySeconds();
  CheckpointState s;
  s.stage_index = static_cast<std::int64_t>(mid_stage ? stage_index_ : stage_index_ + 1);
  s.mid_stage = mid_stage;
  s.stage_start = stage_start_;
  s.next_output = next_output_;
  s.steps = summary_.steps;
  s.point_updates = summary_.point_updates;
  s.next_probe_time = next_probe_time_;
  s.initial_output_written = initial_output_written_;
  s.initial_time_step = initial_time_step_;
  s.initial_liquid_mass = initial_liquid_mass_;
  s.flux_last_step = flux_last_step_;
  s.flux_cumulative = flux_cumulative_;
  s.flux_all_nodes_cumulative = flux_all_nodes_cumulative_;
  s.flux_interior_nodes_cumulative = flux_interior_nodes_cumulative_;
  s.stage_log = stage_log_;
  s.solver = solver_->resumeState();
  s.solver.stage_started = mid_stage;
  if (distributed()) {
    // Collective: rank 0 collects every rank's solver state and points (rank after rank, each
    // in its memory order) and writes the one file.
    static_assert(std::is_trivially_copyable_v<ExplicitTwoPhaseSolver::ResumeState>,
                  "the solver states travel as bytes");
    const int ranks = ranks_->size();
    std::vector<ExplicitTwoPhaseSolver::ResumeState> all(writes() ? ranks : 0);
    MPI_Gather(&s.solver, sizeof s.solver, MPI_BYTE, all.data(), sizeof s.solver, MPI_BYTE, 0,
               MPI_COMM_WORLD);
    std::vector<long long> counts;
    s.points = gatherPointsByRank(MPI_COMM_WORLD, points_, counts);
    if (!writes()) {
      finishCheckpoint(begin, 0);
      return;
    }
    s.other_rank_solvers.assign(all.begin() + 1, all.end());
    s.rank_point_counts.assign(counts.begin(), counts.end());
  } else {
    s.points = points_;  // shares the Views: written as they are now
    s.rank_point_counts = {points_.count};
  }
  if (mid_stage && relaxation_) {
    s.has_relaxation = true;
    s.relaxation = relaxation_->state();
  }
  if (mid_stage && rest_) s.rest_window_start = rest_->windowStart();  // (P12)
  s.results = results_->resumePoint();
  s.diagnostics_bytes = diagnostics_->bytes();
  s.boundary_flux_bytes = boundary_flux_ ? boundary_flux_->bytes() : 0;
  if (probes_)
    for (const auto bytes : probes_->fileBytes()) s.probe_bytes.push_back(bytes);
  if (factor_of_safety_) s.factor_of_safety_bytes = factor_of_safety_->fileBytes();  // (P13)
  if (strength_reduction_trials_)                                                    // (P13)
    s.strength_reduction_bytes = {strength_reduction_trials_->bytes(),
                                  strength_reduction_points_->bytes()};
  s.mesh_nodes = mesh_.numNodes();
  s.mesh_elements = mesh_.numElements();
  finishCheckpoint(
      begin,
      writeCheckpoint(checkpointPath(options_.output_directory, deck_.output.name), deck_hash_, s));
}

void Simulation::finishCheckpoint(double begin, std::uintmax_t bytes) {
  const double end = steadySeconds();
  summary_.checkpoint_bytes = bytes;
  summary_.checkpoints += 1;
  summary_.checkpoint_seconds += end - begin;
  last_checkpoint_wall_ = end;
  const long long every = deck_.output.checkpoint.every_steps;
  checkpoint_step_mark_ = every > 0 ? summary_.steps / every : 0;
}

}  // namespace argine

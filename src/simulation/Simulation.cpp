#include "argine/simulation/Simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include <mpi.h>

#include "argine/boundary/DeckTimeSeriesCheck.hpp"
#include "argine/core/Error.hpp"
#include "argine/init/Initialisation.hpp"
#include "argine/input/DeckWords.hpp"
#include "argine/materials/SolidModel.hpp"
#include "argine/output/CsvWriter.hpp"
#include "argine/output/ProgressReporter.hpp"
#include "argine/output/ResultsWriter.hpp"
#include "argine/parallel/PointMigration.hpp"
#include "argine/parallel/RankDecomposition.hpp"
#include "argine/physics/DistributedStep.hpp"
#include "argine/physics/ExplicitTwoPhaseSolver.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/physics/PointInitialisation.hpp"
#include "argine/physics/StabilityCheck.hpp"
#include "argine/probes/ProbeWriter.hpp"
#include "argine/seepage/ImplicitSeepageSolver.hpp"
#include "argine/simulation/Checkpoint.hpp"
#include "argine/simulation/MaterialChanges.hpp"
#include "argine/simulation/PhysicalPressureRange.hpp"
#include "argine/simulation/RelaxationMonitor.hpp"
#include "argine/simulation/RestMonitor.hpp"
#include "argine/simulation/RunGuards.hpp"
#include "argine/simulation/Setup.hpp"
#include "argine/simulation/StepFallReport.hpp"
#include "argine/timestep/Criteria.hpp"

namespace argine {

namespace {

std::vector<std::string> materialNames(const Deck& deck) {
  std::vector<std::string> names;
  for (const auto& material : deck.materials) names.push_back(material.name);
  return names;
}

std::vector<NodalField> toOutputFields(const std::vector<NamedNodalField>& fields) {
  std::vector<NodalField> output;
  for (const auto& field : fields) output.push_back(NodalField{field.name, field.values});
  return output;
}

double wallSeconds() {
  using Clock = std::chrono::steady_clock;
  return std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
}

}  // namespace

void checkDeckSupported(const Deck& deck) {
  // Every solid model has a stress update (materials/SolidModel.hpp isImplemented); every
  // solver kind, including 'implicit seepage', runs; the hydraulic kinds (total head, pressure
  // series, infiltration, seepage face) are supported by the explicit and the implicit stages.
  // The time series of all stages are read now (P8): a bad gauge file of a later stage is an
  // input error before the first stage runs.
  checkDeckTimeSeries(deck);
}

Simulation::Simulation(const Deck& deck, const RunOptions& options)
    : deck_(deck), options_(options) {
  checkDeckSupported(deck_);
  checkMaterialsForExplicitSolver(deck_.materials);
  mesh_ = loadMesh(deck_);
  points_ = seedPoints(deck_, mesh_);
  stage_log_.push_back(initialisePoints(deck_, mesh_, points_));  // uniform or K0 (P4)
  solver_ = std::make_unique<ExplicitTwoPhaseSolver>(mesh_, points_, deck_.materials);
  // Output and the log follow points by id, so the solver may reorder them for locality.
  solver_->setSortInterval(ExplicitTwoPhaseSolver::kRecommendedSortInterval);
  solver_->setReproducibleSums(deck_.parallel.reproducible_sums);  // (P7) before distributing
  // Several MPI ranks: every rank seeded the same points; the explicit stages keep those of
  // its elements (doc/parallel.md). Only rank 0 prints and writes.
  int initialised = 0, ranks = 1, rank = 0;
  MPI_Initialized(&initialised);  // a library user may run without MPI: one rank
  if (initialised) {
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  }
  if (ranks > 1) {
    ranks_ = std::make_unique<RankDecomposition>(MPI_COMM_WORLD, mesh_,
                                                 pointsPerElementWeights(mesh_, points_));
    solver_->distribute(*ranks_);
  }
  if (rank != 0) options_.quiet = true;
  reports_ = rank == 0;
}

Simulation::~Simulation() = default;

std::string Simulation::gridPath() const {
  return results_ ? results_->gridPath() : "";
}
std::string Simulation::pointsPath() const {
  return results_ ? results_->pointsPath() : "";
}

RunSummary Simulation::run() {
  readRestartCheckpoint();  // (P8) --restart: a bad checkpoint is rejected before any output
  ProgressOptions progress_options;
  progress_options.quiet = options_.quiet;
  progress_ =
      std::make_unique<ProgressReporter>(ProgressReporter::forStandardOutput(progress_options));

  std::vector<std::string> nodal_names;
  for (const auto& field : solver_->nodalFields()) nodal_names.push_back(field.name);
  const MaterialPoints initial_points = gatheredPoints();
  // (P11) the lowest physical p_L of each material, from the initial state (the deck's; a
  // restart reads its checkpoint only below)
  // under the strongest gravity of the deck's stages (the drained suction, the larger)
  Real gravity = 0;
  for (const StageSpec& stage : deck_.stages) gravity = std::max(gravity, std::fabs(stage.gravity));
  lowest_pressures_ = lowestPhysicalPressures(initial_points, deck_.materials, gravity);
  // (P8) A restart continues the checkpointed run's files where the checkpoint left them.
  if (!writes()) {
    // rank > 0 of a distributed run: no files
  } else if (resume_)
    results_ = std::make_unique<ResultsWriter>(options_.output_directory, deck_.output.name, mesh_,
                                               materialNames(deck_), nodal_names, resume_->results);
  else
    results_ = std::make_unique<ResultsWriter>(options_.output_directory, deck_.output.name, mesh_,
                                               materialNames(deck_), nodal_names, initial_points);
  const std::string diagnostics_path =
      options_.output_directory + "/" + deck_.output.name + "_diagnostics.csv";
  const std::vector<std::string> diagnostics_columns{
      "time",        "time_step",   "kinetic_energy_solid",      "kinetic_energy_liquid",
      "liquid_mass", "lost_points", "unphysical_pressure_points"};
  if (!writes()) {
  } else if (resume_)
    diagnostics_ = std::make_unique<CsvWriter>(diagnostics_path, diagnostics_columns,
                                               CsvResume{resume_->diagnostics_bytes});
  else
    diagnostics_ = std::make_unique<CsvWriter>(diagnostics_path, diagnostics_columns);
  openBoundaryFluxLog();
  openFactorOfSafetyLog();  // (P13)
  if (!deck_.probes.empty() && writes())
    probes_ = std::make_unique<ProbeWriter>(
        deck_.probes, options_.output_directory, deck_.output.name, initial_points,
        resume_
            ? std::vector<std::uintmax_t>(resume_->probe_bytes.begin(), resume_->probe_bytes.end())
            : std::vector<std::uintmax_t>{});
  if (!options_.quiet && !stage_log_.empty()) std::printf("argine: %s\n", stage_log_[0].c_str());
  restoreFromCheckpoint();  // (P8) no-op without --restart

  total_points_ = totalPoints();
  const double wall_start = wallSeconds();
  // A resumed run carries the checkpoint's counts; its rate is of the updates it made itself.
  const double updates_at_start = static_cast<double>(summary_.point_updates);
  last_checkpoint_wall_ = wall_start;
  for (stage_index_ = resume_ ? static_cast<std::size_t>(resume_->stage_index) : 0;
       stage_index_ < deck_.stages.size(); ++stage_index_) {
    runStage(deck_.stages[stage_index_]);
    checkpointIfDue(false);  // (P8) at the stage boundary: "before the next stage"
  }
  summary_.wall_seconds = wallSeconds() - wall_start;
  summary_.end_time = solver_->time();
  summary_.output_steps = results_ ? results_->steps() : 0;
  const long long total_points = totalPoints();  // collective: before the rank-0 report

  if (reports_) {  // (P10) also with --quiet: quiet silences progress, not results
    const double rate = summary_.wall_seconds > 0
                            ? (static_cast<double>(summary_.point_updates) - updates_at_start) /
                                  summary_.wall_seconds
                            : 0;
    std::printf(
        "argine: %lld steps, %d points, %.3g s simulated in %.2f s wall: %.3g point-updates/s\n",
        summary_.steps, static_cast<int>(total_points), summary_.end_time, summary_.wall_seconds,
        rate);
    std::printf("argine: where the step time went:\n%s",
                solver_->profile().describe("argine:   ").c_str());
    std::printf("argine: results in %s and %s\n", results_->gridPath().c_str(),
                results_->pointsPath().c_str());
    if (summary_.checkpoints > 0)  // (P8)
      std::printf("argine: %d checkpoint(s) in %s, last %.3g MB, %.3g s in all\n",
                  summary_.checkpoints,
                  checkpointPath(options_.output_directory, deck_.output.name).c_str(),
                  summary_.checkpoint_bytes / 1e6, summary_.checkpoint_seconds);
  }
  return summary_;
}

void Simulation::runStage(const StageSpec& stage) {
  if (stage.solver == SolverKind::ImplicitSeepage) return runImplicitSeepageStage(stage);
  if (stage.strength_reduction.enabled) return runStrengthReductionStage(stage);  // (P13)
  const bool resumed = resume_pending_;  // (P8) restart inside this stage: its start is done
  if (!resumed) {
    applyStageMaterialChanges(stage);  // (P4) before beginStage: its energy scale sees them
    solver_->beginStage(stage);
    if (!initial_output_written_) writeInitialOutput();
  }
  beginStageGuards(stage);  // (P8) on a restart: balances count from the checkpoint
  std::unique_ptr<RelaxationMonitor> relaxation;
  std::unique_ptr<MaterialTable> relaxation_table;
  if (stage.relaxation.enabled) {
    relaxation = std::make_unique<RelaxationMonitor>(stage.relaxation, solver_->time());
    relaxation_table = std::make_unique<MaterialTable>(deck_.materials);
  }
  std::unique_ptr<RestMonitor> rest;  // (P12) Hand Back At Rest
  if (stage.hand_back.enabled) rest = std::make_unique<RestMonitor>(stage.hand_back);
  // Output times are start + k * interval; the step is shortened to land on them exactly.
  const Real interval = stage.output_interval > 0 ? stage.output_interval : stage.duration;
  // (P8) else start and next output from the checkpoint
  if (!resumeStage(relaxation.get(), rest.get())) {
    stage_start_ = solver_->time();
    next_output_ = stage_start_ + interval;
  }
  relaxation_ = relaxation.get();
  rest_ = rest.get();
  if (rest && !resumed) {  // (P12) the first window begins with the stage
    markRestReference(points_);
    rest->startWindow(stage_start_);
  }
  bool at_rest = false;  // (P12) the rest of the stage goes to the implicit path
  const Real start = stage_start_;
  const Real end = start + stage.duration;
  // Times within this tolerance of a target count as reaching it (round-off of sums of dt).
  const Real tolerance = 1e-9 * std::max<Real>(stage.duration, 1e-30);

  progress_->beginStage(stage.name, start, stage.duration, solver_->time());
  Real dt = 0;
  bool first_step = true;
  StepFallReport step_falls;  // a log line each time the critical step halves
  while (solver_->time() < end - tolerance) {
    const TimeStepChoice& choice = solver_->chooseTimeStep();
    if (first_step && !options_.quiet) logTimeStep(stage, choice);
    if (first_step) step_falls.begin(choice);
    const std::string fell = step_falls.note(stage.name, solver_->time(), summary_.steps, choice);
    if (!fell.empty()) log(fell);
    first_step = false;
    dt = choice.time_step;
    dt = std::min(dt, std::min(next_output_, end) - solver_->time());
    solver_->step(dt);
    implicit_liquid_mass_ = -1;  // the explicit diagnostics hold the liquid mass from now on
    accumulateBoundaryFluxes();
    checkGuards(stage);  // (P8) before any output of this step
    ++summary_.steps;
    summary_.point_updates += distributed() ? total_points_ : points_.count;
    bool written = false;
    if (solver_->time() >= next_output_ - tolerance) {
      writeOutput();
      written = true;
      next_output_ = std::min(end, next_output_ + interval);
      if (next_output_ <= solver_->time() + tolerance) next_output_ = end;
      if (handsOverOnFactorOfSafety(stage)) {  // (P13)
        progress_->update(summary_.steps, solver_->time(), dt,
                          distributed() ? static_cast<int>(total_points_) : points_.count);
        break;
      }
      if (rest && solver_->time() < end - tolerance && handsBackAtRest(stage, *rest)) {  // (P12)
        progress_->update(summary_.steps, solver_->time(), dt,
                          distributed() ? static_cast<int>(total_points_) : points_.count);
        at_rest = true;
        break;
      }
    } else if (!deck_.probes.empty() && deck_.probes.interval > 0 &&
               solver_->time() >= next_probe_time_ - tolerance) {
      writeProbes();
    }
    progress_->update(summary_.steps, solver_->time(), dt,
                      distributed() ? static_cast<int>(total_points_) : points_.count);
    if (relaxation) {
      if (addRelaxationStep(*relaxation, *relaxation_table)) {
        const Real stored = relaxation->stored();
        char line[256];
        std::snprintf(line, sizeof line,
                      "stage '%s': relaxed at t = %.6g s after %ld steps: kinetic energy / "
                      "stored elastic energy %.3g <= %.3g (kinetic peak %.4g J/m, stored %.4g "
                      "J/m)",
                      stage.name.c_str(), solver_->time(), relaxation->steps(), relaxation->ratio(),
                      stage.relaxation.kinetic_energy_ratio, relaxation->peak(), stored);
        log(line);
        if (!written) writeOutput();
        break;
      }
    }
    checkpointIfDue(true);  // (P8)
  }
  relaxation_ = nullptr;
  rest_ = nullptr;
  if (relaxation && !relaxation->relaxed()) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "stage '%s': NOT relaxed within %.6g s: kinetic energy / stored elastic "
                  "energy %.3g > %.3g",
                  stage.name.c_str(), stage.duration, relaxation->ratio(),
                  stage.relaxation.kinetic_energy_ratio);
    log(line);
  }
  // The stage's margin below the kinetic energy guard (RunGuards.hpp).
  const std::string peak = guards_->kineticEnergyPeak(stage.name);
  if (!peak.empty()) log(peak);
  logLiquidMadeInside(stage);
  logLowestFactorOfSafety(stage);  // (P13)
  progress_->endStage(summary_.steps, solver_->time(), dt);
  if (at_rest) runRestOfStageImplicitly(stage, end);  // (P12)
}

// ---------------------------------------------------------------- back to implicit (P12)
bool Simulation::handsBackAtRest(const StageSpec& stage, RestMonitor& rest) {
  const Real now = solver_->time();
  if (!rest.due(now)) return false;
  Real motion = largestMotionSinceReference(points_);
  if (distributed()) MPI_Allreduce(MPI_IN_PLACE, &motion, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  if (!rest.atRest(now, motion)) {
    markRestReference(points_);  // a new window from this output
    rest.startWindow(now);
    return false;
  }
  char line[320];
  std::snprintf(line, sizeof line,
                "stage '%s': at rest at t = %.6g s (no point moved more than %.3g m since t = "
                "%.6g s: a mean speed below %.3g m/s): the rest of the stage, to t = %.6g s, on "
                "the implicit seepage path",
                stage.name.c_str(), now, motion, rest.windowStart(), stage.hand_back.largest_speed,
                stage_start_ + stage.duration);
  log(line);
  return true;
}

void Simulation::runRestOfStageImplicitly(const StageSpec& stage, Real end) {
  StageSpec rest = stage;
  rest.solver = SolverKind::ImplicitSeepage;
  rest.duration = end - solver_->time();
  rest.material_changes.clear();  // applied when the stage began
  rest.hand_over_below_factor_of_safety = 0;
  rest.relaxation = {};
  rest.hand_back = {};
  // the stage's tables (heads, series, rain) count from the stage's start, not from now
  runImplicitSeepageStage(rest, stage_start_);
}

// ---------------------------------------------------------------- implicit seepage (P5)
// A fixed-skeleton seepage stage on the same points: the implicit solver advances to each
// output time with its own adaptive step, then hands p_L, S_L, rho_L, k, M_L to the points,
// from which the next stage (explicit or implicit) starts.
void Simulation::runImplicitSeepageStage(const StageSpec& stage, Real table_origin) {
  applyStageMaterialChanges(stage);  // (P4) into deck_.materials, which the solver reads
  if (!initial_output_written_) {    // the t = 0 state (no explicit time step to report)
    initial_output_written_ = true;
    writeOutput();
  }
  // The implicit solver keeps the points replicated on every rank (it splits its matrix
  // rows over the ranks itself): gather them for the stage, hand them back to the explicit
  // solver's ranks after it (redistribute below).
  if (distributed()) {
    points_ = gatherPoints(MPI_COMM_WORLD, points_, true);
    points_replicated_ = true;
  }
  ImplicitSeepageSolver seepage(mesh_, points_, deck_.materials);
  seepage.setTime(solver_->time());
  seepage.beginStage(stage, table_origin);
  const Real start = seepage.time();
  const Real end = start + stage.duration;
  const Real interval = stage.output_interval > 0 ? stage.output_interval : stage.duration;
  const Real tolerance = 1e-9 * std::max<Real>(stage.duration, 1e-30);
  const Real initial_mass = seepage.liquidMass();
  const long long steps_before = summary_.steps;
  progress_->beginStage(stage.name, start, stage.duration);
  Real target = start;
  Real inflow_counted = 0;  // kg/m of this stage's boundary inflow already in the totals
  const std::vector<std::string> condition_names = seepage.conditionNames();
  std::vector<Real> condition_counted(condition_names.size(), 0);  // the same per condition
  while (seepage.time() < end - tolerance) {
    target = std::min(end, target + interval);
    if (end - target <= tolerance) target = end;
    seepage.advanceTo(target);
    seepage.handOver();
    // The run's liquid bookkeeping (boundary-flux CSV, mass-balance guard) goes on through
    // the implicit stage: its stored mass and its inflow through all conditions.
    implicit_liquid_mass_ = seepage.liquidMass();
    implicit_time_step_ = seepage.lastAcceptedStep();
    flux_all_nodes_cumulative_ +=
        (seepage.totals().inflow - inflow_counted) / solver_->referenceLiquidDensity();
    inflow_counted = seepage.totals().inflow;
    accumulateImplicitBoundaryFluxes(condition_names, seepage.totals(), condition_counted);
    solver_->setTime(seepage.time());
    summary_.steps = steps_before + seepage.totals().steps;
    summary_.point_updates += seepage.totals().steps * points_.count;
    writeOutput();
    progress_->update(summary_.steps, seepage.time(), seepage.nextStep(), points_.count);
    if (handsOverOnFactorOfSafety(stage)) break;  // (P13)
  }
  logLowestFactorOfSafety(stage);  // (P13)
  if (distributed()) {             // each rank keeps the points of its elements again
    points_replicated_ = false;
    solver_->distribute(*ranks_);
  }
  progress_->endStage(summary_.steps, seepage.time(), seepage.nextStep());
  if (reports_) {
    const SeepageTotals& totals = seepage.totals();
    const Real stored = seepage.liquidMass() - initial_mass;
    std::printf(
        "argine: stage '%s' (implicit seepage): %lld steps (%lld rejected), %lld %s and "
        "%lld linear iterations; liquid mass change %.6g kg/m, boundary inflow %.6g kg/m\n",
        stage.name.c_str(), totals.steps, totals.rejected_steps, totals.picard_iterations,
        stage.seepage.iteration == SeepageIteration::Newton ? "Newton" : "Picard",
        totals.linear_iterations, stored, totals.inflow);
    std::fflush(stdout);
  }
}

bool Simulation::addRelaxationStep(RelaxationMonitor& relaxation, const MaterialTable& table) {
  const auto& d = solver_->diagnostics();
  Real stored = 0;
  if (deck_.parallel.reproducible_sums) {  // the same bits on any number of ranks (P7)
    std::vector<CompensatedReal> sums{compensatedStoredElasticEnergy(points_, table)};
    if (distributed()) {
      std::vector<Real> scratch;
      sumCompensatedOverRanks(MPI_COMM_WORLD, sums, scratch);
    }
    stored = sums[0].value();
  } else {
    stored = storedElasticEnergy(points_, table);
    if (distributed())  // the kinetic energies are reduced already
      MPI_Allreduce(MPI_IN_PLACE, &stored, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  }
  return relaxation.add(solver_->time(), d.kinetic_energy_solid + d.kinetic_energy_liquid, stored);
}

void Simulation::logTimeStep(const StageSpec& stage, const TimeStepChoice& choice) const {
  std::printf("argine: stage '%s' (%s): dt = %.4g s", stage.name.c_str(),
              deckWord(kSolverWords, stage.solver), choice.time_step);
  if (choice.automatic)
    std::printf(" = %.3g x %.4g s, %s\n", stage.time_step.safety_factor, choice.critical_step,
                governingText(choice).c_str());
  else
    std::printf(" (fixed)\n");
  std::printf(
      "argine: stage '%s': duration %.4g s, gravity %.4g m/s2, local damping %.3g, "
      "mass scaling %.4g\n",
      stage.name.c_str(), stage.duration, stage.gravity, stage.local_damping, stage.mass_scaling);
  std::fflush(stdout);
}

void Simulation::writeOutput() {
  const MaterialPoints points = gatheredPoints();
  const std::vector<NodalField> nodal = gatheredNodalFields();
  total_points_ = totalPoints();
  if (results_) results_->write(solver_->time(), points, nodal);
  writeDiagnostics(points);
  evaluateFactorOfSafety(points);  // (P13)
  writeBoundaryFluxes();
  writeProbes(points);
}

void Simulation::writeDiagnostics(const MaterialPoints& points) {
  if (!diagnostics_) return;
  const Real unphysical = static_cast<Real>(countUnphysicalPressures(points));
  const auto& d = solver_->diagnostics();
  const bool implicit = implicit_liquid_mass_ >= 0;  // the implicit path holds the state
  if (d.step > 0 && !implicit) {
    diagnostics_->writeRow({solver_->time(), d.time_step, d.kinetic_energy_solid,
                            d.kinetic_energy_liquid, d.liquid_mass,
                            static_cast<Real>(d.lost_points), unphysical});
    return;
  }
  // Before the first step the solver has no step sums: take them from the points, and the
  // step the first stage is about to take (P4: a meaningful t = 0 row). On the implicit
  // seepage path: its last step, its liquid mass, and no kinetic energy (a fixed skeleton
  // and Darcy flow without inertia; the points keep the velocities of the last explicit
  // step for the next one, which are not a motion of this stage).
  const PointTotals totals = sumPointTotals(points);
  const MaterialPoints pts = points;
  int lost = 0;
  Kokkos::parallel_reduce(
      "count_lost_points", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p, int& sum) { sum += pts.element(p) < 0 ? 1 : 0; }, lost);
  if (implicit)
    diagnostics_->writeRow({solver_->time(), implicit_time_step_, 0.0, 0.0, implicit_liquid_mass_,
                            static_cast<Real>(lost), unphysical});
  else
    diagnostics_->writeRow({solver_->time(), initial_time_step_, totals.kinetic_energy_solid,
                            totals.kinetic_energy_liquid, totals.liquid_mass,
                            static_cast<Real>(lost), unphysical});
}

int Simulation::countUnphysicalPressures(const MaterialPoints& points) {
  // (P11) the points whose p_L lies outside its physical range (PhysicalPressureRange.hpp);
  // rank 0 holds all points here and warns, as the guards do (stderr, also with --quiet)
  const StageSpec& stage = deck_.stages.at(std::min(stage_index_, deck_.stages.size() - 1));
  const Real highest = largestTotalVerticalStress(points, stage.gravity, stageSurcharge(stage));
  const PressureRangeCount count =
      countPressuresOutsideRange(points, deck_.materials, lowest_pressures_, highest);
  if (count.outside > 0) {
    const std::string line =
        "stage '" + stage.name + "': " + describePressureRange(count, solver_->time());
    std::fprintf(stderr, "argine: warning: %s\n", line.c_str());
    stage_log_.push_back("warning: " + line);
  }
  return count.outside;
}

// ---------------------------------------------------------------- issue P4

void Simulation::log(const std::string& line) {
  stage_log_.push_back(line);
  if (!options_.quiet) {
    std::printf("argine: %s\n", line.c_str());
    std::fflush(stdout);
  }
}

void Simulation::applyStageMaterialChanges(const StageSpec& stage) {
  if (stage.material_changes.empty()) return;
  const std::vector<std::string> lines =
      applyMaterialChanges(stage.name, stage.material_changes, deck_.materials);
  solver_->setMaterials(deck_.materials);
  for (const auto& line : lines) log("stage '" + stage.name + "': " + line);
}

void Simulation::writeInitialOutput() {
  initial_time_step_ = solver_->chooseTimeStep().time_step;
  initial_output_written_ = true;
  writeOutput();
}

void Simulation::writeProbes() {
  if (deck_.probes.empty()) return;
  writeProbes(gatheredPoints());
}

void Simulation::writeProbes(const MaterialPoints& points) {
  if (deck_.probes.empty()) return;
  if (probes_) probes_->write(solver_->time(), points);
  // Every rank keeps the probe clock: the gather before a probe row is collective.
  if (deck_.probes.interval > 0) {
    while (next_probe_time_ <= solver_->time() * (1 + 1e-12))
      next_probe_time_ += deck_.probes.interval;
  }
}

// ---------------------------------------------------------------- hydraulic boundary fluxes
// <name>_boundary_flux.csv: at each output time, the liquid volume (m^3 per m thickness)
// that entered the soil through each hydraulic condition in the last step and since the
// start, the net inflow through all nodes, and the storage change of the points
// (sum M_L - initial) / rho_L. Written only when some stage has hydraulic conditions.

void Simulation::openBoundaryFluxLog() {
  for (const auto& stage : deck_.stages)
    for (const auto& boundary : stage.boundaries) {
      const bool hydraulic = boundary.kind == BoundaryKind::TotalHead ||
                             boundary.kind == BoundaryKind::PressureSeries ||
                             boundary.kind == BoundaryKind::Infiltration ||
                             boundary.kind == BoundaryKind::SeepageFace;
      if (hydraulic &&
          std::find(flux_names_.begin(), flux_names_.end(), boundary.name) == flux_names_.end())
        flux_names_.push_back(boundary.name);
    }
  if (flux_names_.empty()) return;
  flux_last_step_.assign(flux_names_.size(), 0.0);
  flux_cumulative_.assign(flux_names_.size(), 0.0);
  // Summed over all points in id order on rank 0 (the one writing), as on one rank.
  const MaterialPoints all = gatheredPoints();
  const auto mass = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), all.mass_liquid);
  initial_liquid_mass_ = 0;
  for (int p = 0; p < all.count; ++p) initial_liquid_mass_ += mass(p);
  if (!writes()) return;
  std::vector<std::string> columns{"time", "storage_change", "net_inflow_all_nodes",
                                   "net_inflow_interior_nodes"};
  for (const auto& name : flux_names_) {
    columns.push_back(name + "_step");
    columns.push_back(name + "_cumulative");
  }
  const std::string path =
      options_.output_directory + "/" + deck_.output.name + "_boundary_flux.csv";
  if (resume_)  // (P8) continue the checkpointed run's file
    boundary_flux_ =
        std::make_unique<CsvWriter>(path, columns, CsvResume{resume_->boundary_flux_bytes});
  else
    boundary_flux_ = std::make_unique<CsvWriter>(path, columns);
}

std::size_t Simulation::fluxColumn(const std::string& name) const {
  return static_cast<std::size_t>(std::find(flux_names_.begin(), flux_names_.end(), name) -
                                  flux_names_.begin());
}

void Simulation::accumulateBoundaryFluxes() {
  if (!boundary_flux_) return;
  std::fill(flux_last_step_.begin(), flux_last_step_.end(), 0.0);
  const auto& conditions = solver_->hydraulicConditions().conditions();
  const auto& volumes = solver_->boundaryFluxVolumes();
  for (std::size_t c = 0; c < conditions.size(); ++c) {
    const std::size_t k = fluxColumn(conditions[c].name);
    flux_last_step_[k] = volumes[c];
    flux_cumulative_[k] += volumes[c];
  }
  // (all nodes: also in a stage whose only rule is the atmosphere's, which passes liquid)
  flux_all_nodes_cumulative_ += volumes[conditions.size()];
  flux_interior_nodes_cumulative_ += volumes[conditions.size() + 1];
}

// (P10) The implicit path's per-condition columns: the volume through each condition in its
// last accepted step (`_step`) and since the start (`_cumulative`), as on the explicit path.
void Simulation::accumulateImplicitBoundaryFluxes(const std::vector<std::string>& names,
                                                  const SeepageTotals& totals,
                                                  std::vector<Real>& counted) {
  if (!boundary_flux_ || totals.condition_inflow.size() != names.size()) return;
  std::fill(flux_last_step_.begin(), flux_last_step_.end(), 0.0);
  const Real density = solver_->referenceLiquidDensity();
  for (std::size_t c = 0; c < names.size(); ++c) {
    const std::size_t k = fluxColumn(names[c]);
    if (k == flux_names_.size()) continue;  // (not a hydraulic condition: carries nothing)
    flux_last_step_[k] = totals.condition_inflow_last_step[c] / density;
    flux_cumulative_[k] += (totals.condition_inflow[c] - counted[c]) / density;
    counted[c] = totals.condition_inflow[c];
  }
}

void Simulation::logLiquidMadeInside(const StageSpec& stage) {
  // What a cracking, deforming body's point mass balance makes at the nodes inside it is
  // no water that entered (doc/theory.md Sec. 5.5, "Flux accounting"): said once a stage,
  // beside the CSV column, so that a user reads it next to the pore pressures.
  if (!boundary_flux_) return;
  char line[320];
  std::snprintf(line, sizeof line,
                "stage '%s': liquid stored since the run started %+.4g m3/m, of it made at the "
                "nodes inside the body (net_inflow_interior_nodes) %+.4g m3/m",
                stage.name.c_str(),
                (liquidMassNow() - initial_liquid_mass_) / solver_->referenceLiquidDensity(),
                flux_interior_nodes_cumulative_);
  log(line);
}

Real Simulation::liquidMassNow() const {
  if (implicit_liquid_mass_ >= 0) return implicit_liquid_mass_;
  return solver_->diagnostics().step > 0 ? solver_->diagnostics().liquid_mass
                                         : initial_liquid_mass_;
}

void Simulation::writeBoundaryFluxes() {
  if (!boundary_flux_) return;  // also on ranks > 0
  const Real mass = liquidMassNow();
  std::vector<Real> row{solver_->time(),
                        (mass - initial_liquid_mass_) / solver_->referenceLiquidDensity(),
                        flux_all_nodes_cumulative_, flux_interior_nodes_cumulative_};
  for (std::size_t k = 0; k < flux_names_.size(); ++k) {
    row.push_back(flux_last_step_[k]);
    row.push_back(flux_cumulative_[k]);
  }
  boundary_flux_->writeRow(row);
}

// ---------------------------------------------------------------- several MPI ranks (P7)

bool Simulation::writes() const {
  return !distributed() || ranks_->rank() == 0;
}

MaterialPoints Simulation::gatheredPoints() const {
  if (!distributed() || points_replicated_) return points_;
  return gatherPoints(MPI_COMM_WORLD, points_, false);
}

long long Simulation::totalPoints() const {
  long long count = points_.count;
  if (distributed() && !points_replicated_)
    MPI_Allreduce(MPI_IN_PLACE, &count, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  return count;
}

std::vector<NodalField> Simulation::gatheredNodalFields() {
  std::vector<NodalField> fields = toOutputFields(solver_->nodalFields());
  if (!distributed()) return fields;
  // A node's value is complete on the rank owning it (shared nodes are completed on every
  // rank holding them): rank 0 takes each node from its owner. Exact: the sum adds zeros.
  const auto owned =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ranks_->nodeOwnedView());
  const int nodes = mesh_.numNodes();
  std::vector<Real> mine(static_cast<std::size_t>(nodes) * fields.size(), 0.0);
  for (std::size_t f = 0; f < fields.size(); ++f) {
    const auto values = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), fields[f].values);
    for (int n = 0; n < nodes; ++n)
      if (owned(n)) mine[f * nodes + n] = values(n);
  }
  std::vector<Real> all(writes() ? mine.size() : 0);
  MPI_Reduce(mine.data(), all.data(), static_cast<int>(mine.size()), MPI_DOUBLE, MPI_SUM, 0,
             MPI_COMM_WORLD);
  if (!writes()) return fields;  // not written
  for (std::size_t f = 0; f < fields.size(); ++f) {
    Kokkos::View<Real*, MemSpace> complete(fields[f].name, nodes);
    const auto host = Kokkos::create_mirror_view(complete);
    for (int n = 0; n < nodes; ++n) host(n) = all[f * nodes + n];
    Kokkos::deep_copy(complete, host);
    fields[f].values = complete;
  }
  return fields;
}

}  // namespace argine

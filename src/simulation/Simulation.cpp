#include "argine/simulation/Simulation.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

#include "argine/core/Error.hpp"
#include "argine/input/DeckWords.hpp"
#include "argine/materials/SolidModel.hpp"
#include "argine/output/CsvWriter.hpp"
#include "argine/output/ProgressReporter.hpp"
#include "argine/output/ResultsWriter.hpp"
#include "argine/physics/ExplicitTwoPhaseSolver.hpp"
#include "argine/physics/PointInitialisation.hpp"
#include "argine/seepage/ImplicitSeepageSolver.hpp"
#include "argine/simulation/Setup.hpp"
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
  for (const auto& material : deck.materials) {
    if (!isImplemented(material.solid.model))
      throw InputError("Materials/" + material.name + "/Solid/Model",
                       std::string("'") + deckWord(kSolidModelWords, material.solid.model) +
                           "' has no stress update in this version; use 'linear elastic'");
  }
  // implicit seepage (P5): infiltration and seepage faces exist for implicit stages only.
  for (const auto& stage : deck.stages) {
    if (stage.solver == SolverKind::ImplicitSeepage) continue;
    for (const auto& boundary : stage.boundaries)
      if (boundary.kind == BoundaryKind::Infiltration || boundary.kind == BoundaryKind::SeepageFace)
        throw InputError("Stages/" + stage.name + "/Boundary Conditions/" + boundary.name,
                         "'infiltration' and 'seepage face' need an 'implicit seepage' stage in "
                         "this version");
  }
}

Simulation::Simulation(const Deck& deck, const RunOptions& options)
    : deck_(deck), options_(options) {
  checkDeckSupported(deck_);
  checkMaterialsForExplicitSolver(deck_.materials);
  mesh_ = loadMesh(deck_);
  points_ = seedPoints(deck_, mesh_);
  initialisePointState(deck_.materials, points_);
  solver_ = std::make_unique<ExplicitTwoPhaseSolver>(mesh_, points_, deck_.materials);
  // Output and the log follow points by id, so the solver may reorder them for locality.
  solver_->setSortInterval(ExplicitTwoPhaseSolver::kRecommendedSortInterval);
}

Simulation::~Simulation() = default;

std::string Simulation::gridPath() const {
  return results_ ? results_->gridPath() : "";
}
std::string Simulation::pointsPath() const {
  return results_ ? results_->pointsPath() : "";
}

RunSummary Simulation::run() {
  ProgressOptions progress_options;
  progress_options.quiet = options_.quiet;
  progress_ =
      std::make_unique<ProgressReporter>(ProgressReporter::forStandardOutput(progress_options));

  std::vector<std::string> nodal_names;
  for (const auto& field : solver_->nodalFields()) nodal_names.push_back(field.name);
  results_ = std::make_unique<ResultsWriter>(options_.output_directory, deck_.output.name, mesh_,
                                             materialNames(deck_), nodal_names, points_);
  diagnostics_ = std::make_unique<CsvWriter>(
      options_.output_directory + "/" + deck_.output.name + "_diagnostics.csv",
      std::vector<std::string>{"time", "time_step", "kinetic_energy_solid", "kinetic_energy_liquid",
                               "liquid_mass", "lost_points"});
  writeOutput();

  const double wall_start = wallSeconds();
  for (const auto& stage : deck_.stages) runStage(stage);
  summary_.wall_seconds = wallSeconds() - wall_start;
  summary_.end_time = solver_->time();
  summary_.output_steps = results_->steps();

  if (!options_.quiet) {
    const double rate =
        summary_.wall_seconds > 0 ? summary_.point_updates / summary_.wall_seconds : 0;
    std::printf(
        "argine: %lld steps, %d points, %.3g s simulated in %.2f s wall: %.3g point-updates/s\n",
        summary_.steps, points_.count, summary_.end_time, summary_.wall_seconds, rate);
    std::printf("argine: where the step time went:\n%s",
                solver_->profile().describe("argine:   ").c_str());
    std::printf("argine: results in %s and %s\n", results_->gridPath().c_str(),
                results_->pointsPath().c_str());
  }
  return summary_;
}

void Simulation::runStage(const StageSpec& stage) {
  if (stage.solver == SolverKind::ImplicitSeepage) return runImplicitSeepageStage(stage);
  solver_->beginStage(stage);
  const Real start = solver_->time();
  const Real end = start + stage.duration;
  // Output times are start + k * interval; the step is shortened to land on them exactly.
  const Real interval = stage.output_interval > 0 ? stage.output_interval : stage.duration;
  Real next_output = start + interval;
  // Times within this tolerance of a target count as reaching it (round-off of sums of dt).
  const Real tolerance = 1e-9 * std::max<Real>(stage.duration, 1e-30);

  progress_->beginStage(stage.name, start, stage.duration);
  Real dt = 0;
  bool first_step = true;
  while (solver_->time() < end - tolerance) {
    const TimeStepChoice& choice = solver_->chooseTimeStep();
    if (first_step && !options_.quiet) logTimeStep(stage, choice);
    first_step = false;
    dt = choice.time_step;
    dt = std::min(dt, std::min(next_output, end) - solver_->time());
    solver_->step(dt);
    ++summary_.steps;
    summary_.point_updates += points_.count;
    if (solver_->time() >= next_output - tolerance) {
      writeOutput();
      next_output = std::min(end, next_output + interval);
      if (next_output <= solver_->time() + tolerance) next_output = end;
    }
    progress_->update(summary_.steps, solver_->time(), dt, points_.count);
  }
  progress_->endStage(summary_.steps, solver_->time(), dt);
}

// ---------------------------------------------------------------- implicit seepage (P5)
// A fixed-skeleton seepage stage on the same points: the implicit solver advances to each
// output time with its own adaptive step, then hands p_L, S_L, rho_L, k, M_L to the points,
// from which the next stage (explicit or implicit) starts.
void Simulation::runImplicitSeepageStage(const StageSpec& stage) {
  ImplicitSeepageSolver seepage(mesh_, points_, deck_.materials);
  seepage.setTime(solver_->time());
  seepage.beginStage(stage);
  const Real start = seepage.time();
  const Real end = start + stage.duration;
  const Real interval = stage.output_interval > 0 ? stage.output_interval : stage.duration;
  const Real tolerance = 1e-9 * std::max<Real>(stage.duration, 1e-30);
  const Real initial_mass = seepage.liquidMass();
  const long long steps_before = summary_.steps;
  progress_->beginStage(stage.name, start, stage.duration);
  Real target = start;
  while (seepage.time() < end - tolerance) {
    target = std::min(end, target + interval);
    if (end - target <= tolerance) target = end;
    seepage.advanceTo(target);
    seepage.handOver();
    solver_->setTime(seepage.time());
    summary_.steps = steps_before + seepage.totals().steps;
    summary_.point_updates += seepage.totals().steps * points_.count;
    writeOutput();
    progress_->update(summary_.steps, seepage.time(), seepage.nextStep(), points_.count);
  }
  progress_->endStage(summary_.steps, seepage.time(), seepage.nextStep());
  if (!options_.quiet) {
    const SeepageTotals& totals = seepage.totals();
    const Real stored = seepage.liquidMass() - initial_mass;
    std::printf(
        "argine: stage '%s' (implicit seepage): %lld steps (%lld rejected), %lld Picard and "
        "%lld linear iterations; liquid mass change %.6g kg/m, boundary inflow %.6g kg/m\n",
        stage.name.c_str(), totals.steps, totals.rejected_steps, totals.picard_iterations,
        totals.linear_iterations, stored, totals.inflow);
    std::fflush(stdout);
  }
}

void Simulation::logTimeStep(const StageSpec& stage, const TimeStepChoice& choice) const {
  std::printf("argine: stage '%s' (%s): dt = %.4g s", stage.name.c_str(),
              deckWord(kSolverWords, stage.solver), choice.time_step);
  if (choice.automatic)
    std::printf(" = %.3g x %.4g s, governed by '%s' at point %d (%.4g, %.4g) m\n",
                stage.time_step.safety_factor, choice.critical_step,
                criterionName(choice.governing), choice.point_id, choice.position[0],
                choice.position[1]);
  else
    std::printf(" (fixed)\n");
  std::printf(
      "argine: stage '%s': duration %.4g s, gravity %.4g m/s2, local damping %.3g, "
      "mass scaling %.4g\n",
      stage.name.c_str(), stage.duration, stage.gravity, stage.local_damping, stage.mass_scaling);
  std::fflush(stdout);
}

void Simulation::writeOutput() {
  results_->write(solver_->time(), points_, toOutputFields(solver_->nodalFields()));
  writeDiagnostics();
}

void Simulation::writeDiagnostics() {
  const auto& d = solver_->diagnostics();
  diagnostics_->writeRow({solver_->time(), d.time_step, d.kinetic_energy_solid,
                          d.kinetic_energy_liquid, d.liquid_mass,
                          static_cast<Real>(d.lost_points)});
}

}  // namespace argine

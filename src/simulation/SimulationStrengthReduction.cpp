// A strength-reduction stage (P13 item 3): trials from the state the stage found, each with
// the strength of the Mohr-Coulomb materials divided by a factor F
// (materials/SolidModel.hpp reducedStrength), judged by non-convergence, by accelerating and by
// continuing displacement (StrengthReductionTrial.hpp), F chosen by StrengthReductionSearch. The
// stage leaves the points, the solver and the materials as it found them.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <mpi.h>

#include "argine/core/Error.hpp"
#include "argine/input/DeckWords.hpp"
#include "argine/output/CsvWriter.hpp"
#include "argine/output/ProgressReporter.hpp"
#include "argine/parallel/PointMigration.hpp"
#include "argine/physics/ExplicitTwoPhaseSolver.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/simulation/Checkpoint.hpp"
#include "argine/simulation/RelaxationMonitor.hpp"
#include "argine/simulation/RunGuards.hpp"
#include "argine/simulation/Simulation.hpp"
#include "argine/simulation/StrengthReductionSearch.hpp"
#include "argine/simulation/StrengthReductionTrial.hpp"

namespace argine {

namespace {

/// Per point id (0 .. ids - 1), `stride` values picked by `pick` from the (gathered) points; a
/// point no longer present keeps the values of `fallback` (or zeros).
template <class Pick>
std::vector<Real> valuesById(const MaterialPoints& points, int ids, int stride, Pick pick,
                             const std::vector<Real>* fallback = nullptr) {
  std::vector<Real> values =
      fallback ? *fallback : std::vector<Real>(static_cast<std::size_t>(ids) * stride, 0.0);
  const auto id = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.id);
  for (int p = 0; p < points.count; ++p)
    if (id(p) >= 0 && id(p) < ids) pick(p, &values[static_cast<std::size_t>(id(p)) * stride]);
  return values;
}

std::vector<Real> displacementsById(const MaterialPoints& points, int ids,
                                    const std::vector<Real>* fallback = nullptr) {
  const auto u = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.displacement);
  return valuesById(
      points, ids, 2,
      [&](int p, Real* out) {
        out[0] = u(p, 0);
        out[1] = u(p, 1);
      },
      fallback);
}

/// The failure mechanism of a trial: per id x, y (m), displacement over the trial (m),
/// deviatoric strain increment (-) and plastic state, from the points at its end.
std::vector<Real> mechanismById(const MaterialPoints& points, int ids,
                                const std::vector<Real>& start_u,
                                const std::vector<Real>& start_strain) {
  const auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.position);
  const auto u = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.displacement);
  const auto e = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.deviatoric_strain);
  const auto state = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.plastic_state);
  const auto id = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.id);
  const std::vector<Real> absent(static_cast<std::size_t>(ids) * 5,
                                 std::numeric_limits<Real>::quiet_NaN());
  return valuesById(
      points, ids, 5,
      [&](int p, Real* out) {
        const int i = id(p);
        out[0] = x(p, 0);
        out[1] = x(p, 1);
        out[2] = std::hypot(u(p, 0) - start_u[2 * i], u(p, 1) - start_u[2 * i + 1]);
        out[3] = e(p) - start_strain[i];
        out[4] = state(p);
      },
      &absent);
}

}  // namespace

void Simulation::runStrengthReductionStage(const StageSpec& stage) {
  const StrengthReductionSpec& spec = stage.strength_reduction;
  solver_->beginStage(stage);
  if (!initial_output_written_) writeInitialOutput();
  const Real start = solver_->time();
  // The state every trial starts from: this rank's points, the solver's step-to-step state,
  // the materials.
  const MaterialPoints saved_points = pointRange(points_, 0, points_.count);
  const ExplicitTwoPhaseSolver::ResumeState saved_state = solver_->resumeState();
  const std::vector<MaterialSpec> materials = deck_.materials;
  const MaterialPoints start_points = gatheredPoints();  // all points (rank 0)
  // Per-id arrays up to the largest id (points removed by an earlier stage leave gaps).
  const int ids = [&] {
    const auto id = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), start_points.id);
    int largest = -1;
    for (int p = 0; p < start_points.count; ++p) largest = std::max(largest, id(p));
    return largest + 1;
  }();
  const std::vector<Real> start_u = displacementsById(start_points, ids);
  const auto strain_host =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), start_points.deviatoric_strain);
  const std::vector<Real> start_strain =
      valuesById(start_points, ids, 1, [&](int p, Real* out) { out[0] = strain_host(p); });

  // One file of trials and one of mechanisms for the whole run, the stage's start time in
  // their first column (a deck may reduce at several states).
  const std::string stem = options_.output_directory + "/" + deck_.output.name;
  if (writes() && !strength_reduction_trials_) {
    const std::vector<std::string> trial_columns{"time",
                                                 "trial",
                                                 "factor",
                                                 "converged",
                                                 "accelerating",
                                                 "failed",
                                                 "kinetic_energy_ratio",
                                                 "duration",
                                                 "steps",
                                                 "largest_displacement",
                                                 "mobilised_points",
                                                 "mobilised_displacement",
                                                 "third_quarter_rate",
                                                 "last_quarter_rate",
                                                 "continuing"};
    const std::vector<std::string> point_columns{"time",
                                                 "factor",
                                                 "failed",
                                                 "id",
                                                 "x",
                                                 "y",
                                                 "displacement",
                                                 "deviatoric_strain_increment",
                                                 "plastic_state"};
    // (P8) a restart after an earlier strength-reduction stage continues its files
    const std::vector<std::uint64_t> resume =
        resume_ ? resume_->strength_reduction_bytes : std::vector<std::uint64_t>{};
    auto open = [&](const std::string& suffix, const std::vector<std::string>& columns,
                    std::size_t k) {
      const std::string path = stem + suffix;
      return resume.size() == 2 ? std::make_unique<CsvWriter>(path, columns, CsvResume{resume[k]})
                                : std::make_unique<CsvWriter>(path, columns);
    };
    strength_reduction_trials_ = open("_strength_reduction.csv", trial_columns, 0);
    strength_reduction_points_ = open("_strength_reduction_points.csv", point_columns, 1);
  }
  CsvWriter* csv = strength_reduction_trials_.get();
  {
    char line[320];
    std::snprintf(line, sizeof line,
                  "stage '%s': strength reduction from t = %.6g s: trials of %.4g s, "
                  "F from %.4g (step %.3g, tolerance %.3g, within [%.3g, %.3g]), failure by %s",
                  stage.name.c_str(), start, stage.duration, spec.initial_factor, spec.factor_step,
                  spec.tolerance, spec.minimum_factor, spec.maximum_factor,
                  deckWord(kStrengthReductionCriterionWords, spec.criterion));
    log(line);
  }

  StrengthReductionSearch search(spec);
  std::vector<Real> holding_map, failing_map;  // mechanisms at the bracket's ends
  Real holding_factor = 0, failing_factor = std::numeric_limits<Real>::infinity();
  const int snapshots = 32;  // displacement samples per trial, for its half-time value
  while (!search.done()) {
    const Real factor = search.next();
    points_ = pointRange(saved_points, 0, saved_points.count);
    solver_->resume(saved_state);
    deck_.materials = materials;
    for (MaterialSpec& m : deck_.materials) m.solid.strength_reduction = factor;
    solver_->setMaterials(deck_.materials);
    beginStageGuards(stage);
    const MaterialTable table(deck_.materials);
    RelaxationMonitor relaxation(stage.relaxation, start);
    std::vector<std::pair<Real, std::vector<Real>>> samples;  // (time from start, u by id)
    Real next_sample = stage.duration / snapshots;
    long steps = 0;
    std::string stopped;
    progress_->beginStage(stage.name, start, stage.duration);
    const Real end = start + stage.duration;
    const Real tolerance = 1e-9 * stage.duration;
    try {
      while (solver_->time() < end - tolerance) {
        const Real dt = std::min(solver_->chooseTimeStep().time_step, end - solver_->time());
        solver_->step(dt);
        checkGuards(stage);
        ++steps;
        ++summary_.steps;
        summary_.point_updates += distributed() ? total_points_ : points_.count;
        progress_->update(summary_.steps, solver_->time(), dt,
                          distributed() ? static_cast<int>(total_points_) : points_.count);
        if (solver_->time() - start >= next_sample - tolerance) {
          samples.emplace_back(solver_->time() - start,
                               displacementsById(gatheredPoints(), ids, &start_u));
          next_sample += stage.duration / snapshots;
        }
        // Every trial runs the whole Duration (s) and is judged at its end, so that all
        // factors are judged at the same time: a mass that passes for relaxed early may still
        // be creeping (the file comment of StrengthReductionTrial.hpp).
        addRelaxationStep(relaxation, table);
      }
    } catch (const RunError& error) {  // e.g. points leaving the mesh: the trial failed
      stopped = error.what();
    }
    progress_->endStage(summary_.steps, solver_->time(), 0);
    const MaterialPoints end_points = gatheredPoints();
    const Real elapsed = solver_->time() - start;
    StrengthReductionTrial trial;
    trial.factor = factor;
    trial.converged = relaxation.relaxed() && stopped.empty();
    DisplacementTrend trend;
    const std::vector<Real> end_u = displacementsById(end_points, ids, &start_u);
    // The samples nearest to half and three quarters of the trial (before its end).
    auto nearest = [&](Real t) {
      std::size_t k = samples.size();
      for (std::size_t j = 0; j < samples.size(); ++j)
        if (samples[j].first < elapsed * (1 - 1e-9) &&
            (k == samples.size() ||
             std::fabs(samples[j].first - t) < std::fabs(samples[k].first - t)))
          k = j;
      return k;
    };
    const std::size_t half = nearest(0.5 * elapsed), three_quarters = nearest(0.75 * elapsed);
    if (half < samples.size() && three_quarters < samples.size() &&
        samples[half].first < samples[three_quarters].first)
      trend = displacementTrend(start_u, samples[half].second, samples[three_quarters].second,
                                end_u, samples[half].first, samples[three_quarters].first, elapsed,
                                spec.minimum_displacement);
    // The points are gathered on rank 0 only: its verdict is every rank's, so that all ranks
    // follow one search.
    if (distributed()) {
      int verdicts[2] = {trend.accelerating ? 1 : 0, trend.continuing ? 1 : 0};
      MPI_Bcast(verdicts, 2, MPI_INT, 0, MPI_COMM_WORLD);
      trend.accelerating = verdicts[0] != 0;
      trend.continuing = verdicts[1] != 0;
    }
    // Not overruled by the relaxation: a mass creeping at a few mm/s carries a kinetic energy
    // below 1e-6 of a slope's stored elastic energy, so a trial can pass for relaxed while
    // its mobilised mass speeds up (the dry slope at 0.125 m, F = 1.05: 1.1 -> 1.2 mm/s).
    trial.accelerating = trend.accelerating || !stopped.empty();
    trial.continuing = trend.continuing || !stopped.empty();
    const bool failed = trial.failed(spec.criterion);
    search.record(trial);
    if (csv)
      csv->writeRow({start, static_cast<Real>(search.trials().size()), factor,
                     trial.converged ? 1.0 : 0.0, trial.accelerating ? 1.0 : 0.0,
                     failed ? 1.0 : 0.0, relaxation.ratio(), elapsed, static_cast<Real>(steps),
                     trend.largest, static_cast<Real>(trend.mobilised_points), trend.mean,
                     trend.earlier_rate, trend.later_rate, trial.continuing ? 1.0 : 0.0});
    if (failed && factor < failing_factor) {
      failing_factor = factor;
      failing_map = mechanismById(end_points, ids, start_u, start_strain);
    } else if (!failed && factor > holding_factor) {
      holding_factor = factor;
      holding_map = mechanismById(end_points, ids, start_u, start_strain);
    }
    char line[512];
    std::snprintf(line, sizeof line,
                  "stage '%s': F = %.4g %s after %.4g s (%ld steps): %s, kinetic energy ratio "
                  "%.3g; mobilised mass %d points, mean displacement %.4g m, rate %.3g -> %.3g "
                  "m/s%s%s",
                  stage.name.c_str(), factor, failed ? "FAILS" : "holds", elapsed, steps,
                  trial.converged ? "relaxed" : "not relaxed", relaxation.ratio(),
                  trend.mobilised_points, trend.mean, trend.earlier_rate, trend.later_rate,
                  stopped.empty() ? "" : "; stopped: ", stopped.c_str());
    log(line);
  }

  // The state as the stage found it.
  points_ = pointRange(saved_points, 0, saved_points.count);
  solver_->resume(saved_state);
  deck_.materials = materials;
  solver_->setMaterials(deck_.materials);

  if (CsvWriter* map = strength_reduction_points_.get()) {
    auto write = [&](const std::vector<Real>& values, Real factor, bool failed) {
      for (int i = 0; i < ids && !values.empty(); ++i) {
        const Real* v = &values[static_cast<std::size_t>(i) * 5];
        if (std::isnan(v[0])) continue;
        map->writeRow({start, factor, failed ? 1.0 : 0.0, static_cast<Real>(i), v[0], v[1], v[2],
                       v[3], v[4]});
      }
    };
    write(holding_map, holding_factor, false);
    write(failing_map, failing_factor, true);
  }
  auto describe = [&](StrengthReductionCriterion criterion) {
    const StrengthReductionBracket b = search.bracket(criterion);
    char text[256];
    if (b.closed() && b.ordered)
      std::snprintf(text, sizeof text, "FS_SRM = %.4g +- %.3g (holds at %.4g, fails at %.4g)",
                    b.factor(), b.halfWidth(), b.holding, b.failing);
    else if (b.closed())
      std::snprintf(text, sizeof text, "not monotonic in F: holds at %.4g above a failure at %.4g",
                    b.holding, b.failing);
    else if (b.holding > 0)
      std::snprintf(text, sizeof text, "FS_SRM > %.4g (no trial failed)", b.holding);
    else if (b.failing < std::numeric_limits<Real>::infinity())
      std::snprintf(text, sizeof text, "FS_SRM < %.4g (no trial held)", b.failing);
    else
      std::snprintf(text, sizeof text, "no trial");
    return std::string(text);
  };
  // the search's bracket, then every single criterion's from the same trials ("either" is two
  // of them together)
  std::string brackets;
  for (const auto& word : kStrengthReductionCriterionWords)
    if (word.value != StrengthReductionCriterion::Either)
      brackets += std::string("; by ") + word.word + " " + describe(word.value);
  log("stage '" + stage.name + "': strength reduction, " + std::to_string(search.trials().size()) +
      " trials: " + describe(spec.criterion) + " by " +
      deckWord(kStrengthReductionCriterionWords, spec.criterion) + brackets + " (" +
      deck_.output.name + "_strength_reduction.csv, mechanism in " + deck_.output.name +
      "_strength_reduction_points.csv)");
  if (deck_.factor_of_safety.enabled && last_factor_of_safety_ > 0) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "stage '%s': limit equilibrium on the same state (last output): F = %.4g",
                  stage.name.c_str(), last_factor_of_safety_);
    log(line);
  }
}

}  // namespace argine

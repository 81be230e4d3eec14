#pragma once
/// @file Simulation.hpp
/// A run: the mesh, the material points and the output writers, and the loop over the
/// deck's stages. Each stage hands the points to its solver; the loop itself is the
/// ExaMPM five lines: choose dt, step, advance time, write when due, report progress.

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "argine/input/Deck.hpp"
#include "argine/mesh/Mesh.hpp"
#include "argine/output/GridFile.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/simulation/FactorOfSafetyMonitor.hpp"

namespace argine {

class ExplicitTwoPhaseSolver;
class RankDecomposition;
struct TimeStepChoice;
struct SeepageTotals;
class ResultsWriter;
class CsvWriter;
class ProgressReporter;
class ProbeWriter;
class RunGuards;
class RelaxationMonitor;
class RestMonitor;
class MaterialTable;
struct CheckpointState;

/// Options of `argine run` that are not part of the deck.
struct RunOptions {
  std::string output_directory = "results";  ///< where the Exodus and CSV files go
  /// no progress lines and no log of stage set-up; the stage and run summaries (steps,
  /// throughput, where the time went, where the results are) are printed all the same
  bool quiet = false;
  std::string restart;  ///< (P8) checkpoint file to continue from; "": none
};

/// What a finished run measured.
struct RunSummary {
  long long steps = 0;                  ///< time steps taken over all stages
  long long point_updates = 0;          ///< sum over steps of the number of material points
  double wall_seconds = 0;              ///< wall time of the stage loop (s)
  Real end_time = 0;                    ///< simulated time at the end (s)
  int output_steps = 0;                 ///< time steps written to the Exodus files
  int checkpoints = 0;                  ///< (P8) checkpoints written by this process
  double checkpoint_seconds = 0;        ///< (P8) wall time spent writing them (s)
  std::uintmax_t checkpoint_bytes = 0;  ///< (P8) size of the last one (bytes)
};

class Simulation {
 public:
  /// Loads the mesh, checks the deck against it and against what the solvers support, and
  /// seeds and initialises the material points. Throws InputError; writes nothing.
  Simulation(const Deck& deck, const RunOptions& options);
  ~Simulation();

  /// Runs every stage in order, writing results at each stage's output interval and at the
  /// end of each stage. Throws RunError when the run goes unstable (files keep the last
  /// good output).
  RunSummary run();

  const Mesh& mesh() const { return mesh_; }
  const MaterialPoints& points() const { return points_; }
  /// Path of the grid results file (valid after run() started).
  std::string gridPath() const;
  /// Path of the current points results file (valid after run() started).
  std::string pointsPath() const;
  /// What the run logged about initialisation and stages (material changes, relaxation),
  /// in order; also printed unless quiet.
  const std::vector<std::string>& stageLog() const { return stage_log_; }
  /// The materials as they are now (after the material changes of the stages run so far).
  const std::vector<MaterialSpec>& currentMaterials() const { return deck_.materials; }

 private:
  void runStage(const StageSpec& stage);
  /// implicit seepage (P5); `table_origin` (s): the time its tables count from (NaN: now)
  void runImplicitSeepageStage(const StageSpec& stage,
                               Real table_origin = std::numeric_limits<Real>::quiet_NaN());
  /// (P12) whether the explicit stage's slide has stopped at this output (Hand Back At
  /// Rest; all ranks); logs it.
  bool handsBackAtRest(const StageSpec& stage, RestMonitor& rest);
  /// (P12) the rest of `stage`, from now to `end` (s), on the implicit seepage path.
  void runRestOfStageImplicitly(const StageSpec& stage, Real end);
  void logTimeStep(const StageSpec& stage, const TimeStepChoice& choice) const;
  /// Adds the last step's kinetic and stored elastic energy (all ranks) to `relaxation`;
  /// true once relaxed.
  bool addRelaxationStep(RelaxationMonitor& relaxation, const MaterialTable& table);
  void writeOutput();
  void writeDiagnostics(const MaterialPoints& points);  ///< points: all (gathered) points
  // ---- hydraulic boundary fluxes (P3): <name>_boundary_flux.csv
  void openBoundaryFluxLog();
  /// The index of condition `name` in flux_names_ (flux_names_.size() when absent).
  std::size_t fluxColumn(const std::string& name) const;
  void accumulateBoundaryFluxes();
  void accumulateImplicitBoundaryFluxes(const std::vector<std::string>& names,
                                        const SeepageTotals& totals, std::vector<Real>& counted);
  void writeBoundaryFluxes();
  /// The points' liquid mass now (kg/m, all ranks): after an explicit step its diagnostics,
  /// after an implicit stage that stage's, before any step the initial mass.
  /// Logs the liquid stored since the run started and the part made inside the body.
  void logLiquidMadeInside(const StageSpec& stage);
  Real liquidMassNow() const;
  // issue P4: stage additions, probes
  void log(const std::string& line);
  void applyStageMaterialChanges(const StageSpec& stage);
  void writeInitialOutput();
  // issue P8: physical guards (SimulationGuards.cpp)
  void beginStageGuards(const StageSpec& stage);
  void checkGuards(const StageSpec& stage);
  void writeProbes();                              ///< gathers the points
  void writeProbes(const MaterialPoints& points);  ///< all (gathered) points

  Deck deck_;
  RunOptions options_;
  Mesh mesh_;
  MaterialPoints points_;
  // ---- several MPI ranks (doc/parallel.md "Output and the argine program"): the explicit
  // stages run distributed; rank 0 gathers the points by id and writes every file.
  std::unique_ptr<RankDecomposition> ranks_;  ///< null on one rank; outlives solver_
  bool points_replicated_ = false;
  bool reports_ = true;         ///< this rank prints the summaries (rank 0)
  long long total_points_ = 0;  ///< points over all ranks at the last output  ///< every rank holds
                                ///< all points (an implicit stage)
  bool distributed() const { return ranks_ != nullptr; }
  bool writes() const;                            ///< this rank writes the files (rank 0)
  MaterialPoints gatheredPoints() const;          ///< all points on rank 0 (collective)
  long long totalPoints() const;                  ///< points over all ranks (collective)
  std::vector<NodalField> gatheredNodalFields();  ///< complete nodal fields on rank 0
  std::unique_ptr<ExplicitTwoPhaseSolver> solver_;
  std::unique_ptr<ResultsWriter> results_;
  std::unique_ptr<CsvWriter> diagnostics_;
  std::unique_ptr<ProgressReporter> progress_;
  std::unique_ptr<CsvWriter> boundary_flux_;  ///< only when a stage has hydraulic conditions
  std::vector<std::string> flux_names_;       ///< hydraulic conditions of all stages
  std::vector<Real> flux_last_step_;          ///< m^3/m through each, last step
  std::vector<Real> flux_cumulative_;         ///< m^3/m through each since the start
  Real flux_all_nodes_cumulative_ = 0;        ///< net inflow through all nodes (m^3/m)
  Real flux_interior_nodes_cumulative_ = 0;   ///< of it at the nodes on no free side (m^3/m)
  Real initial_liquid_mass_ = 0;              ///< sum of the points' M_L at the start (kg/m)
  /// The points' liquid mass an implicit stage left (kg/m); < 0 once an explicit step has
  /// run since (the explicit diagnostics then hold it). See liquidMassNow().
  Real implicit_liquid_mass_ = -1;
  std::unique_ptr<ProbeWriter> probes_;  ///< (P4)
  std::vector<std::string> stage_log_;   ///< (P4)
  bool initial_output_written_ = false;  ///< (P4) t = 0 written after the first beginStage
  Real next_probe_time_ = 0;             ///< (P4)
  Real implicit_time_step_ = 0;          ///< the implicit path's last step, for its rows
  Real initial_time_step_ = 0;           ///< (P4) the first stage's first dt, for the t = 0 row
  RunSummary summary_;
  std::unique_ptr<RunGuards> guards_;  ///< (P8)
  /// (P11) The points outside their physical p_L range now (warns when any), of all points.
  int countUnphysicalPressures(const MaterialPoints& points);
  std::vector<Real> lowest_pressures_;  ///< (P11) lowest physical p_L per material (Pa)
  // ---- factor of safety (P13; SimulationFactorOfSafety.cpp)
  void openFactorOfSafetyLog();
  /// Bishop's factor of the critical circle of `points` (all points on rank 0), written to
  /// its CSV; known on every rank afterwards. No-op without the deck's `Factor Of Safety`.
  void evaluateFactorOfSafety(const MaterialPoints& points);
  /// Whether `stage` hands over now (its threshold above the last factor); logs it.
  bool handsOverOnFactorOfSafety(const StageSpec& stage);
  /// Logs the stage's lowest factor of safety (if it evaluated any).
  void logLowestFactorOfSafety(const StageSpec& stage);
  /// (P13 item 3; SimulationStrengthReduction.cpp) a stage with `Strength Reduction`
  void runStrengthReductionStage(const StageSpec& stage);
  std::unique_ptr<CsvWriter> strength_reduction_trials_;     ///< rank 0, from the first such stage
  std::unique_ptr<CsvWriter> strength_reduction_points_;     ///< its mechanisms
  std::unique_ptr<FactorOfSafetyMonitor> factor_of_safety_;  ///< rank 0, when enabled
  Real last_factor_of_safety_ = 0;                           ///< NaN: none admissible
  Real stage_lowest_factor_ = 0;                             ///< this stage's lowest (0: none yet)
  Real stage_lowest_factor_time_ = 0;                        ///< (s) when

  // ---- checkpoint / restart (P8; SimulationCheckpoint.cpp, doc/checkpoints.md)
  void readRestartCheckpoint();  ///< options_.restart -> resume_ (InputError naming the file)
  void restoreFromCheckpoint();  ///< after the writers reopened: materials, points, solver
  /// true once, in the checkpoint's stage
  bool resumeStage(RelaxationMonitor* relaxation, RestMonitor* rest);
  void checkpointIfDue(bool mid_stage);  ///< after a step / at a stage's end
  void writeCheckpointIfDue(bool mid_stage);
  void writeCheckpointNow(bool mid_stage);
  /// The bookkeeping after a checkpoint (`bytes` written; 0 on ranks that do not write).
  void finishCheckpoint(double begin, std::uintmax_t bytes);
  std::unique_ptr<CheckpointState> resume_;  ///< the checkpoint a restart continues from
  bool resume_pending_ = false;              ///< its stage has not yet been resumed
  std::size_t stage_index_ = 0;              ///< the stage running
  Real stage_start_ = 0;                     ///< (s) its start time
  Real next_output_ = 0;                     ///< (s) its next output time
  RelaxationMonitor* relaxation_ = nullptr;  ///< its relaxation monitor, if any
  RestMonitor* rest_ = nullptr;              ///< (P12) its Hand Back At Rest monitor, if any
  std::uint64_t deck_hash_ = 0;
  double last_checkpoint_wall_ = 0;     ///< (s, steady clock) run start or last checkpoint
  long long checkpoint_step_mark_ = 0;  ///< steps / Every Steps at the last checkpoint
};

/// Throws InputError for anything the deck asks for that this build cannot run yet: a
/// solid model without a stress update, a stage solver not implemented. `argine check`
/// calls it too, so such a deck is rejected before a run, never half-way through.
void checkDeckSupported(const Deck& deck);

}  // namespace argine

#pragma once
/// @file Checkpoint.hpp
/// What a checkpoint of a run holds (doc/checkpoints.md), besides the header of
/// checkpoint/CheckpointFile.hpp: everything the Simulation and the explicit solver carry
/// from one step to the next that does not follow from the deck, so that
/// `argine run DECK --restart FILE` continues bit for bit as if never stopped. One rank only.

#include <cstdint>
#include <string>
#include <vector>

#include "argine/output/ResultsWriter.hpp"
#include "argine/physics/ExplicitTwoPhaseSolver.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/simulation/RelaxationMonitor.hpp"

namespace argine {

struct CheckpointState {
  // ---- where the run stands
  std::int64_t stage_index = 0;  ///< the stage to continue
  bool mid_stage = false;        ///< inside that stage (else: before its start)
  Real stage_start = 0;          ///< (s) the stage's start time, when mid_stage
  Real next_output = 0;          ///< (s) the stage's next output time, when mid_stage
  std::int64_t steps = 0;        ///< time steps over all stages
  std::int64_t point_updates = 0;
  Real next_probe_time = 0;  ///< (s)
  bool initial_output_written = false;
  Real initial_time_step = 0;                  ///< (s) for the t = 0 diagnostics row
  Real initial_liquid_mass = 0;                ///< (kg/m) reference of the storage change
  std::vector<Real> flux_last_step;            ///< (m^3/m) per hydraulic condition
  std::vector<Real> flux_cumulative;           ///< (m^3/m) per hydraulic condition
  Real flux_all_nodes_cumulative = 0;          ///< (m^3/m)
  Real flux_interior_nodes_cumulative = 0;     ///< (m^3/m) of it on no free side
  std::vector<std::string> stage_log;          ///< what the run logged so far
  ExplicitTwoPhaseSolver::ResumeState solver;  ///< time, step diagnostics, dt controller
  bool has_relaxation = false;                 ///< the stage watches for rest (mid_stage)
  RelaxationMonitor::State relaxation;
  /// (P12) RestMonitor::windowStart of the stage's Hand Back At Rest (the points carry their
  /// rest_reference)
  Real rest_window_start = 0;
  // ---- where the output files stand (later steps/rows of a killed run are dropped)
  ResultsResume results;
  std::uint64_t diagnostics_bytes = 0;
  std::uint64_t boundary_flux_bytes = 0;  ///< 0: no boundary flux file
  std::vector<std::uint64_t> probe_bytes;
  std::vector<std::uint64_t> factor_of_safety_bytes;  ///< (P13) its CSV files; empty: none
  /// (P13) the strength-reduction trials and mechanism CSVs; empty: no such stage ran yet
  std::vector<std::uint64_t> strength_reduction_bytes;
  // ---- consistency with the deck
  std::int64_t mesh_nodes = 0;
  std::int64_t mesh_elements = 0;
  // ---- a run decomposed over MPI ranks (P7): `solver` is rank 0's state
  std::vector<ExplicitTwoPhaseSolver::ResumeState> other_rank_solvers;  ///< ranks 1, 2, ...
  std::vector<std::int64_t> rank_point_counts;  ///< points of each rank; one entry: one rank
  // ---- the material points, every field: rank 0's in their current order, then rank 1's...
  MaterialPoints points;
};

/// `<directory>/<stem>.checkpoint`.
std::string checkpointPath(const std::string& directory, const std::string& stem);

/// Writes `state` atomically (writeCheckpointFile); returns the file size.
std::uintmax_t writeCheckpoint(const std::string& path, std::uint64_t deck_hash,
                               const CheckpointState& state);

/// Reads a checkpoint made for the deck of hash `deck_hash`. The points are read into
/// `state.points`, which must be allocated for the deck's number of points. InputError naming
/// the file for anything wrong.
void readCheckpoint(const std::string& path, std::uint64_t deck_hash, CheckpointState& state);

}  // namespace argine

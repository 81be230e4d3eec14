// The payload of a checkpoint (simulation/Checkpoint.hpp), field by field in a fixed order:
// changing the order or a field means a new kCheckpointFormatVersion (doc/checkpoints.md).
#include <filesystem>

#include "argine/checkpoint/CheckpointFile.hpp"
#include "argine/simulation/Checkpoint.hpp"

namespace argine {

namespace {

void putChoice(CheckpointWriter& out, const TimeStepChoice& c) {
  out.put<Real>(c.time_step);
  out.put<std::uint8_t>(c.automatic);
  out.put<Real>(c.critical_step);
  out.put<std::int32_t>(static_cast<std::int32_t>(c.governing));
  out.put<std::int32_t>(c.point);
  out.put<std::int32_t>(c.point_id);
  out.put<Real>(c.position[0]);
  out.put<Real>(c.position[1]);
}

TimeStepChoice getChoice(CheckpointReader& in) {
  TimeStepChoice c;
  c.time_step = in.get<Real>();
  c.automatic = in.get<std::uint8_t>() != 0;
  c.critical_step = in.get<Real>();
  c.governing = static_cast<CriterionKind>(in.get<std::int32_t>());
  c.point = in.get<std::int32_t>();
  c.point_id = in.get<std::int32_t>();
  c.position[0] = in.get<Real>();
  c.position[1] = in.get<Real>();
  return c;
}

void putSolver(CheckpointWriter& out, const ExplicitTwoPhaseSolver::ResumeState& s) {
  out.put<Real>(s.time);
  const StepDiagnostics& d = s.diagnostics;
  out.put<std::int64_t>(d.step);
  out.put<Real>(d.time);
  out.put<Real>(d.time_step);
  out.put<Real>(d.kinetic_energy_solid);
  out.put<Real>(d.kinetic_energy_liquid);
  out.put<Real>(d.liquid_mass);
  out.put<std::int32_t>(d.lost_points);
  out.put<std::int32_t>(d.active_nodes);
  putChoice(out, d.time_step_choice);
  out.put<Real>(s.stage_energies.potential);
  out.put<Real>(s.stage_energies.stored);
  out.put<Real>(s.stage_energies.kinetic);
  out.put<Real>(s.load_bound);
  out.put<Real>(s.inflow_energy);
  out.put<std::uint8_t>(s.stage_started);
  out.put<std::uint8_t>(s.time_step.stale);
  out.put<std::int32_t>(s.time_step.calls_since_update);
  putChoice(out, s.time_step.choice);
}

ExplicitTwoPhaseSolver::ResumeState getSolver(CheckpointReader& in) {
  ExplicitTwoPhaseSolver::ResumeState s;
  s.time = in.get<Real>();
  StepDiagnostics& d = s.diagnostics;
  d.step = static_cast<long>(in.get<std::int64_t>());
  d.time = in.get<Real>();
  d.time_step = in.get<Real>();
  d.kinetic_energy_solid = in.get<Real>();
  d.kinetic_energy_liquid = in.get<Real>();
  d.liquid_mass = in.get<Real>();
  d.lost_points = in.get<std::int32_t>();
  d.active_nodes = in.get<std::int32_t>();
  d.time_step_choice = getChoice(in);
  s.stage_energies.potential = in.get<Real>();
  s.stage_energies.stored = in.get<Real>();
  s.stage_energies.kinetic = in.get<Real>();
  s.load_bound = in.get<Real>();
  s.inflow_energy = in.get<Real>();
  s.stage_started = in.get<std::uint8_t>() != 0;
  s.time_step.stale = in.get<std::uint8_t>() != 0;
  s.time_step.calls_since_update = in.get<std::int32_t>();
  s.time_step.choice = getChoice(in);
  return s;
}

}  // namespace

std::string checkpointPath(const std::string& directory, const std::string& stem) {
  return (std::filesystem::path(directory) / (stem + ".checkpoint")).string();
}

std::uintmax_t writeCheckpoint(const std::string& path, std::uint64_t deck_hash,
                               const CheckpointState& s) {
  CheckpointWriter out;
  out.put<std::int64_t>(s.stage_index);
  out.put<std::uint8_t>(s.mid_stage);
  out.put<Real>(s.stage_start);
  out.put<Real>(s.next_output);
  out.put<std::int64_t>(s.steps);
  out.put<std::int64_t>(s.point_updates);
  out.put<Real>(s.next_probe_time);
  out.put<std::uint8_t>(s.initial_output_written);
  out.put<Real>(s.initial_time_step);
  out.put<Real>(s.initial_liquid_mass);
  out.putVector(s.flux_last_step);
  out.putVector(s.flux_cumulative);
  out.put<Real>(s.flux_all_nodes_cumulative);
  out.put<Real>(s.flux_interior_nodes_cumulative);
  out.put<std::uint64_t>(s.stage_log.size());
  for (const auto& line : s.stage_log) out.putString(line);
  putSolver(out, s.solver);
  out.put<std::uint64_t>(s.other_rank_solvers.size());
  for (const auto& solver : s.other_rank_solvers) putSolver(out, solver);
  out.putVector(s.rank_point_counts);
  out.put<std::uint8_t>(s.has_relaxation);
  out.put<Real>(s.relaxation.start);
  out.put<Real>(s.relaxation.peak);
  out.put<Real>(s.relaxation.stored);
  out.put<std::int64_t>(s.relaxation.steps);
  out.put<std::uint8_t>(s.relaxation.relaxed);
  out.put<std::uint64_t>(s.relaxation.window.size());
  for (const auto& [time, energy] : s.relaxation.window) {
    out.put<Real>(time);
    out.put<Real>(energy);
  }
  out.put<Real>(s.rest_window_start);  // (P12, format 8)
  out.put<std::int32_t>(s.results.grid_steps);
  out.put<std::int32_t>(s.results.points_file_count);
  out.put<std::int32_t>(s.results.points_steps);
  out.put<std::uint64_t>(s.diagnostics_bytes);
  out.put<std::uint64_t>(s.boundary_flux_bytes);
  out.putVector(s.probe_bytes);
  out.putVector(s.factor_of_safety_bytes);
  out.putVector(s.strength_reduction_bytes);
  out.put<std::int64_t>(s.mesh_nodes);
  out.put<std::int64_t>(s.mesh_elements);
  putPoints(out, s.points);
  return writeCheckpointFile(path, deck_hash, out.payload());
}

void readCheckpoint(const std::string& path, std::uint64_t deck_hash, CheckpointState& s) {
  CheckpointReader in(readCheckpointFile(path, deck_hash), path);
  s.stage_index = in.get<std::int64_t>();
  s.mid_stage = in.get<std::uint8_t>() != 0;
  s.stage_start = in.get<Real>();
  s.next_output = in.get<Real>();
  s.steps = in.get<std::int64_t>();
  s.point_updates = in.get<std::int64_t>();
  s.next_probe_time = in.get<Real>();
  s.initial_output_written = in.get<std::uint8_t>() != 0;
  s.initial_time_step = in.get<Real>();
  s.initial_liquid_mass = in.get<Real>();
  s.flux_last_step = in.getVector<Real>();
  s.flux_cumulative = in.getVector<Real>();
  s.flux_all_nodes_cumulative = in.get<Real>();
  s.flux_interior_nodes_cumulative = in.get<Real>();
  const auto lines = in.get<std::uint64_t>();
  s.stage_log.clear();
  for (std::uint64_t k = 0; k < lines; ++k) s.stage_log.push_back(in.getString());
  s.solver = getSolver(in);
  const auto other_ranks = in.get<std::uint64_t>();
  s.other_rank_solvers.clear();
  for (std::uint64_t r = 0; r < other_ranks; ++r) s.other_rank_solvers.push_back(getSolver(in));
  s.rank_point_counts = in.getVector<std::int64_t>();
  if (s.rank_point_counts.size() != other_ranks + 1)
    in.fail("point counts of " + std::to_string(s.rank_point_counts.size()) + " ranks for " +
            std::to_string(other_ranks + 1) + " ranks' solver states");
  s.has_relaxation = in.get<std::uint8_t>() != 0;
  s.relaxation.start = in.get<Real>();
  s.relaxation.peak = in.get<Real>();
  s.relaxation.stored = in.get<Real>();
  s.relaxation.steps = static_cast<long>(in.get<std::int64_t>());
  s.relaxation.relaxed = in.get<std::uint8_t>() != 0;
  const auto window = in.get<std::uint64_t>();
  s.relaxation.window.clear();
  for (std::uint64_t k = 0; k < window; ++k) {
    const Real time = in.get<Real>();
    s.relaxation.window.emplace_back(time, in.get<Real>());
  }
  s.rest_window_start = in.get<Real>();  // (P12, format 8)
  s.results.grid_steps = in.get<std::int32_t>();
  s.results.points_file_count = in.get<std::int32_t>();
  s.results.points_steps = in.get<std::int32_t>();
  s.diagnostics_bytes = in.get<std::uint64_t>();
  s.boundary_flux_bytes = in.get<std::uint64_t>();
  s.probe_bytes = in.getVector<std::uint64_t>();
  s.factor_of_safety_bytes = in.getVector<std::uint64_t>();
  s.strength_reduction_bytes = in.getVector<std::uint64_t>();
  s.mesh_nodes = in.get<std::int64_t>();
  s.mesh_elements = in.get<std::int64_t>();
  getPoints(in, s.points);
  in.expectEnd();
}

}  // namespace argine

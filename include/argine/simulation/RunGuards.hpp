#pragma once
/// @file RunGuards.hpp
/// Physical guards of a run (issue P8), checked after every explicit step, so a run never
/// gives a silently wrong answer:
/// - the liquid mass balance of a stage with hydraulic conditions: |storage change - net
///   inflow through the nodes| / initial liquid volume above Guards/Mass Balance Bound warns
///   once (the two agree to round-off when the flux accounting is right, doc/verification.md
///   V6);
/// - the kinetic energy above Guards/Kinetic Energy Bound x the stage's energy scale warns
///   once (the solver stops the run at 1 x the scale, an upper bound of what a stable stage
///   can turn into motion: StabilityCheck.hpp, energyScale); the stage's largest ratio of the
///   two is logged when it ends (the margin of the run);
/// - material points that left the background mesh (element -1: they carry no shape
///   functions, so they no longer take part) stop the run with a RunError naming time, step,
///   point id and position, or, with `Points Leaving Mesh: remove`, are taken out of the
///   computation (velocities zeroed so they add no kinetic energy; they stay, frozen, in the
///   output) and counted in the log.
/// Warnings come back as text; the caller prints and logs them.

#include <string>

#include "argine/input/Deck.hpp"
#include "argine/points/MaterialPoints.hpp"

namespace argine {

/// Where the run is, for messages.
struct GuardPlace {
  Real time = 0;      ///< s
  long step = 0;      ///< steps since the solver was made
  std::string stage;  ///< stage name
};

class RunGuards {
 public:
  explicit RunGuards(const GuardsSpec& spec) : spec_(spec) {}

  /// Starts a stage's mass balance from its current liquid storage and cumulative inflow
  /// (m^3/m); `initial_volume` (m^3/m) is the reference of the relative error.
  void beginStage(Real storage, Real inflow, Real initial_volume);

  /// The stage's balance error |(storage - storage_0) - (inflow - inflow_0)| / initial
  /// volume. Returns a warning (value, bound, time, step) the first time in the run it
  /// exceeds the bound, "" otherwise.
  std::string checkMassBalance(Real storage, Real inflow, const GuardPlace& place);

  /// Returns a warning the first time in the run `kinetic` > bound x `scale` (J/m). Also
  /// keeps the stage's largest kinetic / scale (kineticEnergyPeak).
  std::string checkKineticEnergy(Real kinetic, Real scale, const GuardPlace& place);

  /// "stage '<name>': largest kinetic energy <E> J/m at t = <t> s (step <n>) = <r> x the
  /// energy scale <S> J/m ..." for the stage's largest ratio since beginStage, or "" when no
  /// step was checked. Since a restart only, on a restarted run.
  std::string kineticEnergyPeak(const std::string& stage) const;

  /// Points outside the mesh (element < 0). None new: "". Stop: throws RunError naming the
  /// count, time, step, stage and the first point's id and position. Remove: zeroes their
  /// velocities and returns the log line with the new and total counts.
  std::string handleLeavingPoints(MaterialPoints& points, const GuardPlace& place);

  int removedPoints() const { return removed_; }

 private:
  GuardsSpec spec_;
  Real storage_0_ = 0, inflow_0_ = 0, initial_volume_ = 0;
  bool mass_warned_ = false;
  bool energy_warned_ = false;
  Real peak_ratio_ = -1, peak_kinetic_ = 0, peak_scale_ = 0;  ///< the stage's largest ratio
  GuardPlace peak_place_;
  int removed_ = 0;
};

}  // namespace argine

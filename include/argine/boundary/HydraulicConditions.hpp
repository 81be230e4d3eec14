#pragma once
/// @file HydraulicConditions.hpp
/// The hydraulic conditions of a stage on the MOVING free boundary (thesis Sec. 4.1-4.3):
/// total head, pressure series, infiltration/evaporation and potential seepage face. Each
/// applies on a zone of the current free boundary (FreeBoundary, tested at side midpoints)
/// or on a mesh side set (sides of active elements only). Every step, plan() turns them
/// into device lists for the solver's kernels:
///  - nodal loads: the pressure integrated along the condition's sides (HydraulicAlgebra),
///    added to the liquid (4.41) external force, and its free-water part (p^ > 0) to the
///    mixture (4.42) external force, so the water weight acts on the slope; a suction above
///    the level loads the liquid only (mixtureLoadPressure: sigma n = 0 against air);
///  - nodal corrections: infiltration (vertical rain, q_out = -q n_y) and seepage-face nodes,
///  corrected
///    by the predictor-corrector (4.53-4.59) in the solver;
///  - ownership: each node of a condition's sides belongs to the first condition (deck
///    order) that claims it, for the liquid volume each condition lets through.
///  - the atmosphere (`Surfaces Without Condition: atmosphere`, the default): every node of a
///    free side that no condition covers, and that no condition owns, is corrected as a
///    seepage-face node, with the normal of those sides: it drains at p_L >= 0 and lets
///    nothing in at suction. Without it such a surface keeps the natural p_L = 0 of 4.36
///    and draws water in from the air wherever the soil below is at suction. Its nodes are
///    owned by no condition (their flux is in the all-nodes total) and are not among
///    conditionedNodes().
/// Host loops over the boundary sides only (boundary-sized), a few small copies per step.

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "argine/boundary/BoundaryConditions.hpp"
#include "argine/boundary/FreeBoundary.hpp"
#include "argine/boundary/HydraulicAlgebra.hpp"
#include "argine/boundary/LinearInX.hpp"
#include "argine/boundary/NodeTable.hpp"
#include "argine/boundary/TimeSeries.hpp"
#include "argine/boundary/Zone.hpp"
#include "argine/input/Deck.hpp"

namespace argine {

/// One resolved hydraulic condition.
struct HydraulicCondition {
  std::string name;
  BoundaryKind kind = BoundaryKind::TotalHead;
  bool on_zone = true;                       ///< zone on the free boundary, else side_set
  Zone zone;                                 ///< where, when on_zone
  std::vector<std::array<int, 2>> side_set;  ///< (element, local side), when !on_zone
  TimeSeries series;                         ///< head (m), pressure (Pa) or infiltration flux (m/s)
  LinearInX linear_in_x;                     ///< pressure series: `series` at x0, linear to x1
  AboveLevel above = AboveLevel::ConstantPressure;
  Real pressure_above = 0;     ///< (Pa)
  bool ponding = false;        ///< infiltration
  Real liquid_density = 1000;  ///< head -> pressure (kg/m^3)
};

/// Resolves the time series of a deck spec (reads a CSV file; InputError(spec.where)) on the
/// simulation clock: a table or file whose times count from the stage's start
/// (TimeOrigin::StageStart) is shifted by `stage_start` (s), the simulation time at which
/// the stage holding the condition begins.
TimeSeries makeTimeSeries(const TimeSeriesSpec& spec, Real stage_start);

/// The x-dependence of a pressure series (inactive unless `Linear Between x (m)` is given),
/// its end series on the simulation clock as makeTimeSeries.
LinearInX makeLinearInX(const HydraulicSpec& spec, Real stage_start);

/// Device lists of one step's nodal corrections (see HydraulicAlgebra: FluxCorrection).
struct FluxCorrectionList {
  Kokkos::View<int*, MemSpace> node;    ///< mesh node
  Kokkos::View<int*, MemSpace> kind;    ///< FluxCorrection as int
  Kokkos::View<Real*, MemSpace> q_out;  ///< prescribed outward relative flux w^ . n (m/s)
  /// Outward unit normal of the correcting condition's own sides at the node: the sum of
  /// n L / 2 over them, normalised (HydraulicBoundaryStep.hpp says why not 4.51 here).
  Kokkos::View<Real* [kDim], MemSpace> normal;
  /// |sum of n L / 2| over the same sides (m): the node's share of the face, which passes
  /// q_out times it (fluxWeightCorrection).
  Kokkos::View<Real*, MemSpace> face_length;
  Kokkos::View<int*, MemSpace> applied;  ///< 1 where the correction applied this step
  int count() const { return static_cast<int>(node.extent(0)); }
};

/// Which condition each node of the conditions' sides belongs to.
struct NodeOwnership {
  Kokkos::View<int*, MemSpace> node;   ///< mesh node
  Kokkos::View<int*, MemSpace> owner;  ///< index into conditions()
  int count() const { return static_cast<int>(node.extent(0)); }
};

class HydraulicConditions {
 public:
  HydraulicConditions() = default;
  /// The hydraulic conditions of `stage` (others are ignored); InputError with where =
  /// "Stages/<stage>/Boundary Conditions/<name>" for a missing side set, or the time-series
  /// key for an unreadable file. `stage_start` (s): the simulation time at which the stage
  /// begins, the origin of its tables' times unless a condition says `simulation start`.
  HydraulicConditions(const Mesh& mesh, const StageSpec& stage, Real stage_start = 0);

  /// Nothing to plan: no condition, and no atmosphere on the other free sides.
  bool empty() const { return conditions_.empty() && !atmosphere_; }
  /// Whether the free sides under no condition get the atmosphere's rule (see above).
  bool atmosphere() const { return atmosphere_; }
  /// Switches the atmosphere off (a model without liquid, or a stage holding p_L).
  void dropAtmosphere() { atmosphere_ = false; }
  /// What the stage's other conditions already say about the liquid at each mesh node
  /// (LiquidRuleBits, or'ed; empty: nothing). The atmosphere leaves out
  ///  - the free sides sealed by impermeable conditions (both end nodes locked along the
  ///    side's normal: a sealed base, a symmetry axis, a membrane): they pass no liquid to
  ///    begin with, and a correction confined to the one unlocked direction, nearly
  ///    perpendicular to the flux weight there, would have to be enormous to change the
  ///    node's flux (the default scene went unstable in 3 steps with the atmosphere on its
  ///    sealed base);
  ///  - the nodes of a prescribed liquid pressure (`liquid pressure`, Sec. 5.4), and the
  ///    sides between two of them: the deck gives their p_L, in- or outflow as it comes.
  enum LiquidRuleBits : unsigned char {
    kLockedX = 1,            ///< the liquid's relative velocity locked along x
    kLockedY = 2,            ///< ... along y
    kPressurePrescribed = 4  ///< a `liquid pressure` condition's node
  };
  void setOtherLiquidRules(std::vector<unsigned char> rules) { rules_ = std::move(rules); }
  /// Whether `rules` (LiquidRuleBits per mesh node; empty: none) seal the free side: both
  /// its end nodes locked along every direction its normal has a component in.
  static bool sealsSide(const std::vector<unsigned char>& rules, const FreeSide& side);
  const std::vector<HydraulicCondition>& conditions() const { return conditions_; }

  /// Builds this step's loads, corrections and ownership from the current free boundary at
  /// `time` (s); `gravity` (m/s^2) converts heads to pressures.
  void plan(Real time, Real gravity, const FreeBoundary& boundary);

  const NodalLoads& loads() const { return loads_; }
  /// `Hydraulic Loads: through the soil` (StageSpec::hydraulic_heads_through_soil): whether
  /// the total head loads the soil as a field over its points, not through loads().
  bool headsThroughSoil() const { return heads_through_soil_; }
  /// ... the index of that condition, its loads as the free sides would carry them (not
  /// applied: for the energy scale's load bound and the check of the sides it does not
  /// cover), and its pressure field at the last plan's time (`gravity` in m/s^2).
  std::size_t throughSoilHead() const { return through_soil_head_; }
  const NodalLoads& headLoads() const { return head_loads_; }
  HeadPressureField headFieldThroughSoil(Real gravity) const;
  const FluxCorrectionList& corrections() const { return corrections_; }
  const NodeOwnership& ownership() const { return ownership_; }
  /// The nodes the conditions load or correct, the atmosphere's excepted (the strain kernel's
  /// exchange of a lone point: TwoPhaseTransfer.hpp).
  Kokkos::View<const int*, MemSpace> conditionedNodes() const { return conditioned_nodes_; }
  /// The sides each condition used in the last plan (host copies, for tests and plots).
  const std::vector<std::vector<FreeSide>>& sidesUsed() const { return sides_used_; }
  /// The value of each condition's time series at the last plan's time (a pressure linear
  /// in x: the value at x0).
  const std::vector<Real>& currentValues() const { return current_values_; }
  /// The largest value each condition prescribes anywhere at the last plan's time (a pressure
  /// linear in x: the larger of its two ends).
  Real largestCurrentValue(std::size_t condition) const;
  /// Whether every condition's values at `time` are those of the last plan (then the plan,
  /// for an unchanged free boundary and gravity, is the same plan).
  bool valuesUnchangedAt(Real time) const;

 private:
  /// The free sides `condition` applies on, into `sides` (cleared first).
  void sidesOf(const HydraulicCondition& condition, const FreeBoundary& boundary,
               std::vector<FreeSide>& sides) const;

  /// plan()'s host tables and lists, kept between steps: once they have grown to the
  /// boundary's size a step allocates nothing on the host.
  struct PlanScratch {
    struct Claim {
      int kind = 0;
      Real rain = 0;  ///< vertical inflow q (m/s), 0 for a seepage face
      int condition = 0;
    };
    /// node -> force on the liquid (full p^), then on the mixture (free water only: p^ > 0)
    NodeTable<std::array<Real, 2 * kDim>> forces;
    NodeTable<std::array<Real, 2 * kDim>> head_forces;  ///< through the soil: apart
    NodeTable<Claim> corrections;                       ///< node -> the first claim
    NodeTable<int> owner;                               ///< node -> condition
    /// per condition (the atmosphere last): node -> sum of n L / 2 of its sides there
    std::vector<NodeTable<std::array<Real, kDim>>> face;
    std::vector<std::pair<int, int>> covered;  ///< (element, side) of the conditions' sides
    std::vector<int> conditioned, node, kind, owned, owners;
    std::vector<Real> q_out, normal, length;
  };

  std::vector<HydraulicCondition> conditions_;
  bool atmosphere_ = false;
  bool heads_through_soil_ = false;
  std::size_t through_soil_head_ = 0;
  NodalLoads head_loads_;             ///< through the soil: the head's side loads, not applied
  std::vector<unsigned char> rules_;  ///< LiquidRuleBits per mesh node; empty: none
  Kokkos::View<int*, MemSpace> conditioned_nodes_;  ///< corrected by a condition, or loaded
  NodalLoads loads_;
  FluxCorrectionList corrections_;
  NodeOwnership ownership_;
  std::vector<std::vector<FreeSide>> sides_used_;
  std::vector<Real> current_values_;
  std::vector<Real> current_end_values_;  ///< at x1 (pressure linear in x), else as above
  PlanScratch scratch_;
};

}  // namespace argine

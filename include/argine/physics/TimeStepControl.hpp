#pragma once
/// @file TimeStepControl.hpp
/// The time step of the explicit solver (thesis Sec. 7): automatic = safety factor times the
/// minimum over material points of the stage's selected critical-step criteria
/// (timestep/Criteria.hpp), recomputed every `update_interval` steps, with the criterion and
/// the point that govern it; or a fixed step.
///
/// Dry points have no liquid, so every liquid criterion is meaningless there: a dry point is
/// held to the dry CFL criterion (4.62) alone, whichever criteria the stage selected.

#include <string>
#include <vector>

#include "argine/core/Types.hpp"
#include "argine/timestep/CriterionKind.hpp"

namespace argine {

class MaterialTable;

/// Columns of TimeStepControl's per-point scratch: the criteria's inputs that are not point
/// fields (the element's size, the material's parameters, dS_L/ds), and which criteria hold
/// the point (none outside the mesh, the dry CFL criterion at a dry point, the stage's at
/// the others).
enum CriterionGathered : int {
  kGatheredElementSize = 0,
  kGatheredSolidDensity,
  kGatheredBulkModulus,
  kGatheredConstrainedModulus,
  kGatheredSaturationSlope,
  kGatheredHeldTo,
  kCriterionGathered
};
struct MaterialPoints;
struct Mesh;
struct TimeStepSpec;

/// The step chosen and why.
struct TimeStepChoice {
  Real time_step = 0;      ///< dt to use (s)
  bool automatic = false;  ///< from the criteria (true) or fixed (false)
  Real critical_step = 0;  ///< minimum critical step over points and criteria (s); automatic only
  CriterionKind governing = CriterionKind::CflDry;  ///< the criterion giving the minimum
  int point = -1;                                   ///< index of the governing point
  int point_id = -1;                                ///< its permanent id
  Real position[kDim] = {0, 0};                     ///< its position (m)
};

/// The index of the point with permanent id `id` (-1 when none of `points` has it): a
/// choice's point after the points were permuted or moved to another rank.
int pointIndexOfId(const MaterialPoints& points, int id);

class TimeStepControl {
 public:
  TimeStepControl() = default;
  /// Caches the characteristic size of every element of `mesh`.
  explicit TimeStepControl(const Mesh& mesh);

  /// Takes the stage's settings; the next call to next() recomputes. Throws InputError
  /// ("Stages/<stage>/Time Step/...") for a non-positive fixed step or safety factor, or an
  /// automatic step without criteria.
  /// `implicit_drag`: the stage solves the drag implicitly (CriterionInput::implicit_drag).
  void configure(const TimeStepSpec& spec, Real mass_scaling, const std::string& stage,
                 bool implicit_drag = false);

  /// The step to take now: recomputed on the first call after configure() and then every
  /// update_interval calls. Throws RunError when no criterion limits the step, or when the
  /// minimum critical step is zero (naming the criterion and the point).
  const TimeStepChoice& next(const MaterialPoints& points, const MaterialTable& table);

  /// next() on one of several ranks that holds no points: no step to offer (time_step and
  /// critical_step infinite), but the calls are counted as next() counts them, so that every
  /// rank evaluates at the same calls (and the minimum over the ranks is the one-rank step).
  const TimeStepChoice& nextWithoutPoints();

  /// The minimum critical step over the points and selected criteria (no safety factor),
  /// with the governing criterion and point, evaluated now.
  TimeStepChoice evaluate(const MaterialPoints& points, const MaterialTable& table) const;

  /// The next call to next() evaluates the criteria again, whatever the update interval
  /// (e.g. the materials changed: a cached step may no longer be stable).
  void markStale() { stale_ = true; }

  /// Points were permuted (sorted): the last choice's point index follows its id.
  void pointsReordered(const MaterialPoints& points);

  /// The last choice.
  const TimeStepChoice& last() const { return choice_; }

  /// What next() carries from one call to the next (checkpoints, simulation/Checkpoint.hpp):
  /// with update_interval > 1 the cached choice is reused, so a restart must restore it.
  struct State {
    bool stale = true;
    int calls_since_update = 0;
    TimeStepChoice choice;
  };
  State state() const { return State{stale_, calls_since_update_, choice_}; }
  /// Restores state() after configure() with the same stage settings.
  void restore(const State& state) {
    stale_ = state.stale;
    calls_since_update_ = state.calls_since_update;
    choice_ = state.choice;
  }

 private:
  /// The fixed step, or the cached choice, replaced by evaluate() when the update interval
  /// is up (next() and nextWithoutPoints() differ only in what they evaluate).
  template <class Evaluate>
  const TimeStepChoice& advance(Evaluate&& evaluate);

  Kokkos::View<Real*, MemSpace> element_size_;
  std::vector<CriterionKind> criteria_;  ///< the stage's, in order (slots 0, 1, ...)
  // evaluate()'s scratch, per point: the gathered inputs, the smallest critical step of the
  // criteria evaluated so far.
  mutable Kokkos::View<Real* [kCriterionGathered], Kokkos::LayoutLeft, MemSpace> gathered_p_;
  mutable Kokkos::View<Real*, MemSpace> limit_p_;
  bool automatic_ = true;
  Real fixed_step_ = 0;
  Real safety_factor_ = 0.5;
  Real mass_scaling_ = 1;
  bool implicit_drag_ = false;
  int update_interval_ = 1;
  int calls_since_update_ = 0;
  bool stale_ = true;
  TimeStepChoice choice_;
};

}  // namespace argine

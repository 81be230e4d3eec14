#pragma once
/// @file RelaxationMonitor.hpp
/// When a quasi-static stage has come to rest (thesis Ch. 4 Sec. 5.1: the K0 procedure is
/// followed by quasi-static steps until the system is balanced). The measure is the
/// KINETIC ENERGY RATIO
///     R = max(E_k over the last W seconds) / E_el,
/// E_k the kinetic energy of solid and liquid, E_el the stored elastic energy
/// (physics/StabilityCheck.hpp storedElasticEnergy) at the last step, and the stage is
/// relaxed when R <= tolerance once the stage has run for at least W. The stored energy, not the
/// stage's peak kinetic energy, is the reference: a stage that starts near equilibrium (the K0
/// procedure's purpose) has a tiny, meaningless kinetic peak, and a steady seepage (the
/// liquid keeps moving, the skeleton creeps) would never fall below a fraction of it; the
/// stored energy says whether the motion is negligible for the stresses. The window W
/// (longer than an oscillation period) keeps a turning point of an undamped oscillation,
/// where E_k passes through ~0, from passing for rest.

#include <deque>
#include <utility>
#include <vector>

#include "argine/input/Deck.hpp"

namespace argine {

class RelaxationMonitor {
 public:
  /// `start`: the stage's start time (s).
  RelaxationMonitor(const RelaxationSpec& spec, Real start) : spec_(spec), start_(start) {}

  /// Records the kinetic and the stored elastic energy (J/m) at `time` (s), after a step;
  /// true once relaxed.
  bool add(Real time, Real kinetic_energy, Real stored_energy);

  /// R after the last add(): 1 before any step; 0 when nothing moves; infinity when moving
  /// with no stored energy.
  Real ratio() const;
  /// Largest kinetic energy of the stage so far (J/m), for the log.
  Real peak() const { return peak_; }
  /// Stored elastic energy of the last add() (J/m).
  Real stored() const { return stored_; }
  long steps() const { return steps_; }
  bool relaxed() const { return relaxed_; }

  /// Everything add() carries between calls, for checkpoints (simulation/Checkpoint.hpp).
  struct State {
    Real start = 0, peak = 0, stored = 0;
    long steps = 0;
    bool relaxed = false;
    std::vector<std::pair<Real, Real>> window;
  };
  State state() const {
    return State{start_, peak_, stored_, steps_, relaxed_, {window_.begin(), window_.end()}};
  }
  void restore(const State& state) {
    start_ = state.start;
    peak_ = state.peak;
    stored_ = state.stored;
    steps_ = state.steps;
    relaxed_ = state.relaxed;
    window_.assign(state.window.begin(), state.window.end());
  }

 private:
  RelaxationSpec spec_;
  Real start_ = 0;
  Real peak_ = 0;
  Real stored_ = 0;
  long steps_ = 0;
  bool relaxed_ = false;
  std::deque<std::pair<Real, Real>> window_;  ///< (time, E_k), decreasing E_k: window max first
};

}  // namespace argine

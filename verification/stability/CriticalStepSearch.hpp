#pragma once
/// @file CriticalStepSearch.hpp
/// The empirical critical time step of a column deck: runs with a FIXED step over a fixed
/// simulated time, each judged stable or unstable, and a bisection between a stable and an
/// unstable step.
///
/// A run is UNSTABLE when (checked in this order, the first that applies is the reason):
///  1. non-finite: the solver throws RunError for a non-finite or collapsed point;
///  2. energy bound: the solver throws RunError for a kinetic energy beyond 10x the stage's
///     energy scale (StabilityCheck.hpp) — both are what a production run would die of;
///  3. energy growth: the kinetic energy exceeds `energy_factor` times the largest kinetic
///     energy of the converged small-step reference over the same time. A growing mode is
///     caught long before it reaches the bound of 2 (which allows ~30x the physical velocity
///     here);
///  4. departure: at the end time the solid displacement or the liquid pressure departs from
///     the reference by more than `departure_tolerance` (RMS over the points, relative to the
///     RMS reference displacement, resp. to the top load): an unstable mode that saturates
///     (e.g. through the retention curve) without blowing up still gives a wrong answer.
///     The default tolerance 1.0 is loose on purpose: after the sudden load the column
///     oscillates undamped, and the phase error makes the late-time difference grow smoothly
///     with dt (tens of % near the limit) without any jump there (doc/stability.md).
/// The reference is the same column run at `reference_fraction` x the search's first guess
/// (halved until it is itself stable by tests 1-2).
///
/// The search: the reference step (stable by construction), then a LADDER up by factor `ladder`
/// until the first unstable run, then geometric bisection between the last stable and the first
/// unstable rung until unstable / stable <= 1 + relative_width. Stability is not always
/// monotone in dt here: the load can push points to wetter, stiffer states at some time in
/// the run, and whether that happens depends on dt. Climbing from
/// below finds the FIRST instability (to the ladder's resolution) rather than any stable
/// step above an unstable one, which plain doubling + bisection can report. The reported
/// critical step is the largest stable step of the final bracket.

#include <functional>
#include <string>
#include <vector>

#include "argine/core/Types.hpp"
#include "argine/input/Deck.hpp"

namespace argine::stability {

enum class Verdict { Stable, NonFinite, EnergyBound, EnergyGrowth, Departure };

/// "stable", "non-finite", "energy bound", "energy growth", "departure".
const char* verdictName(Verdict verdict);

/// One fixed-step run to a fixed time.
struct RunOutcome {
  Verdict verdict = Verdict::Stable;  ///< Departure is decided by the search, not the run
  long steps = 0;                     ///< steps taken (until the failure, if any)
  Real max_kinetic_energy = 0;        ///< over the steps taken (J per m)
  std::vector<double> displacement;   ///< u_y per point at the end (m), when stable
  std::vector<double> pressure;       ///< p_L per point at the end (Pa), when stable
  double wall_seconds = 0;            ///< setup and stepping
  std::string message;                ///< the RunError text, when there was one
  /// With tracking: the minimum over the run (sampled every kTrackInterval steps, the
  /// initial state included) of each criterion of kAllCriteria at the CURRENT point states,
  /// i.e. what an automatic step with that criterion would have been limited to (s).
  std::vector<Real> criteria_min;
  Real saturation_min = 1, saturation_max = 0;  ///< extremes of S_L over points and samples
};

/// Steps between two samples of the tracked criteria and S_L range.
inline constexpr int kTrackInterval = 5;

/// Runs `deck` (a fixed-step column deck) with step `dt` until `duration`, the last step
/// shortened to land on it. kinetic_energy_limit > 0: stop with EnergyGrowth beyond it.
/// track: fill criteria_min and the S_L range.
RunOutcome runFixedStep(const Deck& deck, Real dt, Real duration, Real kinetic_energy_limit,
                        bool track = false);

struct SearchSettings {
  Real steps_of_guess = 2000;      ///< simulated time = this x the first guess (s)
  Real reference_fraction = 0.5;   ///< reference step / first guess
  Real energy_factor = 10;         ///< test 3
  Real departure_tolerance = 1.0;  ///< test 4 (see the header comment)
  Real load = 1.0e5;               ///< top load (Pa), the pressure scale of test 4
  Real relative_width = 0.02;      ///< bracket unstable/stable - 1 at the end
  int reference_halvings = 6;      ///< RunError when no reference at guess x 0.5^(this+1)
  Real ladder = 1.15;              ///< ratio of two rungs of the ladder
  int max_rungs = 80;              ///< the ladder gives up beyond ladder^this x the start
};

struct SearchResult {
  Real stable_step = 0;                       ///< largest stable step found (s): the empirical dt_c
  Real unstable_step = 0;                     ///< smallest unstable step found (s)
  Verdict unstable_reason = Verdict::Stable;  ///< why the smallest unstable step failed
  Real departure_at_stable = 0;               ///< test 4's measure at stable_step
  Real duration = 0;                          ///< simulated time of every run (s)
  Real reference_step = 0;                    ///< (s)
  Real reference_kinetic_energy = 0;          ///< largest kinetic energy of the reference (J per m)
  int runs = 0;                               ///< runs made, the reference included
  long steps = 0;                             ///< steps made in all runs
  double wall_seconds = 0;                    ///< of all runs
  double seconds_per_step = 0;                ///< of the reference run (setup included, amortised)
  /// The reference run's criteria minima and S_L range (RunOutcome, tracked).
  std::vector<Real> criteria_min;
  Real saturation_min = 1, saturation_max = 0;
};

/// The departure measure of test 4 between a run and the reference.
Real departure(const RunOutcome& run, const RunOutcome& reference, Real load);

/// The empirical critical step of `make_deck(dt)`'s column, starting from `guess` (s).
SearchResult findCriticalStep(const std::function<Deck(Real)>& make_deck, Real guess,
                              const SearchSettings& settings);

}  // namespace argine::stability

#pragma once
/// @file StepProfile.hpp
/// Where the wall time of the explicit two-phase step goes: seconds accumulated per named
/// phase of ExplicitTwoPhaseSolver (the steps of Sec. 3.3 grouped as P2G, nodal solve, G2P,
/// constitutive update, relocation, sorting, ...), with the number of steps and
/// material-point updates, so a run can print its split and its points-per-second rate.
///
/// Cost: two clock reads per phase and step (tens of ns each on Linux), nothing else. On an
/// asynchronous backend (CUDA, HIP) the timer fences before reading the clock, so a phase is
/// charged for its own kernels; on Serial and OpenMP kernels return finished and the fence
/// is compiled out.

#include <array>
#include <chrono>
#include <string>
#include <type_traits>

#include "argine/core/Types.hpp"

namespace argine {

/// The timed phases of one explicit step, in the order the step runs them.
enum class StepPhase : int {
  TimeStep,      ///< critical-step criteria over the points (chooseTimeStep)
  P2G,           ///< grid clear, P2G of masses, momenta, forces, boundary loads, v^k
  NodalSolve,    ///< liquid and mixture momentum, acceleration and velocity conditions
  G2PVelocity,   ///< G2P of the accelerations to the point velocities + momentum remap
  G2PStrain,     ///< G2P of the nodal velocities to strain increments and flux terms
  Constitutive,  ///< point states: volume, porosity, p_L, sigma', S_L, k, position
  Relocation,    ///< point location, shape functions, active-node list
  Sort,          ///< periodic sort of the points by element
  Stability,     ///< diagnostics and the instability checks
};

/// Number of StepPhase values.
inline constexpr int kStepPhases = 9;

/// Accumulated seconds per phase of the explicit step.
struct StepProfile {
  std::array<double, kStepPhases> seconds{};  ///< wall seconds per phase, by StepPhase
  long steps = 0;                             ///< steps timed
  long point_updates = 0;                     ///< sum over the timed steps of the point count
  long sorts = 0;                             ///< point sorts done

  /// Short name of a phase, e.g. "P2G", "nodal solve".
  static const char* name(StepPhase phase);
  /// Seconds of one phase.
  double of(StepPhase phase) const { return seconds[static_cast<int>(phase)]; }
  /// Seconds of all phases.
  double total() const;
  /// Share of one phase in the total (0 without time).
  double share(StepPhase phase) const;
  /// Material-point updates per second of wall time spent in the timed phases (0 without).
  double pointUpdatesPerSecond() const;
  /// Forget everything (e.g. after warm-up steps).
  void reset() { *this = StepProfile{}; }
  /// Adds seconds to a phase.
  void add(StepPhase phase, double elapsed) { seconds[static_cast<int>(phase)] += elapsed; }
  /// Multi-line table: one line per phase that took time, with its share in % and seconds,
  /// then the steps, point updates and rate; every line starts with `indent`.
  std::string describe(const std::string& indent = "  ") const;
};

/// Whether kernels of ExecSpace have finished when parallel_for returns (no fence needed
/// before reading a clock).
template <class Space>
inline constexpr bool kSynchronousSpace = false;
#ifdef KOKKOS_ENABLE_SERIAL
template <>
inline constexpr bool kSynchronousSpace<Kokkos::Serial> = true;
#endif
#ifdef KOKKOS_ENABLE_OPENMP
template <>
inline constexpr bool kSynchronousSpace<Kokkos::OpenMP> = true;
#endif

/// Charges the wall time from construction to destruction to one phase of a profile.
class PhaseTimer {
 public:
  using Clock = std::chrono::steady_clock;
  /// Starts timing `phase`.
  PhaseTimer(StepProfile& profile, StepPhase phase)
      : profile_(profile), phase_(phase), start_(Clock::now()) {}
  /// Stops timing: fences an asynchronous backend, then adds the elapsed time.
  ~PhaseTimer() {
    if constexpr (!kSynchronousSpace<ExecSpace>) Kokkos::fence();
    profile_.add(phase_, std::chrono::duration<double>(Clock::now() - start_).count());
  }
  PhaseTimer(const PhaseTimer&) = delete;
  PhaseTimer& operator=(const PhaseTimer&) = delete;

 private:
  StepProfile& profile_;
  StepPhase phase_;
  Clock::time_point start_;
};

}  // namespace argine

#pragma once
/// @file ProgressReporter.hpp
/// Progress of long runs. On a terminal: one line redrawn with '\r' (stage, simulated time
/// against the stage duration, %, step, dt, ETA, point updates per second). Otherwise (a log
/// file, CI): a plain line every `plain_interval` seconds of wall time and at stage end.
/// update() is meant to be called every step: it only reads a cheap clock (steady_clock,
/// ~25 ns) and compares it with the next report time.

#include <functional>
#include <iosfwd>
#include <string>

#include "argine/core/Types.hpp"

namespace argine {

/// Wall-clock seconds since any fixed origin (injected so tests can drive time).
using WallClock = std::function<double()>;

/// How and how often progress is shown.
struct ProgressOptions {
  bool quiet = false;               ///< print nothing at all
  double plain_interval = 10.0;     ///< seconds between lines when not on a terminal
  double terminal_interval = 0.25;  ///< seconds between redraws of the terminal line
};

/// A wall-clock duration for people: "42s", "3m05s", "1h02m", "2d03h"; "--" if negative or
/// not finite (unknown).
std::string formatWallDuration(double seconds);

class ProgressReporter {
 public:
  /// Reports to `out`; `is_terminal` selects the redrawn line; `clock` gives wall seconds.
  ProgressReporter(std::ostream& out, bool is_terminal, WallClock clock,
                   ProgressOptions options = {});

  /// Reports to standard output: terminal mode when it is a tty (isatty), steady clock.
  static ProgressReporter forStandardOutput(const ProgressOptions& options = {});

  /// Starts a stage running from simulated time `start_time` for `duration` seconds, its
  /// steps from `resume_time` on (later than `start_time` when a run resumes from a
  /// checkpoint in the middle of the stage; the ETA is the rate since then).
  void beginStage(const std::string& name, Real start_time, Real duration);
  void beginStage(const std::string& name, Real start_time, Real duration, Real resume_time);

  /// Records one step that updated `num_points` points and ended at simulated time `time`;
  /// prints when a report is due.
  void update(long long step, Real time, Real dt, long long num_points);

  /// Prints the stage's final line (and ends the terminal line).
  void endStage(long long step, Real time, Real dt);

  /// The progress line for the current state at wall time `now` (without '\r' or '\n').
  std::string line(long long step, Real time, Real dt, double now) const;

 private:
  void print(long long step, Real time, Real dt, double now, bool final_line);

  std::ostream* out_;
  bool is_terminal_;
  WallClock clock_;
  ProgressOptions options_;

  std::string stage_;             ///< current stage name
  Real start_time_ = 0.0;         ///< simulated time at stage start (s)
  Real duration_ = 0.0;           ///< stage duration (s)
  Real resume_time_ = 0.0;        ///< simulated time this run's steps of the stage began (s)
  double wall_start_ = 0.0;       ///< wall time at stage start (s)
  double next_report_ = 0.0;      ///< wall time of the next report (s)
  long long point_updates_ = 0;   ///< point updates since stage start
  std::size_t drawn_length_ = 0;  ///< length of the terminal line last drawn
};

}  // namespace argine

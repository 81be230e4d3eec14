#pragma once
/// @file RestMonitor.hpp
/// When an explicit stage's slide has stopped, so that the rest of the stage can go back to
/// the implicit seepage path (`Hand Back At Rest`, issue P12: "hand over to the explicit MPM
/// when the motion starts, and back if it stops").
///
/// The measure is the LARGEST MEAN SPEED of the points over a window: at an output at time t,
/// at least W after the window began at t_w,
///     max_p |u_p(t) - u_p(t_w)| < v_r (t - t_w)
/// means at rest; otherwise a new window begins at t (u_p(t) is stored as each point's
/// `rest_reference`). A displacement over a window, not the points' speeds: a point's velocity
/// carries oscillations and transfer noise that move nothing (the experimental slope's drawdown
/// has about 580 points at 5-60 mm/s from 22 to 32 s while none moves more than 5 mm), and not
/// the kinetic-energy ratio of RelaxationMonitor: in a hydraulic stage the seepage carries
/// most of the kinetic energy, and a slide creeping at mm/min has a kinetic energy far below
/// any useful fraction of the stored elastic energy while it still moves.

#include "argine/input/Deck.hpp"
#include "argine/points/MaterialPoints.hpp"

namespace argine {

class RestMonitor {
 public:
  explicit RestMonitor(const HandBackSpec& spec) : spec_(spec) {}

  /// Whether the window that began at windowStart() is long enough to be judged at `time` (s).
  bool due(Real time) const { return time - window_start_ >= spec_.window * (1 - 1e-9); }
  /// Whether `largest_motion` (m), the largest displacement of any point since the window
  /// began, means rest at `time` (s); a NaN motion is motion.
  bool atRest(Real time, Real largest_motion) const {
    return largest_motion < spec_.largest_speed * (time - window_start_);
  }
  /// A new window from `time` (s) (the caller stores the points' rest_reference).
  void startWindow(Real time) { window_start_ = time; }
  Real windowStart() const { return window_start_; }

 private:
  HandBackSpec spec_;
  Real window_start_ = 0;
};

/// rest_reference = displacement at every point.
void markRestReference(MaterialPoints& points);
/// max |u_p - rest_reference_p| over the located points of `points` (m; 0 for none; infinity
/// when some value is not finite), this rank's points only.
Real largestMotionSinceReference(const MaterialPoints& points);

}  // namespace argine

#pragma once
/// @file LinearInX.hpp
/// A boundary value that varies linearly in x between two time series, constant beyond:
/// the imposed pore pressure along the bottom of the thesis' toe-uplift model (Ch. 5
/// Sec. 4, Table 5.6 and Fig. 5.32: the river's pressure in the sand at x = 0, the drain's
/// at x = 50 m). Used by a `pressure series` condition with `Linear Between x (m)` on both
/// the explicit path (HydraulicConditions) and the implicit seepage path (SeepageBoundary).

#include <algorithm>

#include "argine/boundary/TimeSeries.hpp"
#include "argine/core/Types.hpp"

namespace argine {

/// v(x) = v0 + (v1 - v0) s with s = (x - x0) / (x1 - x0) clamped to [0, 1] (x1 > x0): v0 at
/// and before x0, v1 at and after x1. The one formula of the profile.
inline Real linearInX(Real v0, Real v1, Real x0, Real x1, Real x) {
  const Real s = std::clamp((x - x0) / (x1 - x0), Real(0), Real(1));
  return v0 + (v1 - v0) * s;
}

/// The x-dependence of a condition whose own series gives the value at x0.
struct LinearInX {
  bool active = false;  ///< false: the value is uniform (the series alone)
  Real x0 = 0, x1 = 1;  ///< (m), x1 > x0
  TimeSeries end;       ///< the value at x1 in time
  /// The value at `x` for the series' value `v0` at `time`.
  Real at(Real v0, Real time, Real x) const {
    return active ? linearInX(v0, end.at(time), x0, x1, x) : v0;
  }
};

}  // namespace argine

#pragma once
/// @file DiffusionSeries.hpp
/// The series solution of 1D linear diffusion u_t = c u_yy on 0 <= y <= h with a no-flux
/// base (u_y = 0 at y = 0), u = 0 at the top (y = h) for t > 0 and u = 1 everywhere at
/// t = 0 (Terzaghi 1943; thesis Eq. 4.17; VERIFICATION.md V1):
///   u(y, T) = (4/pi) sum_{j>=1} (-1)^(j-1)/(2j-1) cos((2j-1) pi y/(2h)) exp(-(2j-1)^2 pi^2 T/4)
///   U(T) = 1 - (1/h) int_0^h u dy = 1 - (8/pi^2) sum_{j>=1} exp(-(2j-1)^2 pi^2 T/4)/(2j-1)^2
/// with the time factor T = c t / h^2. Both V1 (excess pore pressure) and V2 (suction) use
/// these two functions.

#include <cmath>

namespace argine::verification {

/// u(y, T) of the series above; `relative_height` = y/h in [0, 1], T > 0. Terms are summed
/// until the exponential factor drops below 1e-17 (9 terms at T = 0.05; more as T -> 0,
/// capped at 100000 terms).
inline double drainedTopSeries(double relative_height, double factor) {
  const double pi = M_PI;
  double sum = 0;
  for (int j = 1; j <= 100000; ++j) {
    const double m = 2.0 * j - 1.0;
    const double decay = std::exp(-m * m * pi * pi * factor / 4.0);
    if (decay < 1e-17) break;
    const double sign = (j % 2 == 1) ? 1.0 : -1.0;
    sum += sign / m * std::cos(m * pi * relative_height / 2.0) * decay;
  }
  return 4.0 / pi * sum;
}

/// The average degree of dissipation U(T) of the series above.
inline double drainedTopDegree(double factor) {
  const double pi = M_PI;
  double sum = 0;
  for (int j = 1; j <= 100000; ++j) {
    const double m = 2.0 * j - 1.0;
    const double decay = std::exp(-m * m * pi * pi * factor / 4.0);
    if (decay < 1e-17) break;
    sum += decay / (m * m);
  }
  return 1.0 - 8.0 / (pi * pi) * sum;
}

}  // namespace argine::verification

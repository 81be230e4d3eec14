#include "argine/simulation/StrengthReductionTrial.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace argine {

DisplacementTrend displacementTrend(const std::vector<Real>& start, const std::vector<Real>& a,
                                    const std::vector<Real>& b, const std::vector<Real>& c,
                                    Real t_a, Real t_b, Real t_c, Real minimum_displacement) {
  if (start.size() != a.size() || start.size() != b.size() || start.size() != c.size() ||
      start.size() % 2 != 0)
    throw std::invalid_argument("displacementTrend: displacement arrays of different sizes");
  if (!(t_a >= 0) || !(t_b > t_a) || !(t_c > t_b))
    throw std::invalid_argument("displacementTrend: expected 0 <= t_a < t_b < t_c");
  const std::size_t n = start.size() / 2;
  auto moved = [](const std::vector<Real>& from, const std::vector<Real>& to, std::size_t p) {
    return std::hypot(to[2 * p] - from[2 * p], to[2 * p + 1] - from[2 * p + 1]);
  };
  DisplacementTrend trend;
  for (std::size_t p = 0; p < n; ++p) trend.largest = std::max(trend.largest, moved(start, c, p));
  if (!(trend.largest > 0)) return trend;
  Real earlier = 0, later = 0, total = 0;
  for (std::size_t p = 0; p < n; ++p) {
    const Real u = moved(start, c, p);
    if (u < 0.5 * trend.largest) continue;
    ++trend.mobilised_points;
    total += u;
    earlier += moved(a, b, p);
    later += moved(b, c, p);
  }
  const Real count = static_cast<Real>(trend.mobilised_points);
  trend.mean = total / count;
  trend.earlier_rate = earlier / count / (t_b - t_a);
  trend.later_rate = later / count / (t_c - t_b);
  trend.accelerating = trend.later_rate > trend.earlier_rate && trend.mean >= minimum_displacement;
  trend.continuing = later / count >= minimum_displacement;
  return trend;
}

}  // namespace argine

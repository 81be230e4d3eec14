#include "argine/simulation/RestMonitor.hpp"

#include <cmath>
#include <limits>

namespace argine {

void markRestReference(MaterialPoints& points) {
  Kokkos::deep_copy(points.rest_reference, points.displacement);
}

Real largestMotionSinceReference(const MaterialPoints& points) {
  const auto element = points.element;
  const auto u = points.displacement;
  const auto reference = points.rest_reference;
  Real largest = 0;
  Kokkos::parallel_reduce(
      "largest_motion_since_reference", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p, Real& m) {
        if (element(p) < 0) return;
        const Real dx = u(p, 0) - reference(p, 0), dy = u(p, 1) - reference(p, 1);
        Real motion = std::sqrt(dx * dx + dy * dy);
        if (!std::isfinite(motion)) motion = std::numeric_limits<Real>::infinity();
        if (motion > m) m = motion;
      },
      Kokkos::Max<Real>(largest));
  return largest;
}

}  // namespace argine

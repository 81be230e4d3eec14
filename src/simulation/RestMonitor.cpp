#include "argine/simulation/RestMonitor.hpp"

#include "argine/materials/KernelMath.hpp"

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
        Real motion = kmath::sqrt(dx * dx + dy * dy);
        if (!kmath::isFinite(motion)) motion = kmath::infinity();
        if (motion > m) m = motion;
      },
      Kokkos::Max<Real>(largest));
  return largest;
}

}  // namespace argine

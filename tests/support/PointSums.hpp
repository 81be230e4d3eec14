#pragma once
// Sums over a run's material points that tests compare with hand values (the points may live
// in device memory: copied to the host first).

#include "argine/points/MaterialPoints.hpp"

namespace argine {

/// sum_p M_L,p of all points (kg per m of thickness).
inline Real totalLiquidMass(const MaterialPoints& points) {
  const auto mass = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.mass_liquid);
  Real total = 0;
  for (int p = 0; p < points.count; ++p) total += mass(p);
  return total;
}

}  // namespace argine

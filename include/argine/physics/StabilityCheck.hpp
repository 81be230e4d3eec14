#pragma once
/// @file StabilityCheck.hpp
/// Sums over the material points after each step (kinetic energies, liquid mass) and the
/// instability test: a non-finite point value, or a kinetic energy beyond a bound, stops the
/// run with a RunError naming the time, step, point and quantity.

#include <string>

#include "argine/core/Lanes.hpp"
#include "argine/core/Types.hpp"
#include "argine/materials/KernelMath.hpp"
#include "argine/points/MaterialPoints.hpp"

namespace argine {

class MaterialTable;

/// Point sums of one step.
struct PointTotals {
  Real kinetic_energy_solid = 0;   ///< sum 1/2 M_S |v_S|^2 (J per m thickness)
  Real kinetic_energy_liquid = 0;  ///< sum 1/2 M_L |v_L|^2 (J per m thickness)
  Real liquid_mass = 0;            ///< sum M_L (kg per m thickness)
  int non_finite_points = 0;       ///< points with a non-finite checked value or volume <= 0
};

/// Whether point p's position, liquid pressure and effective stress are finite and its
/// volume positive (a collapsed or inverted point volume is the other way an explicit step
/// fails). Velocities are checked where they are updated (the G2P).
/// T = Real: point p (a bool); Lanes: points p .. p + kLanes - 1 (a LaneMask).
template <class T = Real>
KOKKOS_INLINE_FUNCTION auto pointStateIsValid(const MaterialPoints& pts, int p) {
  const T volume = load<T>(pts.volume, p);
  auto ok = both(volume > 0,
                 both(kmath::isFinite(volume), kmath::isFinite(load<T>(pts.pressure_liquid, p))));
  for (int d = 0; d < kDim; ++d) ok = both(ok, kmath::isFinite(load<T>(pts.position, p, d)));
  for (int c = 0; c < kStressComponents; ++c)
    ok = both(ok, kmath::isFinite(load<T>(pts.stress_effective, p, c)));
  return ok;
}

/// pointStateIsValid and finite velocities.
KOKKOS_INLINE_FUNCTION bool pointIsValid(const MaterialPoints& pts, int p) {
  auto finite = [](Real x) { return Kokkos::Experimental::isfinite(x); };
  bool ok = pointStateIsValid(pts, p);
  for (int d = 0; d < kDim; ++d)
    ok = ok && finite(pts.velocity_solid(p, d)) && finite(pts.velocity_liquid(p, d));
  return ok;
}

/// Adds point p to the running sums [KE_S, KE_L, M_L, invalid points].
KOKKOS_INLINE_FUNCTION void addPointTotals(const MaterialPoints& pts, int p, Real sum[4]) {
  const Real vs2 = pts.velocity_solid(p, 0) * pts.velocity_solid(p, 0) +
                   pts.velocity_solid(p, 1) * pts.velocity_solid(p, 1);
  const Real vl2 = pts.velocity_liquid(p, 0) * pts.velocity_liquid(p, 0) +
                   pts.velocity_liquid(p, 1) * pts.velocity_liquid(p, 1);
  sum[0] += 0.5 * pts.mass_solid(p) * vs2;
  sum[1] += 0.5 * pts.mass_liquid(p) * vl2;
  sum[2] += pts.mass_liquid(p);
  if (!pointIsValid(pts, p)) sum[3] += 1;
}

/// The totals of the sums filled by addPointTotals.
PointTotals pointTotalsOf(const Real sums[4]);

/// One pass over the points: energies, liquid mass, and the count of points whose position,
/// velocities, pressure, effective stress or volume is not finite, or whose volume is not
/// positive.
PointTotals sumPointTotals(const MaterialPoints& points);

/// Index of the first point with a non-finite checked value, or -1.
int firstNonFinitePoint(const MaterialPoints& points);

/// Index of the point with the largest kinetic energy (-1 without points).
int mostEnergeticPoint(const MaterialPoints& points);

/// "point <id> (index <i>) at (x, y)" plus, when `non_finite`, ": <field> is <value>" for the
/// first non-finite value of the point (host copy of that point only).
std::string describePoint(const MaterialPoints& points, int index, bool non_finite);

/// The stored elastic energy (J per m), a scale estimate: sum V |sigma'|^2 / (2 E) over the
/// points plus, where there is liquid, sum V n p_L^2 / (2 K_L). Also the reference of a
/// stage's relaxation test (simulation/RelaxationMonitor.hpp).
Real storedElasticEnergy(const MaterialPoints& points, const MaterialTable& table);

/// A load-and-stored-energy scale of the current state (J per m): (weight + boundary loads)
/// times `size` (the extent of the background mesh: nothing falls or is pushed further), the
/// elastic energy of the effective stress and of the liquid pressure, and the kinetic energy.
/// The instability bound is a multiple of it: no stable run turns more energy into motion.
Real energyScale(const MaterialPoints& points, const MaterialTable& table, Real gravity,
                 Real boundary_load, Real size);

}  // namespace argine

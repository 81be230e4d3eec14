#pragma once
/// @file StabilityCheck.hpp
/// Sums over the material points after each step (kinetic energies, liquid mass) and the
/// instability test: a non-finite point value, or a kinetic energy beyond a bound, stops the
/// run with a RunError naming the time, step, point and quantity.

#include <string>

#include "argine/core/Lanes.hpp"
#include "argine/core/Types.hpp"
#include "argine/input/Deck.hpp"
#include "argine/materials/KernelMath.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/CompensatedSum.hpp"

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
  T stress[kStressComponents];
  loadComponents(pts.stress_effective, p, stress);
  for (int c = 0; c < kStressComponents; ++c) ok = both(ok, kmath::isFinite(stress[c]));
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
/// The same terms summed exactly (transfer/CompensatedSum.hpp): with reproducible sums the
/// relaxation test reads the same bits on any number of ranks (sumCompensatedOverRanks).
CompensatedReal compensatedStoredElasticEnergy(const MaterialPoints& points,
                                               const MaterialTable& table);

/// The parts of the energy scale that are sums over the points (J per m; on several ranks a
/// rank's share, to be summed over the ranks).
struct PointEnergies {
  /// sum (M_S + M_L) g max(y - datum, 0) over the points inside the mesh (element >= 0): with
  /// gravity along -y and `datum` the lowest y of the background mesh, the most the weight
  /// of the points can release (nothing inside the mesh falls below its lowest point; a
  /// point that left the mesh is frozen and releases nothing more).
  Real potential = 0;
  Real stored = 0;   ///< storedElasticEnergy
  Real kinetic = 0;  ///< sum 1/2 M_S |v_S|^2 + 1/2 M_L |v_L|^2
};

/// The point sums of the energy scale of the current state; `gravity` (m/s^2) along -y.
PointEnergies pointEnergies(const MaterialPoints& points, const MaterialTable& table, Real gravity,
                            Real datum);

/// The energy scale of the instability bound (J per m): an upper bound of the kinetic energy
/// a stable stage can reach. Energy balance of the stage: KE(t) + PE(t) + stored(t) +
/// dissipated = E(0) + work of the loads + energy of the liquid that entered; PE above the
/// datum, stored energy and dissipation (plasticity, drag, damping) are >= 0, so
///   KE(t) <= points.potential + points.stored + points.kinetic   (E(0), at the stage start)
///            + load x size                                         (work of the loads)
///            + inflow                                              (liquid that entered)
/// with `load` (N per m) the largest sum of load magnitudes of the stage so far and `size`
/// (m) the extent of the background mesh (nothing is pushed further), and `inflow` (J per m)
/// the energy the liquid entering through hydraulic conditions brought with it
/// (inflowEnergyPerMass). The one formula of the scale: the solver's stop and the
/// Kinetic Energy Bound warning both read it.
inline Real energyScale(const PointEnergies& points, Real load, Real size, Real inflow) {
  return points.potential + points.stored + points.kinetic + load * size + inflow;
}

/// Energy per kg (J/kg) of liquid entering the soil, above `datum`, bounded over the
/// condition's boundary: its potential energy at the highest point it can enter (`top`, the
/// highest y of the mesh, or a total head H above it) plus its pressure work p / rho_L where
/// the pressure is positive (under a total head g (H - y) + g (y - datum) = g (H - datum)).
/// `value`: the condition's current head (m) or pressure (Pa); `pressure_above`: the constant
/// pressure above a head's level (Pa). Infiltration without ponding enters at p_L <= 0 and
/// a seepage face lets liquid out only: g (top - datum). Not bounded: the pressure that
/// ponding rain (imposed whatever the pressure) may build up.
Real inflowEnergyPerMass(BoundaryKind kind, Real value, Real pressure_above, Real liquid_density,
                         Real gravity, Real top, Real datum);

}  // namespace argine

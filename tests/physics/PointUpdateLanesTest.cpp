// [Plasticity][2Phase] updatePointStates takes kLanes points at once where they share a
// material with a lane stress update (physics/PointUpdates.hpp); every point must get the
// bits of the one-point updates, whichever way it went: elastic or plastic lanes, each phase
// model, the suction-dependent model (no lane form), unsaturated lanes whose pressure takes the
// Newton iterations at once (one chunk, or two side by side) or point by point (a kink
// crossed, an air-filled crack open), lost points and a ragged end.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "Harness.hpp"
#include "argine/core/Lanes.hpp"
#include "argine/physics/PointUpdates.hpp"
#include "argine/points/PointFields.hpp"

namespace argine {
namespace {

using test::hostCopy;

std::vector<MaterialSpec> materials() {
  MaterialSpec saturated_mc = test::elasticMaterial("mc", PhaseModel::Saturated, 2e7, 0.3, 0.4);
  saturated_mc.solid.model = SolidModel::MohrCoulomb;
  saturated_mc.solid.cohesion = 2e3;
  saturated_mc.solid.friction_angle = 0.5;
  saturated_mc.solid.dilatancy_angle = 0.1;
  MaterialSpec elastic = test::elasticMaterial("elastic", PhaseModel::Saturated, 1e7, 0.25, 0.35);
  elastic.mass_balance = MassBalanceForm::Simplified;
  MaterialSpec unsaturated = saturated_mc;
  unsaturated.name = "unsaturated";
  unsaturated.phase = PhaseModel::Unsaturated;
  unsaturated.retention.linear_slope = 4e-7;
  MaterialSpec dry = saturated_mc;
  dry.name = "dry";
  dry.phase = PhaseModel::Dry;
  MaterialSpec suction = unsaturated;  // no lane form: point by point
  suction.name = "suction";
  suction.solid.model = SolidModel::SuctionMohrCoulomb;
  suction.solid.friction_suction_rate = 0.1;
  suction.solid.cohesion_increase_max = 5e3;
  suction.solid.cohesion_suction_rate = 1;
  MaterialSpec cracks = unsaturated;  // an open air-filled crack: its lanes point by point
  cracks.name = "cracks";
  cracks.tension_cracks = TensionCracks::AirFilled;
  return {saturated_mc, elastic, unsaturated, dry, suction, cracks};
}

/// Random point states and increments: materials by blocks of `block_points` (kLanes, or two
/// chunks of kLanes that updatePointStates takes together; some blocks mixed), stresses near
/// and past the Mohr-Coulomb surface, some spins exactly 0, pressures of either sign, a lost
/// point.
void randomise(MaterialPoints& points, PointRates& rates, unsigned seed, int block_points) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-1, 1);
  for (int p = 0; p < points.count; ++p) {
    const int block = p / block_points;
    points.material(p) = block % 7 == 6 ? p % 6 : block % 6;
    points.element(p) = p == 13 ? -1 : p;
    points.volume(p) = 0.01 * (1 + 0.2 * u(rng));
    points.porosity(p) = 0.4 + 0.05 * u(rng);
    // blocks of two chunks, even ones: suctions no step's increment takes across s = 0, so
    // that the pair of chunks finds its pressures together (any lane at the kink or with
    // an open crack sends its pair chunk by chunk)
    const bool suction_block = block_points > kLanes && block % 2 == 0;
    const Real pressure = suction_block ? -2.5e4 + 5e3 * u(rng) : 2e4 * u(rng);
    points.pressure_liquid(p) = pressure;
    points.saturation(p) = pressure < 0 ? 1 + 4e-7 * pressure : 1;
    points.density_liquid(p) = 1000 * std::exp(pressure / 2.2e9);
    points.mass_liquid(p) = points.porosity(p) * points.saturation(p) * points.density_liquid(p) *
                            points.volume(p) * (1 + 1e-6 * u(rng));
    points.stress_effective(p, XX) = -3e4 + 2e4 * u(rng);
    points.stress_effective(p, YY) = -5e4 + 2e4 * u(rng);
    points.stress_effective(p, ZZ) = -4e4 + 1e4 * u(rng);
    points.stress_effective(p, XY) = 1e4 * u(rng);
    for (int c = 0; c < kStressComponents; ++c) {
      points.strain(p, c) = 1e-3 * u(rng);
      rates.strain_increment_p(p, c) = c == ZZ ? 0 : 1e-3 * u(rng);
    }
    points.plastic_strain(p) = 1e-3 * (1 + u(rng));
    points.separation(p) = p % 4 == 1 ? 1e-3 * (1 + u(rng)) : 0;  // some open gaps
    for (int d = 0; d < kDim; ++d) {
      points.position(p, d) = u(rng);
      points.displacement(p, d) = 0.01 * u(rng);
      rates.displacement_increment_p(p, d) = 1e-4 * u(rng);
    }
    rates.spin_increment_p(p) = p % 3 == 0 ? 0.0 : 1e-3 * u(rng);
    rates.liquid_divergence_increment_p(p) = 1e-4 * u(rng);
    rates.content_flux_divergence_increment_p(p) = 0.1 * u(rng);
  }
}

/// The one-point updates in their order (updatePointStates' reference).
void updateOneByOne(const MaterialTable& table, const PointRates& rates, MaterialPoints& points,
                    bool hold) {
  const PointUpdateViews v{table.materials(), points, rates, hold, {}};
  for (int p = 0; p < points.count; ++p) {
    if (points.element(p) < 0) continue;
    closeSeparation(v, p);
    updatePorosityAndVolume(v, p);
    updateLiquidPressure(v, p);
    updateEffectiveStress(v, p);
    updateLiquidState(v, p);
    updatePointPosition(v, p);
  }
}

TEST(PointUpdateLanes, EveryPointGetsTheOnePointBits) {
  const MaterialTable table(materials());
  const int count = 70;  // not a multiple of kLanes
  for (const bool hold : {false, true})
    for (const int block_points : {kLanes, 2 * kLanes}) {
      SCOPED_TRACE(block_points);
      MaterialPoints lanes, reference;
      lanes.allocate(count);
      reference.allocate(count);
      PointRates rates;
      rates.allocate(count);
      randomise(lanes, rates, 3, block_points);
      forEachPointField(lanes, [&](const char* name, const auto& field) {
        forEachPointField(reference, [&](const char* other, auto& target) {
          if constexpr (std::is_same_v<std::decay_t<decltype(field)>,
                                       std::decay_t<decltype(target)>>)
            if (std::string(name) == other) Kokkos::deep_copy(target, field);
        });
      });
      // the gap closure rewrites a point's strain increment: each path its own copy
      PointRates reference_rates;
      reference_rates.allocate(count);
      Kokkos::deep_copy(reference_rates.strain_increment_p, rates.strain_increment_p);
      Kokkos::deep_copy(reference_rates.spin_increment_p, rates.spin_increment_p);
      Kokkos::deep_copy(reference_rates.displacement_increment_p, rates.displacement_increment_p);
      Kokkos::deep_copy(reference_rates.liquid_divergence_increment_p,
                        rates.liquid_divergence_increment_p);
      Kokkos::deep_copy(reference_rates.content_flux_divergence_increment_p,
                        rates.content_flux_divergence_increment_p);
      const PointTotals totals = updatePointStates(table, rates, lanes, hold);
      updateOneByOne(table, reference_rates, reference, hold);

      int plastic = 0, invalid = 0;
      Real liquid_mass = 0;
      for (int p = 0; p < count; ++p) {
        liquid_mass += reference.mass_liquid(p);
        plastic += reference.plastic_state(p) != kPlasticStateElastic;
        invalid += !pointStateIsValid(reference, p);
      }
      EXPECT_EQ(totals.liquid_mass, liquid_mass);
      EXPECT_EQ(totals.non_finite_points, invalid);
      EXPECT_EQ(invalid, 0);
      EXPECT_GT(plastic, 4);  // the returns are exercised, in lanes with elastic neighbours
      EXPECT_LT(plastic, count / 2);
      forEachPointField(lanes, [&](const char* name, const auto& field) {
        forEachPointField(reference, [&](const char* other, const auto& expected) {
          if constexpr (std::is_same_v<std::decay_t<decltype(field)>,
                                       std::decay_t<decltype(expected)>>)
            if (std::string(name) == other)
              for (int p = 0; p < count; ++p) {
                if constexpr (std::decay_t<decltype(field)>::rank == 1) {
                  EXPECT_EQ(std::memcmp(&field(p), &expected(p), sizeof(field(p))), 0)
                      << name << " of point " << p << ": " << field(p) << " vs " << expected(p);
                } else {
                  for (std::size_t c = 0; c < field.extent(1); ++c)
                    EXPECT_EQ(std::memcmp(&field(p, c), &expected(p, c), sizeof(field(p, c))), 0)
                        << name << "[" << c << "] of point " << p;
                }
              }
        });
      });
    }
}

TEST(PointUpdateLanes, AnInvalidStateIsCountedInItsLane) {
  const MaterialTable table(materials());
  MaterialPoints points;
  points.allocate(8);
  PointRates rates;
  rates.allocate(8);
  randomise(points, rates, 5, kLanes);
  for (int p = 0; p < 8; ++p) points.material(p) = 0, points.element(p) = p;
  points.volume(2) = -1;                            // inverted
  points.stress_effective(5, XY) = std::nan("");    // not finite
  rates.displacement_increment_p(6, 0) = INFINITY;  // position becomes infinite
  EXPECT_EQ(updatePointStates(table, rates, points).non_finite_points, 3);
}

}  // namespace
}  // namespace argine

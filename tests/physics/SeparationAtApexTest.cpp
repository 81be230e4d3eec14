// [Plasticity][LargeDeformation] A return to the Mohr-Coulomb apex separates a point from its
// neighbours: the opening is not porosity (PointUpdates.hpp: separationOpening,
// separateFromNeighbours). Hand-computed single points, then a psi = 0 collapse that keeps its
// volume and its time step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "Harness.hpp"
#include "argine/physics/PointUpdates.hpp"

namespace argine {
namespace {

using test::hostCopy;

/// A cohesionless Mohr-Coulomb material (phi 30 deg, psi 0) of the given phase model.
MaterialSpec sand(PhaseModel phase) {
  MaterialSpec m = test::elasticMaterial("sand", phase, 1e6, 0.25, 0.4);
  m.solid.model = SolidModel::MohrCoulomb;
  m.solid.cohesion = 0;
  m.solid.friction_angle = M_PI / 6;
  m.solid.dilatancy_angle = 0;
  if (phase == PhaseModel::Unsaturated) m.retention.linear_slope = 4e-5;  // S_L = 1 - 4e-5 s
  return m;
}

/// One point at isotropic effective stress -1 kPa given the strain increment `dstrain`
/// (xx, yy; zz = xy = 0), updated by the one-point path; returns the point. `air_reaches`:
/// the point's element (0) in the air path's map (-1: no map).
MaterialPoints updateOnePoint(const MaterialSpec& material, Real dxx, Real dyy, Real pressure,
                              int air_reaches = -1) {
  MaterialPoints points;
  points.allocate(1);
  PointRates rates;
  rates.allocate(1);
  points.element(0) = 0;
  points.volume(0) = 1e-4;
  points.porosity(0) = 0.4;
  for (int c : {XX, YY, ZZ}) points.stress_effective(0, c) = -1e3;
  const bool wet = material.phase != PhaseModel::Dry;
  points.pressure_liquid(0) = wet ? pressure : 0;
  const MaterialTable table({material});
  if (wet) {
    const LiquidState state = saturationAndConductivity(table.materials()(0), pressure);
    points.saturation(0) = state.saturation;
    points.conductivity(0) = state.conductivity;
    points.density_liquid(0) = liquidDensity(material.liquid, pressure);
    points.mass_liquid(0) = 0.4 * state.saturation * points.density_liquid(0) * 1e-4;
  }
  rates.strain_increment_p(0, XX) = dxx;
  rates.strain_increment_p(0, YY) = dyy;
  Kokkos::View<unsigned char*, MemSpace> air;
  if (air_reaches >= 0) {
    air = Kokkos::View<unsigned char*, MemSpace>("air", 1);
    Kokkos::deep_copy(air, static_cast<unsigned char>(air_reaches));
  }
  const PointUpdateViews v{table.materials(), points, rates, false, air};
  closeSeparation(v, 0);
  updatePorosityAndVolume(v, 0);
  updateLiquidPressure(v, 0);
  updateEffectiveStress(v, 0);
  updateLiquidState(v, 0);
  return points;
}

TEST(SeparationAtApex, OpeningIsTheVolumetricStrainTheStressDidNotFollow) {
  // K = lambda + 2 G / 3 = E / (3 (1 - 2 nu)) = 1e6 / 1.5 = 666,667 Pa. From p' = -1 kPa to
  // the apex (0): the elastic part is 1e3 / K = 1.5e-3; of d eps_vol = 1e-2 the opening is
  // 8.5e-3.
  SolidConstants constants = solidConstants(sand(PhaseModel::Dry).solid);
  const Real dstrain[kStressComponents] = {6e-3, 4e-3, 0, 1e-3};
  EXPECT_NEAR(separationOpening(constants, dstrain, -1e3, 0.0), 1e-2 - 1.5e-3, 1e-15);
}

TEST(SeparationAtApex, ADryPointPulledApartKeepsTheVolumeItsStressFollowed) {
  // Isotropic extension 2 x 5e-3 from p' = -1 kPa: the trial lies beyond the apex. The point
  // keeps V (1 + 1.5e-3) (the elastic part to p' = 0) and n from (1 - n) V = const; the
  // kinematic 1 + 1e-2 would be the old rule.
  const MaterialPoints p = updateOnePoint(sand(PhaseModel::Dry), 5e-3, 5e-3, 0);
  EXPECT_EQ(p.plastic_state(0), kPlasticStateApex);
  EXPECT_NEAR(p.volume(0), 1e-4 * (1 + 1.5e-3), 1e-15);
  EXPECT_NEAR(p.porosity(0), 1 - 0.6 / (1 + 1.5e-3), 1e-14);
  for (int c : {XX, YY, ZZ}) EXPECT_NEAR(p.stress_effective(0, c), 0.0, 1e-9);
}

TEST(SeparationAtApex, APointCrackingAtTheTensionCutOffKeepsTheVolumeItsStressFollowed) {
  // c = 2 kPa, phi 30: apex c cot phi = 3.46 kPa above the cut-off sigma_t = 0. From p' =
  // -1 kPa, d eps_xx = 1e-2 alone: the trial sigma_xx = -1e3 + (lambda + 2G) 1e-2 > 0 returns
  // to the cut-off face (a crack normal to x), a kPlasticStateTension return; the point keeps
  // V (1 + (p' after - p' before) / K) and not the kinematic 1 + 1e-2.
  MaterialSpec material = sand(PhaseModel::Dry);
  material.solid.cohesion = 2e3;
  material.solid.tensile_strength = 0;
  const MaterialPoints p = updateOnePoint(material, 1e-2, 0, 0);
  EXPECT_EQ(p.plastic_state(0), kPlasticStateTension);
  const Real bulk = 1e6 / 1.5;
  const Real mean =
      (p.stress_effective(0, XX) + p.stress_effective(0, YY) + p.stress_effective(0, ZZ)) / 3;
  EXPECT_NEAR(p.stress_effective(0, XX), 0.0, 1e-6);
  EXPECT_NEAR(p.volume(0), 1e-4 * (1 + (mean + 1e3) / bulk), 1e-15);
  EXPECT_LT(p.volume(0), 1e-4 * (1 + 2e-3));
}

/// The sand with c = 2 kPa and the cut-off at 0 (APointCrackingAtTheTensionCutOff...), its
/// cracks filled as `cracks` says.
MaterialSpec crackingSand(PhaseModel phase, TensionCracks cracks = TensionCracks::PoreSpace) {
  MaterialSpec material = sand(phase);
  material.solid.cohesion = 2e3;
  material.solid.tensile_strength = 0;
  material.tension_cracks = cracks;
  return material;
}

TEST(SeparationAtApex, AnUnsaturatedCrackAtTheCutOffStaysPoreSpaceByDefault) {
  // The cut-off case of APointCrackingAtTheTensionCutOff... on an unsaturated point with
  // `Tension Cracks: pore space` (the thesis): the crack is pore space of the point
  // (keepsOpeningOut): the kinematic volume.
  const MaterialPoints p = updateOnePoint(crackingSand(PhaseModel::Unsaturated), 1e-2, 0, -5e3);
  EXPECT_EQ(p.plastic_state(0), kPlasticStateTension);
  EXPECT_NEAR(p.volume(0), 1e-4 * (1 + 1e-2), 1e-15);
  EXPECT_EQ(p.separation(0), 0.0);
}

TEST(SeparationAtApex, AnAirFilledCrackIsKeptOutOfThePoresAndDrawsNoWater) {
  // The same with `Tension Cracks: air-filled`: the point kept its suction, so the crack is
  // open to the air: the point keeps the volume its stress followed, as a dry point, the
  // opening is its separation, and its pores hold the liquid they held: S_L = 0.8 n0 V0 /
  // (n V) with n V = V - 0.6 V0 (rho_L changes by ~p / K_L, 1e-8 here).
  const MaterialPoints p = updateOnePoint(
      crackingSand(PhaseModel::Unsaturated, TensionCracks::AirFilled), 1e-2, 0, -5e3);
  EXPECT_EQ(p.plastic_state(0), kPlasticStateTension);
  const Real bulk = 1e6 / 1.5;
  const Real mean =
      (p.stress_effective(0, XX) + p.stress_effective(0, YY) + p.stress_effective(0, ZZ)) / 3;
  const Real kept = (mean + 1e3) / bulk;  // the elastic part of d eps_vol
  EXPECT_NEAR(p.volume(0), 1e-4 * (1 + kept), 1e-15);
  EXPECT_NEAR(p.separation(0), 1e-2 - kept, 1e-15);
  const Real saturation = 0.8 * 0.4 / (0.4 + kept);
  EXPECT_NEAR(p.saturation(0), saturation, 1e-6);
  EXPECT_NEAR(p.pressure_liquid(0), -(1 - saturation) / 4e-5, 0.05);
  // the pore-space crack takes the whole 1e-2 into the pores: S_L = 0.8 x 0.4 / 0.41
  const MaterialPoints pores = updateOnePoint(crackingSand(PhaseModel::Unsaturated), 1e-2, 0, -5e3);
  EXPECT_NEAR(pores.saturation(0), 0.8 * 0.4 / 0.41, 1e-6);
  EXPECT_GT(p.saturation(0), pores.saturation(0) + 0.01);
}

TEST(SeparationAtApex, NoAirFilledCrackOpensWhereNoAirReaches) {
  // The point of AnAirFilledCrack... in an element the air path does not reach (AirPath.hpp):
  // its crack stays pore space, the same bits as the pore-space model; where air reaches,
  // the air-filled crack of the test above.
  const MaterialSpec air_filled = crackingSand(PhaseModel::Unsaturated, TensionCracks::AirFilled);
  const MaterialPoints shut = updateOnePoint(air_filled, 1e-2, 0, -5e3, 0);
  const MaterialPoints pores = updateOnePoint(crackingSand(PhaseModel::Unsaturated), 1e-2, 0, -5e3);
  EXPECT_EQ(shut.plastic_state(0), kPlasticStateTension);
  EXPECT_EQ(shut.separation(0), 0.0);
  EXPECT_EQ(shut.volume(0), pores.volume(0));
  EXPECT_EQ(shut.saturation(0), pores.saturation(0));
  EXPECT_EQ(shut.pressure_liquid(0), pores.pressure_liquid(0));
  const MaterialPoints open = updateOnePoint(air_filled, 1e-2, 0, -5e3, 1);
  const MaterialPoints no_map = updateOnePoint(air_filled, 1e-2, 0, -5e3);
  EXPECT_GT(open.separation(0), 9e-3);
  EXPECT_EQ(open.separation(0), no_map.separation(0));
  EXPECT_EQ(open.saturation(0), no_map.saturation(0));
}

TEST(SeparationAtApex, LiquidSqueezedFromACrackedPointFillsItsCrackAtZeroPressure) {
  // Nearly saturated (p_L = -50 Pa, S_L = 0.998), pulled in x (1e-2) and squeezed in y
  // (-3e-3). Hand-computed: lambda = G = 4e5 Pa; the trial sigma_xx = -1e3 + 1.2e6 x 1e-2 +
  // 4e5 x (-3e-3) = 9,800 Pa returns to the cut-off alone (sigma_yy -3,867, sigma_zz -1,467
  // Pa: inside the Mohr-Coulomb planes) with d lambda = 9,800 / 1.2e6 = 8.1667e-3, the
  // opening; the pores keep d eps_vol - opening = 7e-3 - 8.1667e-3 = -1.1667e-3, a squeeze
  // of n V from 0.4 to 0.39883 V0 that the liquid (0.3992 rho_L0 V0) no longer fits at
  // p_L <= 0: the rest stands in the crack (8.17e-7 m^3 of room), p_L = 0, M_L kept.
  // The pore-space model takes the opening into the pores instead: suction, s = 480 Pa.
  const MaterialSpec material = crackingSand(PhaseModel::Unsaturated, TensionCracks::AirFilled);
  const Real mass0 = 0.4 * 0.998 * liquidDensity(material.liquid, -50) * 1e-4;
  const MaterialPoints air = updateOnePoint(material, 1e-2, -3e-3, -50);
  EXPECT_EQ(air.plastic_state(0), kPlasticStateTension);
  EXPECT_NEAR(air.separation(0), 9800 / 1.2e6, 1e-12);
  EXPECT_NEAR(air.volume(0), 1e-4 * (1 + 7e-3 - 9800 / 1.2e6), 1e-15);
  EXPECT_EQ(air.pressure_liquid(0), 0.0);
  EXPECT_NEAR(air.mass_liquid(0), mass0, 1e-12 * mass0);
  EXPECT_EQ(air.saturation(0), 1.0);
  const MaterialPoints pores =
      updateOnePoint(crackingSand(PhaseModel::Unsaturated), 1e-2, -3e-3, -50);
  EXPECT_NEAR(pores.pressure_liquid(0), -(1 - 0.998 * 0.4 / 0.407) / 4e-5, 5.0);

  // Closing the crack (2 x -5e-3: 8.1667e-3 of gap, then 1.8333e-3 of the pores) puts the
  // crack's water back into the smaller pores: the crack is gone and p_L > 0, M_L kept.
  MaterialPoints points = air;
  const MaterialTable table({material});
  PointRates rates;
  rates.allocate(1);
  rates.strain_increment_p(0, XX) = -5e-3;
  rates.strain_increment_p(0, YY) = -5e-3;
  const PointUpdateViews v{table.materials(), points, rates, false, {}};
  closeSeparation(v, 0);
  updatePorosityAndVolume(v, 0);
  updateLiquidPressure(v, 0);
  EXPECT_EQ(points.separation(0), 0.0);
  EXPECT_GT(points.pressure_liquid(0), 0.0);
  EXPECT_NEAR(points.mass_liquid(0), mass0, 1e-12 * mass0);
}

TEST(SeparationAtApex, APointThatOpenedClosesItsGapBeforeItCompresses) {
  // Pulled apart (gap 8.5e-3, ADryPointPulledApart...), then compressed by 2 x -3e-3: the
  // -6e-3 close the gap (2.5e-3 of it left), the point's volume and stress do not change.
  // A further -2 x 3e-3 closes the rest (2.5e-3) and compresses the point by the remaining
  // 3.5e-3, isotropically in the plane: V = V_open (1 - 3.5e-3), p' = -K 3.5e-3 ... from 0.
  MaterialSpec material = sand(PhaseModel::Dry);
  MaterialPoints points = updateOnePoint(material, 5e-3, 5e-3, 0);
  const Real volume_open = points.volume(0);
  EXPECT_NEAR(points.separation(0), 8.5e-3, 1e-15);
  const MaterialTable table({material});
  PointRates rates;
  rates.allocate(1);
  const PointUpdateViews v{table.materials(), points, rates, false, {}};
  auto compress = [&] {
    rates.strain_increment_p(0, XX) = -3e-3;
    rates.strain_increment_p(0, YY) = -3e-3;
    closeSeparation(v, 0);
    updatePorosityAndVolume(v, 0);
    updateEffectiveStress(v, 0);
  };
  compress();
  EXPECT_NEAR(points.separation(0), 2.5e-3, 1e-15);
  EXPECT_NEAR(points.volume(0), volume_open, 1e-18);
  for (int c : {XX, YY, ZZ}) EXPECT_NEAR(points.stress_effective(0, c), 0.0, 1e-9);
  compress();
  EXPECT_EQ(points.separation(0), 0.0);
  EXPECT_NEAR(points.volume(0), volume_open * (1 - 3.5e-3), 1e-16);
  const Real bulk = 1e6 / 1.5;
  const Real mean = (points.stress_effective(0, XX) + points.stress_effective(0, YY) +
                     points.stress_effective(0, ZZ)) /
                    3;
  EXPECT_NEAR(mean, -bulk * 3.5e-3, 1e-6 * bulk * 3.5e-3);
}

TEST(SeparationAtApex, AnElasticOrShearedPointFollowsItsKinematicVolume) {
  // Compression (elastic) and a shear with psi = 0 (a face return: no plastic volume) keep
  // the kinematic rule V (1 + d eps_vol).
  const MaterialPoints compressed = updateOnePoint(sand(PhaseModel::Dry), -1e-3, -2e-3, 0);
  EXPECT_EQ(compressed.plastic_state(0), kPlasticStateElastic);
  EXPECT_NEAR(compressed.volume(0), 1e-4 * (1 - 3e-3), 1e-16);
  const MaterialPoints sheared = updateOnePoint(sand(PhaseModel::Dry), 4e-3, -4e-3, 0);
  EXPECT_EQ(sheared.plastic_state(0), kPlasticStatePlastic);
  EXPECT_NEAR(sheared.volume(0), 1e-4, 1e-16);
}

TEST(SeparationAtApex, AnUnsaturatedPointKeepsItsContentAndSoItsSuction) {
  // Air fills the opening: the liquid keeps the point's own pores, which grow by the elastic
  // part only: n V from 0.4 V to 0.4015 V, so S_L rho_L falls by 0.4 / 0.4015 (rho_L changes
  // by ~p / K_L, 1e-8 here): S_L = 0.8 x 0.4 / 0.4015 = 0.797011, s = (1 - S_L) / 4e-5 Pa. The
  // kinematic rule (n V = 0.41 V) would give S_L = 0.7805, s = 5488 Pa.
  const Real suction = 5e3;
  const MaterialPoints p = updateOnePoint(sand(PhaseModel::Unsaturated), 5e-3, 5e-3, -suction);
  EXPECT_EQ(p.plastic_state(0), kPlasticStateApex);
  const Real saturation = 0.8 * 0.4 / 0.4015;
  EXPECT_NEAR(p.saturation(0), saturation, 1e-6);
  EXPECT_NEAR(p.pressure_liquid(0), -(1 - saturation) / 4e-5, 0.05);
}

TEST(SeparationAtApex, ASaturatedPointDrawsWaterIntoItsOpening) {
  // Saturated: the dilation stays (the liquid's mass balance answers it with suction).
  const MaterialPoints p = updateOnePoint(sand(PhaseModel::Saturated), 5e-3, 5e-3, 0);
  EXPECT_NEAR(p.volume(0), 1e-4 * (1 + 1e-2), 1e-15);
}

TEST(SeparationAtApex, APsiZeroCollapseKeepsItsVolumeAndItsTimeStep) {
  // A dry column, 5 cm x 10 cm (a = 2) of 5 mm quads, 4 points each, phi 30, psi 0, c 0,
  // released against a smooth wall on a rough floor, FLIP and linear shapes (the scheme that
  // dilated most: +44 % of volume at a = 2 before, points at n = 0.99), 0.3 s. Its volume stays
  // within 5 % of the initial, no point loosens beyond n0 + 0.02, and the dry CFL step stays
  // within a factor 2 of its initial value (it fell 14-fold with the dilated points).
  Mesh mesh = test::rectangleMesh(40, 24, 0.2, 0.12, ElementType::Quad4);
  MaterialPoints points = test::seedUniform(mesh, 0, [](int e) {
    const int i = e % 40, j = e / 40;
    return i < 10 && j < 20;
  });
  const std::vector<MaterialSpec> materials{sand(PhaseModel::Dry)};
  initialisePointState(materials, points);
  const Real volume0 = [&] {
    Real sum = 0;
    const auto v = hostCopy(points.volume);
    for (int p = 0; p < points.count; ++p) sum += v(p);
    return sum;
  }();
  ExplicitTwoPhaseSolver solver(mesh, points, materials);
  solver.setSortInterval(ExplicitTwoPhaseSolver::kRecommendedSortInterval);
  solver.beginStage(test::makeStage("collapse", SolverKind::Explicit, 9.81, 0.0,
                                    {test::solidFixity("floor", "bottom", true, true),
                                     test::solidFixity("wall", "left", true, false)},
                                    {CriterionKind::CflDry}));
  const Real dt0 = solver.chooseTimeStep().time_step;
  Real dt_min = dt0;
  test::runUntil(solver, 0.3, [&] { dt_min = std::min(dt_min, solver.diagnostics().time_step); });
  const auto v = hostCopy(points.volume), n = hostCopy(points.porosity);
  const auto x = hostCopy(points.position);
  Real volume = 0, n_max = 0, front = 0;
  for (int p = 0; p < points.count; ++p) {
    volume += v(p);
    n_max = std::max(n_max, n(p));
    front = std::max(front, x(p, 0));
  }
  EXPECT_GT(front, 0.08);  // the column did collapse (L0 = 0.05 m)
  EXPECT_NEAR(volume / volume0, 1.0, 0.05);
  EXPECT_LT(n_max, 0.42);
  EXPECT_GT(dt_min, 0.5 * dt0);
}

}  // namespace
}  // namespace argine

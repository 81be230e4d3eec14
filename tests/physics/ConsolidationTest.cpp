// [2Phase][Explicit] Liquid flow: Terzaghi consolidation, closed-column mass conservation,
// fixed-skeleton drainage, dry material next to saturated.
#include <gtest/gtest.h>

#include <cmath>

#include "Harness.hpp"
#include "argine/physics/LiquidState.hpp"
#include "argine/physics/MaterialTable.hpp"

namespace argine {
namespace {

using test::hostCopy;
using test::makeStage;
using test::runUntil;

/// Terzaghi's excess pore pressure (drained top at z = 0, impermeable base at z = H):
/// p(z, t) = sum_m 2 p0 / M sin(M z / H) exp(-M^2 T), M = pi (2m + 1) / 2, T = c_v t / H^2.
Real terzaghi(Real p0, Real z, Real height, Real time_factor) {
  Real p = 0;
  for (int m = 0; m < 200; ++m) {
    const Real M = M_PI * (2 * m + 1) / 2;
    p += 2 * p0 / M * std::sin(M * z / height) * std::exp(-M * M * time_factor);
  }
  return p;
}

/// Saturated column for consolidation: E = 1e7 Pa, nu = 0 (E_c = 1e7, m_v = 1e-7 1/Pa),
/// n = 0.4, K_L = 2e7 Pa, k = 1e-3 m/s; H = 1 m in 10 elements of 0.1 m, width 0.1 m.
/// Hand values:
///   B  = m_v / (m_v + n/K_L) = 1e-7 / 1.2e-7 = 0.833333       p0 = B q = 8333.33 Pa
///   c_v = k / (gamma_w (m_v + n/K_L)) = 1e-3 / (1000 * 9.81 * 1.2e-7) = 0.849473 m^2/s
///   (gamma_w = rho_L g with the g = 9.81 that defines k).
MaterialSpec consolidationClay() {
  return test::elasticMaterial("clay", PhaseModel::Saturated, 1e7, 0.0, 0.4, 1e-3, 2e7);
}

/// Runs Terzaghi's column with `elements` elements over the height: q = 10 kPa on a drained
/// top (p_L = 0, the natural condition), impermeable fixed base, rollers with impermeable
/// sides, no gravity (the excess pressure alone). Returns the largest |p - p_exact| / p0 over
/// the points at each T of `times`; checks the early state on the way.
std::vector<Real> terzaghiErrors(int elements, const std::vector<Real>& times,
                                 bool implicit_drag = false) {
  test::Column column(elements, 0.1, 1.0, consolidationClay());
  auto boundaries = test::columnBoundaries();
  boundaries.push_back(test::traction("load", "top", 0.0, -1e4));
  ExplicitTwoPhaseSolver solver(column.mesh, column.points, column.materials);
  // Local damping takes out the stress waves of the sudden load (Terzaghi's solution is
  // quasi-static); it acts on unbalanced forces only and leaves the consolidation alone.
  StageSpec stage = makeStage("consolidate", SolverKind::QuasiStatic, 0.0, 0.5, boundaries);
  if (implicit_drag) {  // the drag no longer bounds the step; the diffusion still does
    stage.implicit_drag = true;
    stage.time_step.criteria.push_back(CriterionKind::Consolidation);
  }
  solver.beginStage(stage);
  const Real p0 = 1e4 / 1.2;
  const Real cv = 1e-3 / (1000 * 9.81 * 1.2e-7);
  const auto y0 = hostCopy(column.points.initial_position);
  std::vector<Real> errors;
  for (const Real time_factor : times) {
    runUntil(solver, time_factor / cv);
    const auto pressure = hostCopy(column.points.pressure_liquid);
    Real worst = 0;
    for (int p = 0; p < column.points.count; ++p) {
      const Real exact = terzaghi(p0, 1.0 - y0(p, 1), 1.0, time_factor);
      worst = std::max(worst, std::fabs(pressure(p) - exact));
      // Early, the base still carries the undrained p0 (Skempton/Terzaghi B).
      if (time_factor <= 0.05 && y0(p, 1) < 0.1) {
        EXPECT_NEAR(pressure(p), p0, 0.03 * p0) << "T = " << time_factor;
      }
    }
    errors.push_back(worst / p0);
    std::printf("[ terzaghi ] %d elements, T = %.2f: largest |p - p_exact| = %.3g p0\n", elements,
                time_factor, worst / p0);
  }
  return errors;
}

TEST(Consolidation, TerzaghiColumnUnderTopLoad) {
  const std::vector<Real> times{0.05, 0.1, 0.2, 0.5};
  const auto coarse = terzaghiErrors(10, times);
  EXPECT_LT(coarse[0], 0.08);  // T = 0.05: the damped load transient still shows
  EXPECT_LT(coarse[1], 0.06);
  EXPECT_LT(coarse[2], 0.04);
  EXPECT_LT(coarse[3], 0.02);
  // Twice the elements: the error falls (about first order, the drained-top points lag).
  const auto fine = terzaghiErrors(20, {0.5});
  EXPECT_LT(fine[0], 0.65 * coarse[3]);
}

TEST(Consolidation, TerzaghiColumnWithImplicitDrag) {
  // `Liquid Drag: implicit` (doc/theory.md Sec. 3.1): the same column, the drag at the new
  // velocities. The flow is Darcy's either way, so Terzaghi's solution must hold to the
  // same bounds as with the thesis' explicit drag.
  const auto errors = terzaghiErrors(10, {0.05, 0.1, 0.2, 0.5}, true);
  EXPECT_LT(errors[0], 0.08);
  EXPECT_LT(errors[1], 0.06);
  EXPECT_LT(errors[2], 0.04);
  EXPECT_LT(errors[3], 0.02);
}

/// The undrained p_L under q = 10 kPa on top of a column of S_max = 0.8 soil at p_L = 0 (the
/// 20 % of air occluded), with the air rigid (the thesis) or compressing by Boyle's law at
/// p_a = 101.325 kPa (Retention/Occluded Air Pressure). Oedometric, E_oed = 1e7 Pa (nu = 0),
/// n = 0.4, K_L = 2.2e9 Pa, k = 1e-8 m/s (drainage reaches a few cm below the top in 0.6 s).
Real undrainedPressureOfOccludedAir(Real air_pressure, int& lower_points) {
  MaterialSpec soil = test::elasticMaterial("soil", PhaseModel::Unsaturated, 1e7, 0.0, 0.4, 1e-8);
  soil.retention.model = RetentionModel::VanGenuchten;
  soil.retention.reference_pressure = 19e3;
  soil.retention.lambda = 0.75;
  soil.retention.saturation_min = 0.16;
  soil.retention.saturation_max = 0.8;
  soil.retention.occluded_air_pressure = air_pressure;
  test::Column column(10, 0.1, 1.0, soil);
  auto boundaries = test::columnBoundaries();
  boundaries.push_back(test::traction("load", "top", 0.0, -1e4));
  ExplicitTwoPhaseSolver solver(column.mesh, column.points, column.materials);
  StageSpec stage = makeStage("load", SolverKind::QuasiStatic, 0.0, 0.7, boundaries,
                              {CriterionKind::CflUndrained, CriterionKind::Consolidation});
  stage.implicit_drag = true;
  solver.beginStage(stage);
  runUntil(solver, 0.6);  // damped waves settle in about 0.6 s
  const auto pressure = hostCopy(column.points.pressure_liquid);
  const auto y0 = hostCopy(column.points.initial_position);
  Real sum = 0;
  lower_points = 0;
  for (int p = 0; p < column.points.count; ++p)
    if (y0(p, 1) < 0.5) {
      sum += pressure(p);
      lower_points += 1;
    }
  return sum / lower_points;
}

TEST(Consolidation, OccludedAirTakesLittleOfAnUndrainedLoadWhereRigidAirTakesMoreThanAll) {
  // Hand values (no drainage; Bishop chi = S_L; the skeleton's strain eps from the liquid's
  // mass, (n0 - eps) S_L(p) rho_L(p) = n0 S_max rho_L0; the load q = E_oed eps + S_L(p) p):
  //   rigid air:  S_L = 0.8, eps = 2.27e-6:   p = 12,472 Pa = 1.247 q (q / S_max, less the
  //               water's compression): above the load, as if the pores pushed harder than
  //               the load presses;
  //   Boyle air:  S_L(p) = 1 - 0.2 p_a / (p_a + p), eps = 9.24e-4: p = 947.1 Pa = 0.095 q
  //               (the skeleton takes the rest).
  int lower = 0;
  const Real rigid = undrainedPressureOfOccludedAir(0.0, lower);
  EXPECT_EQ(lower, 20);
  EXPECT_NEAR(rigid, 12471.7, 0.005 * 12471.7);
  const Real boyle = undrainedPressureOfOccludedAir(101325.0, lower);
  EXPECT_NEAR(boyle, 947.07, 0.005 * 947.07);
  std::printf(
      "[ occluded air ] mean p_L of the lower half: rigid %.1f Pa (hand 12471.7), Boyle "
      "%.2f Pa (hand 947.07)\n",
      rigid, boyle);
}

TEST(Consolidation, HeldLiquidPressureGivesTheDrainedResponse) {
  // `Liquid Pressure: held` (the hand-over after implicit seepage): Terzaghi's column, the
  // same 10 kPa on top, but the liquid moves with the solid and p_L stays 0, so the skeleton
  // takes the whole load at once: sigma'_yy = -q everywhere and the top settles by
  // q H / E_oed = 1e4 * 1 / 1e7 = 1 mm (nu = 0). The liquid mass follows the pore volume,
  // M_L = n rho_L V, and no point gets a relative velocity. (Free, the base would carry
  // p0 = 8333 Pa at first: TerzaghiColumnUnderTopLoad.)
  test::Column column(10, 0.1, 1.0, consolidationClay());
  auto boundaries = test::columnBoundaries();
  boundaries.push_back(test::traction("load", "top", 0.0, -1e4));
  ExplicitTwoPhaseSolver solver(column.mesh, column.points, column.materials);
  StageSpec stage =
      makeStage("drained", SolverKind::QuasiStatic, 0.0, 0.7, boundaries, {CriterionKind::CflDry});
  stage.hold_liquid_pressure = true;
  solver.beginStage(stage);
  runUntil(solver, 1.0);  // damped waves settle in about 0.6 s
  const auto pressure = hostCopy(column.points.pressure_liquid);
  const auto stress = hostCopy(column.points.stress_effective);
  const auto mass = hostCopy(column.points.mass_liquid);
  const auto porosity = hostCopy(column.points.porosity);
  const auto density = hostCopy(column.points.density_liquid);
  const auto volume = hostCopy(column.points.volume);
  const auto u = hostCopy(column.points.displacement);
  const auto y0 = hostCopy(column.points.initial_position);
  const auto vs = hostCopy(column.points.velocity_solid);
  const auto vl = hostCopy(column.points.velocity_liquid);
  Real top_settlement = 0;
  for (int p = 0; p < column.points.count; ++p) {
    EXPECT_EQ(pressure(p), 0.0);
    EXPECT_NEAR(stress(p, YY), -1e4, 2e-3 * 1e4);
    EXPECT_NEAR(mass(p), porosity(p) * density(p) * volume(p), 1e-12 * mass(p));
    for (int d = 0; d < kDim; ++d) EXPECT_EQ(vl(p, d), vs(p, d));
    // u_y(y) = -q (y / E_oed): the compression of the column below the point.
    EXPECT_NEAR(u(p, 1), -1e4 * y0(p, 1) / 1e7, 2e-3 * 1e-3);
    top_settlement = std::min(top_settlement, u(p, 1));
  }
  std::printf("[ held ] top points settled %.6e m (drained hand value 1e-3 m at y = 1)\n",
              -top_settlement);
}

TEST(Consolidation, HeldLiquidPressureMovesTheLiquidWithTheSolidUnderEveryTransfer) {
  // The held column of HeldLiquidPressureGivesTheDrainedResponse under APIC and TPIC, whose
  // points take v_L from the grid: the grid's liquid velocity is the solid's (moveLiquidWith-
  // Solid), so every point's liquid velocity is its solid velocity, to the bit, all the way
  // (the fixed base keeps a mapped v_L that it takes v_S from otherwise). Without it the
  // liquid's kinetic energy grows from the base while the solid comes to rest.
  for (const TransferScheme scheme : {TransferScheme::Apic, TransferScheme::Tpic}) {
    SCOPED_TRACE(scheme == TransferScheme::Apic ? "APIC" : "TPIC");
    test::Column column(10, 0.1, 1.0, consolidationClay());
    auto boundaries = test::columnBoundaries();
    boundaries.push_back(test::traction("load", "top", 0.0, -1e4));
    ExplicitTwoPhaseSolver solver(column.mesh, column.points, column.materials);
    StageSpec stage = makeStage("drained", SolverKind::QuasiStatic, 9.81, 0.7, boundaries,
                                {CriterionKind::CflDry});
    stage.hold_liquid_pressure = true;
    stage.transfer = scheme;
    solver.beginStage(stage);
    Real largest_solid_speed = 0;
    for (int k = 0; k < 400; ++k) {
      solver.step(solver.chooseTimeStep().time_step);
      const auto vs = hostCopy(column.points.velocity_solid);
      const auto vl = hostCopy(column.points.velocity_liquid);
      for (int p = 0; p < column.points.count; ++p)
        for (int d = 0; d < kDim; ++d) {
          ASSERT_EQ(vl(p, d), vs(p, d)) << "step " << k << ", point " << p;
          largest_solid_speed = std::max(largest_solid_speed, std::abs(vs(p, d)));
        }
    }
    EXPECT_GT(largest_solid_speed, 0.0);  // the column did move
  }
}

TEST(Consolidation, HeldLiquidPressureKeepsTheRetentionCurvesValuesAtItsPressure) {
  // A held stage renews S_L and k from the held p_L once, after its first step, and then
  // skips the curves (their values could not change). An unsaturated column on van Genuchten
  // and Mualem (lambda 0.75: the library's pow), suction 0-10 kPa growing upwards, whose
  // stored S_L and k are stale when the stage begins (0.3 and 1e-9 m/s everywhere): after
  // the first step and after 200 damped steps under gravity, every point holds exactly (to
  // the bit) the curves' values at its p_L, and p_L is the one it started with.
  MaterialSpec silt =
      test::withVanGenuchten(test::elasticMaterial("silt", PhaseModel::Unsaturated, 1e7, 0.3, 0.4),
                             19000, 0.75, 0.16, 0.8);
  silt.conductivity.model = ConductivityModel::Mualem;
  silt.conductivity.mualem_lambda = 0.75;
  silt.conductivity.saturated_conductivity = 5.3e-6;
  test::Column column(10, 0.1, 1.0, silt);
  ExplicitTwoPhaseSolver solver(column.mesh, column.points, column.materials);
  StageSpec stage = makeStage("drained", SolverKind::QuasiStatic, 9.81, 0.7,
                              test::columnBoundaries(), {CriterionKind::CflDry});
  stage.hold_liquid_pressure = true;
  solver.beginStage(stage);
  const auto y0 = hostCopy(column.points.initial_position);
  auto pressure = hostCopy(column.points.pressure_liquid);
  auto saturation = hostCopy(column.points.saturation);
  auto conductivity = hostCopy(column.points.conductivity);
  for (int p = 0; p < column.points.count; ++p) {
    pressure(p) = -1e4 * y0(p, 1);
    saturation(p) = 0.3;
    conductivity(p) = 1e-9;
  }
  Kokkos::deep_copy(column.points.pressure_liquid, pressure);
  Kokkos::deep_copy(column.points.saturation, saturation);
  Kokkos::deep_copy(column.points.conductivity, conductivity);
  const PointMaterial material = MaterialTable(column.materials).host(0);
  const auto expectCurvesAtHeldPressure = [&](const char* when) {
    const auto y = hostCopy(column.points.initial_position);
    const auto p_l = hostCopy(column.points.pressure_liquid);
    const auto s_l = hostCopy(column.points.saturation);
    const auto k = hostCopy(column.points.conductivity);
    for (int p = 0; p < column.points.count; ++p) {
      EXPECT_EQ(p_l(p), -1e4 * y(p, 1)) << when << ", point " << p;
      const LiquidState state = saturationAndConductivity(material, p_l(p));
      EXPECT_EQ(s_l(p), state.saturation) << when << ", point " << p;
      EXPECT_EQ(k(p), state.conductivity) << when << ", point " << p;
    }
  };
  solver.step(solver.chooseTimeStep().time_step);
  expectCurvesAtHeldPressure("after the first step");
  for (int k = 0; k < 200; ++k) solver.step(solver.chooseTimeStep().time_step);
  expectCurvesAtHeldPressure("after 201 steps");
}

TEST(Consolidation, DeformingClosedColumnKeepsItsLiquidMassToQuadrature) {
  // Saturated column under gravity, every side impermeable (the top too): no liquid can
  // leave. The undrained response puts p_L above hydrostatic (B rho_sat > rho_L), so liquid
  // flows up inside the column while the skeleton settles. The point masses change only by
  // the relative flux between points; its divergence is integrated by the points, which is
  // exact at the seeded (symmetric) positions but not once the settling has moved them, so
  // the total is kept to that quadrature error (~1e-7 relative here), not to round-off.
  test::Column column(10, 0.1, 1.0, consolidationClay());
  auto boundaries = test::columnBoundaries();
  boundaries.push_back(test::impermeable("top seal", "top"));
  ExplicitTwoPhaseSolver solver(column.mesh, column.points, column.materials);
  solver.beginStage(makeStage("gravity", SolverKind::QuasiStatic, 9.81, 0.1, boundaries));
  const auto m0 = hostCopy(column.points.mass_liquid);
  Real initial = 0;
  for (int p = 0; p < column.points.count; ++p) initial += m0(p);
  // Hand value: n rho_L V over 1 m x 0.1 m = 0.4 * 1000 * 0.1 = 40 kg/m.
  EXPECT_NEAR(initial, 40.0, 1e-12);
  Real worst = 0;
  runUntil(solver, 0.2,
           [&] { worst = std::max(worst, std::fabs(solver.diagnostics().liquid_mass - initial)); });
  EXPECT_LT(worst, 1e-6 * initial);
  std::printf("[ closed column ] largest liquid mass change %.3g kg/m (relative %.3g)\n", worst,
              worst / initial);
}

TEST(Consolidation, FixedSkeletonDrainsMonotonically) {
  // Fixed skeleton (seepage only), uniform p_L = 10 kPa, drained top, impermeable base and
  // sides, no gravity; 5 elements of 0.2 m. Only the liquid moves, and the pressure must fall
  // everywhere, never rise, towards 0. Storage is n / K_L alone, so Terzaghi's solution
  // holds with c_v = k K_L / (n gamma_w) = 2.5e-4 * 2e7 / (0.4 * 9810) = 1.27421 m^2/s.
  // Monotone decay needs the drag to dominate the liquid's inertia at the grid scale: the
  // drag rate n g / k = 15696 1/s is 10 x the fastest liquid wave frequency 2 sqrt(K_L /
  // rho_L) / h = 1414 1/s. (With less drag the liquid's inertia makes the decay ring, as the
  // liquid momentum equation 4.36 says it should.)
  MaterialSpec clay =
      test::elasticMaterial("clay", PhaseModel::Saturated, 1e7, 0.0, 0.4, 2.5e-4, 2e7);
  clay.initial.liquid_pressure = 1e4;
  test::Column column(5, 0.2, 1.0, clay);
  ExplicitTwoPhaseSolver solver(column.mesh, column.points, column.materials);
  solver.beginStage(makeStage("drain", SolverKind::FixedSkeleton, 0.0, 0.0,
                              test::columnBoundaries(),
                              {CriterionKind::UnsaturatedLiquid, CriterionKind::Consolidation}));
  const Real cv = 2.5e-4 * 2e7 / (0.4 * 9810);
  const auto x0 = hostCopy(column.points.position);
  // The mean pressure (the stored liquid) must fall at every step. Single points may rise
  // by a hair while the sudden drop at the top spreads (the explicit remap carries it one
  // element per step, faster than the physical liquid wave): bounded by 1e-3 p_i.
  auto previous = hostCopy(column.points.pressure_liquid);
  auto mean = [&](const auto& pressure) {
    Real sum = 0;
    for (int p = 0; p < column.points.count; ++p) sum += pressure(p);
    return sum / column.points.count;
  };
  int mean_rises = 0;
  Real largest_rise = 0;
  runUntil(solver, 0.5 / cv, [&] {
    const auto now = hostCopy(column.points.pressure_liquid);
    if (mean(now) > mean(previous)) ++mean_rises;
    for (int p = 0; p < column.points.count; ++p)
      largest_rise = std::max(largest_rise, now(p) - previous(p));
    previous = now;
  });
  EXPECT_EQ(mean_rises, 0);
  EXPECT_LT(largest_rise, 1e-3 * 1e4);
  const auto pressure = hostCopy(column.points.pressure_liquid);
  const auto x = hostCopy(column.points.position);
  const auto stress = hostCopy(column.points.stress_effective);
  Real worst = 0;
  for (int p = 0; p < column.points.count; ++p) {
    worst = std::max(worst, std::fabs(pressure(p) - terzaghi(1e4, 1.0 - x0(p, 1), 1.0, 0.5)));
    EXPECT_EQ(x(p, 1), x0(p, 1));  // the skeleton did not move
    EXPECT_EQ(stress(p, YY), 0.0);
  }
  EXPECT_LT(worst, 0.04 * 1e4);
  std::printf("[ fixed skeleton ] T = 0.5 after %ld steps: largest |p - p_exact| = %.3g p_i\n",
              solver.diagnostics().step, worst / 1e4);
}

TEST(Consolidation, FixedSkeletonClosedColumnKeepsLiquidMassToRoundOff) {
  // Closed column, fixed skeleton, gravity switched on from p_L = 0: the liquid settles into
  // a hydrostatic state by flowing down. Nothing leaves, the points do not move, so the sum
  // of the point flux divergences is exactly the (zero) boundary flux: the liquid mass is
  // kept to round-off. Initial: n rho_L V = 0.4 * 1000 * 0.1 * 1.0 = 40 kg/m.
  test::Column column(10, 0.1, 1.0, consolidationClay());
  auto boundaries = test::columnBoundaries();
  boundaries.push_back(test::impermeable("top seal", "top"));
  ExplicitTwoPhaseSolver solver(column.mesh, column.points, column.materials);
  solver.beginStage(makeStage("settle", SolverKind::FixedSkeleton, 9.81, 0.0, boundaries,
                              {CriterionKind::UnsaturatedLiquid, CriterionKind::Consolidation}));
  Real worst = 0;
  runUntil(solver, 0.05,
           [&] { worst = std::max(worst, std::fabs(solver.diagnostics().liquid_mass - 40.0)); });
  EXPECT_LT(worst, 1e-12 * 40.0);
  // And it did flow: the base pressure rose from 0 (towards rho_L g H = 9810 Pa).
  const auto pressure = hostCopy(column.points.pressure_liquid);
  EXPECT_GT(pressure(0), 1000.0);
}

TEST(Consolidation, DryMaterialCarriesNoLiquid) {
  // A dry layer (upper 5 elements) on a saturated one, under gravity. Dry points never get
  // liquid: pressure, liquid mass and liquid velocity stay zero, and the nodes touched only
  // by dry points have no liquid mass. The top of the saturated layer meets no liquid
  // equation above it, so it is a free-draining surface (p_L = 0, the natural condition):
  // the layer's excess pressure from the dry fill's weight drains there and the liquid that
  // leaves is gone (declare the fill unsaturated to keep it). Initial liquid mass
  // n rho_L V = 0.4 * 1000 * 0.05 = 20 kg/m.
  test::Column column(10, 0.1, 1.0, consolidationClay());
  column.materials.push_back(test::elasticMaterial("fill", PhaseModel::Dry, 1e7, 0.0, 0.4));
  auto material = hostCopy(column.points.material);
  const auto y = hostCopy(column.points.position);
  for (int p = 0; p < column.points.count; ++p) material(p) = y(p, 1) > 0.5 ? 1 : 0;
  Kokkos::deep_copy(column.points.material, material);
  initialisePointState(column.materials, column.points);
  ExplicitTwoPhaseSolver solver(column.mesh, column.points, column.materials);
  solver.beginStage(
      makeStage("gravity", SolverKind::QuasiStatic, 9.81, 0.1, test::columnBoundaries()));
  runUntil(solver, 0.05);
  const auto pressure = hostCopy(column.points.pressure_liquid);
  const auto mass = hostCopy(column.points.mass_liquid);
  const auto vl = hostCopy(column.points.velocity_liquid);
  for (int p = 0; p < column.points.count; ++p) {
    if (material(p) != 1) continue;
    EXPECT_EQ(pressure(p), 0.0);
    EXPECT_EQ(mass(p), 0.0);
    EXPECT_EQ(vl(p, 1), 0.0);
  }
  EXPECT_GT(solver.diagnostics().liquid_mass, 19.9);
  EXPECT_LT(solver.diagnostics().liquid_mass, 20.0);
  // Nodes 14..21 (rows y >= 0.7) see only dry points.
  const auto liquid_i = hostCopy(solver.grid().mass_liquid_intrinsic_i);
  for (int i = 14; i < column.mesh.numNodes(); ++i) EXPECT_EQ(liquid_i(i), 0.0) << "node " << i;
  // Row y = 0.5 (nodes 10, 11) is shared: it has liquid from the saturated points below.
  EXPECT_GT(liquid_i(10), 0.0);
}

TEST(Consolidation, PrescribedPressureOnTopSubmergesTheColumn) {
  // p^ = 10 kPa of water on the top (LiquidPressureBoundary: -p^ n on liquid AND mixture),
  // no gravity, impermeable base and sides, k = 1e-2 m/s. The water load first compresses
  // the column undrained (p_L = B p^ = 8333 Pa, sigma'_yy = -1667 Pa), then water flows in
  // through the top until p_L = p^ everywhere and the skeleton is unloaded again
  // (total stress -p^ = sigma' - p_L  ->  sigma' = 0). c_v = k / (gamma_w (m_v + n/K_L)) =
  // 1e-2 / (9810 * 1.2e-7) = 8.49 m^2/s: T = 2 at t = 0.24 s.
  MaterialSpec sand =
      test::elasticMaterial("sand", PhaseModel::Saturated, 1e7, 0.0, 0.4, 1e-2, 2e7);
  test::Column column(5, 0.2, 1.0, sand);
  auto boundaries = test::columnBoundaries();
  boundaries.push_back(test::liquidPressure("water", "top", 1e4));
  ExplicitTwoPhaseSolver solver(column.mesh, column.points, column.materials);
  solver.beginStage(makeStage("flood", SolverKind::QuasiStatic, 0.0, 0.5, boundaries));
  runUntil(solver, 0.24);
  const auto pressure = hostCopy(column.points.pressure_liquid);
  const auto stress = hostCopy(column.points.stress_effective);
  for (int p = 0; p < column.points.count; ++p) {
    EXPECT_NEAR(pressure(p), 1e4, 0.02 * 1e4);
    EXPECT_NEAR(stress(p, YY), 0.0, 0.02 * 1e4);
  }
  // Water came in through the top: with the skeleton back at its volume, the stored liquid
  // is denser by rho_L0 p / K_L = 0.5 kg/m^3 over the pore volume n V = 0.4 * 0.2 m^2/m:
  // +0.04 kg/m on the initial 0.4 * 1000 * 0.2 = 80 kg/m (within the 2 % of p above).
  EXPECT_NEAR(solver.diagnostics().liquid_mass - 80.0, 0.04, 0.1 * 0.04);
}

}  // namespace
}  // namespace argine
